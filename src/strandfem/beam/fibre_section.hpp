// Circular wire section integrated over fibres, each with J2 plasticity and kinematic hardening.
#pragma once
#include <vector>

#include "strandfem/beam/fibre_quadrature.hpp"
#include "strandfem/beam/j2_beam_plasticity.hpp"
#include "strandfem/beam/section.hpp"

namespace strandfem {

// Elastoplastic circular section: resultants and consistent tangent integrated over disc_fibres(); the
// plastic state of every fibre is the section point's history (7 numbers per fibre).
class FibreSection final : public Section {
 public:
  // The material must carry plasticity; the geometry must be a circle (contact_radius > 0).
  FibreSection(const SectionGeometry& geometry, const Material& material);
  SectionResponse evaluate(const Vec6& strain, const SectionHistory& committed, SectionHistory& trial) const override;
  SectionHistory initial_history() const override;
  SectionPointSummary summary(const Vec6& strain, const SectionHistory& history) const override;
  const SectionGeometry& geometry() const override { return geometry_; }
  const Material& material() const override { return material_; }
  Vec6 elastic_stiffness() const override { return stiffness_; }
  const std::vector<Fibre>& fibres() const { return fibres_; }

 private:
  SectionGeometry geometry_;
  Material material_;
  Vec6 stiffness_;
  std::vector<Fibre> fibres_;
  std::vector<Eigen::Matrix<double, 3, 6>> operators_;  // fibre_strain_operator of each fibre
};

}  // namespace strandfem
