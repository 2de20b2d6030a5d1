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
  Vec3 material_stress = Vec3::Zero();  // the law's own stress (true stress under StressMeasure::true_stress)
};

// Von Mises stress of the fibre stress state: sqrt(sigma^2 + 3 tau12^2 + 3 tau13^2).
double von_mises(const Vec3& stress);

// Radial return (closest point in the energy norm) from the committed state; `trial` receives the updated
// plastic state. Yield function f = sqrt(eta^T P eta) - sigma_y, eta = stress - back stress, P = diag(1, 3, 3);
// associative flow, Prager's hardening scaled so that uniaxially alpha = H eps_p (H: plastic modulus).
FibreResponse j2_fibre_return(const Vec3& strain, const Material& material, const FibrePlasticState& committed,
                              FibrePlasticState& trial);

// The fibre's response to the beam's fibre strains [eps, gamma12, gamma13], in the stress the section
// integrates over the reference area (work conjugate to eps). Engineering measure: j2_fibre_return as is.
// True-stress measure: the J2 law acts on the logarithmic axial strain ln(1 + eps) and returns Kirchhoff
// stress tau (true stress to within the elastic volume change, since plastic flow is isochoric); the section
// gets tau / (1 + eps), i.e. true stress times the current area of an incompressible fibre. Shear strains
// stay small and enter unchanged. Elastic wires (no plasticity) are unaffected.
FibreResponse fibre_response(const Vec3& strain, const Material& material, const FibrePlasticState& committed,
                             FibrePlasticState& trial);

}  // namespace strandfem
