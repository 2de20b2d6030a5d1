// Wire material: isotropic elasticity, optionally bilinear kinematic hardening plasticity (paper Tables 1, 3).
#pragma once
#include <optional>
#include <string>

namespace strandfem {

// Which stress the law's (sigma_y, Et) describe; see fibre_response() for how each enters the section.
enum class StressMeasure {
  true_stress,  // true (Kirchhoff) stress against logarithmic axial strain, as large-strain FE codes take it
  engineering,  // force over the initial area against engineering axial strain
};

// Bilinear kinematic hardening: elastic up to the yield stress, then the tangent modulus Et in uniaxial
// tension; the elastic range keeps its width 2 sigma_y and moves with the back stress (Bauschinger effect).
struct BilinearHardening {
  double yield_stress = 0;     // MPa
  double tangent_modulus = 0;  // MPa, 0 <= Et < E
  StressMeasure stress_measure = StressMeasure::true_stress;
  // Plastic (kinematic) modulus H = E Et / (E - Et): the uniaxial back stress is H times the plastic strain.
  double plastic_modulus(double youngs_modulus) const {
    return youngs_modulus * tangent_modulus / (youngs_modulus - tangent_modulus);
  }
};

struct Material {
  double youngs_modulus = 0;  // MPa
  double poisson_ratio = 0;
  double density = 0;         // t/mm^3 (1 t/mm^3 = 1e12 kg/m^3), used only for mass per length
  std::string name;           // the case file's material key (friction is given per material pair)
  std::optional<BilinearHardening> plasticity;  // none: linear elastic
  double shear_modulus() const { return youngs_modulus / (2.0 * (1.0 + poisson_ratio)); }
};

}  // namespace strandfem
