// Beam cross-section response: stress resultants and their tangent from generalized strains.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "strandfem/core/types.hpp"

namespace strandfem {

// Generalized strains in the section frame (axis 1 = beam axis): [Gamma1 (axial), Gamma2, Gamma3 (shear),
// K1 (twist), K2, K3 (bending)], measured from the stress-free reference configuration.
// Resultants conjugate to them: [N, Q2, Q3, T, M2, M3] in N and N*mm.
struct SectionResponse {
  Vec6 resultants = Vec6::Zero();
  Mat6 tangent = Mat6::Zero();
};

// History variables of one section point (plastic strains, back stresses...). Empty for elastic sections.
// Owned by the element's integration point; committed only when an increment converges.
using SectionHistory = std::vector<double>;

// Elastic properties of a homogeneous isotropic material.
struct ElasticMaterial {
  double youngs_modulus = 0;  // MPa
  double poisson_ratio = 0;
  double density = 0;         // t/mm^3 (1 t/mm^3 = 1e12 kg/m^3), used only for mass per length
  std::string name;           // the case file's material key (friction is given per material pair)
  double shear_modulus() const { return youngs_modulus / (2.0 * (1.0 + poisson_ratio)); }
};

// Geometric properties of a cross-section.
struct SectionGeometry {
  double area = 0;              // mm^2
  double inertia_2 = 0;         // mm^4, about local axis 2
  double inertia_3 = 0;         // mm^4, about local axis 3
  double torsion_constant = 0;  // mm^4
  double shear_factor = 0;      // shear area / area
  double contact_radius = 0;    // mm, radius used by contact (0 for non-circular sections)

  static SectionGeometry circle(double diameter, double poisson_ratio);
};

// A section model. Implementations must be thread-safe for concurrent evaluate() calls.
class Section {
 public:
  virtual ~Section() = default;
  // Resultants and tangent for the given strains; reads the committed history, writes the trial one.
  virtual SectionResponse evaluate(const Vec6& strain, const SectionHistory& committed,
                                   SectionHistory& trial) const = 0;
  virtual SectionHistory initial_history() const { return {}; }
  virtual const SectionGeometry& geometry() const = 0;
  virtual const ElasticMaterial& material() const = 0;
  // Elastic stiffness diagonal [EA, kGA, kGA, GJ, EI2, EI3].
  virtual Vec6 elastic_stiffness() const = 0;
};

// Linear elastic section: resultants = diag(EA, kGA2, kGA3, GJ, EI2, EI3) * strain.
class ElasticSection final : public Section {
 public:
  ElasticSection(const SectionGeometry& geometry, const ElasticMaterial& material);
  SectionResponse evaluate(const Vec6& strain, const SectionHistory& committed,
                           SectionHistory& trial) const override;
  const SectionGeometry& geometry() const override { return geometry_; }
  const ElasticMaterial& material() const override { return material_; }
  Vec6 elastic_stiffness() const override { return stiffness_; }

 private:
  SectionGeometry geometry_;
  ElasticMaterial material_;
  Vec6 stiffness_;
};

}  // namespace strandfem
