// Beam cross-section response: stress resultants and their tangent from generalized strains.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "strandfem/beam/fibre_quadrature.hpp"
#include "strandfem/beam/material.hpp"
#include "strandfem/core/types.hpp"

namespace strandfem {

// Generalized strains in the section frame (axis 1 = beam axis): [Gamma1 (axial), Gamma2, Gamma3 (shear),
// K1 (twist), K2, K3 (bending)], measured from the stress-free reference configuration.
// Resultants conjugate to them: [N, Q2, Q3, T, M2, M3] in N and N*mm.
struct SectionResponse {
  Vec6 resultants = Vec6::Zero();
  Mat6 tangent = Mat6::Zero();
};

// What a section point reports for output: von Mises stress (MPa) and equivalent plastic strain over its
// fibres, largest and mean (plastic strains are 0 for elastic sections).
struct SectionPointSummary {
  double max_von_mises = 0, mean_von_mises = 0;
  double max_plastic_strain = 0, mean_plastic_strain = 0;
};

// History variables of one section point (plastic strains, back stresses...). Empty for elastic sections.
// Owned by the element's integration point; committed only when an increment converges.
using SectionHistory = std::vector<double>;

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
  // Output values at the given strains and (converged) history.
  virtual SectionPointSummary summary(const Vec6& strain, const SectionHistory& history) const = 0;
  virtual const SectionGeometry& geometry() const = 0;
  virtual const Material& material() const = 0;
  // Elastic stiffness diagonal [EA, kGA, kGA, GJ, EI2, EI3].
  virtual Vec6 elastic_stiffness() const = 0;
};

// Linear elastic section: resultants = diag(EA, kGA2, kGA3, GJ, EI2, EI3) * strain.
class ElasticSection final : public Section {
 public:
  ElasticSection(const SectionGeometry& geometry, const Material& material);
  SectionResponse evaluate(const Vec6& strain, const SectionHistory& committed,
                           SectionHistory& trial) const override;
  // Von Mises stress sampled on the fibres of a disc of the section's area.
  SectionPointSummary summary(const Vec6& strain, const SectionHistory& history) const override;
  const SectionGeometry& geometry() const override { return geometry_; }
  const Material& material() const override { return material_; }
  Vec6 elastic_stiffness() const override { return stiffness_; }

 private:
  SectionGeometry geometry_;
  Material material_;
  Vec6 stiffness_;
  std::vector<Fibre> fibres_;  // where summary() samples the stresses: a disc of the section's area
};

// The section of a wire of this material: FibreSection when the material has plasticity (circular
// geometry required; throws std::invalid_argument otherwise), ElasticSection when not.
std::unique_ptr<Section> make_section(const SectionGeometry& geometry, const Material& material);

}  // namespace strandfem
