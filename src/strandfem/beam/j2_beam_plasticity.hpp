// J2 plasticity with linear kinematic hardening in the stress state of a beam fibre (sigma, tau12, tau13).
#pragma once
#include "strandfem/beam/material.hpp"
#include "strandfem/core/types.hpp"

namespace strandfem {

// Strains and stresses of a fibre: [axial strain, engineering shear strains gamma12, gamma13] and
// [sigma, tau12, tau13]; the lateral stresses are zero (lateral strains are free), so the elastic law is
// diagonal: C = diag(E, G, G).
// Plastic state of one fibre: its plastic strains, back stress and equivalent plastic strain. The committed
// state is read, a trial state written; it survives load reversals (kinematic hardening).
struct FibrePlasticState {
  Vec3 plastic_strain = Vec3::Zero();  // [eps_p, gamma_p12, gamma_p13]
  Vec3 back_stress = Vec3::Zero();     // [alpha, alpha12, alpha13]
  double equivalent_plastic_strain = 0;
};

struct FibreResponse {
  Vec3 stress = Vec3::Zero();
  Mat3 tangent = Mat3::Zero();  // algorithmic (consistent) d stress / d strain
  bool yielding = false;
};

// Von Mises stress of the fibre stress state: sqrt(sigma^2 + 3 tau12^2 + 3 tau13^2).
double von_mises(const Vec3& stress);

// Radial return (closest point in the energy norm) from the committed state; `trial` receives the updated
// plastic state. Yield function f = sqrt(eta^T P eta) - sigma_y, eta = stress - back stress, P = diag(1, 3, 3);
// associative flow, Prager's hardening scaled so that uniaxially alpha = H eps_p (H: plastic modulus).
FibreResponse j2_fibre_return(const Vec3& strain, const Material& material, const FibrePlasticState& committed,
                              FibrePlasticState& trial);

}  // namespace strandfem
