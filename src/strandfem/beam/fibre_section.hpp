// Circular wire section integrated over fibres, each with J2 plasticity and kinematic hardening.
#pragma once
#include <vector>

#include "strandfem/beam/j2_beam_plasticity.hpp"
#include "strandfem/beam/section.hpp"

namespace strandfem {

// One section point of the fibre quadrature: position (y, z) in the section axes 2 and 3, and its area.
struct Fibre {
  double y = 0, z = 0, area = 0;
};

// Polar quadrature of a disc: Gauss-Legendre rings (exact for the area, inertia and polar moment) times
// equally spaced sectors. 4 x 24 fibres put the fully plastic moment sum |z| A sigma_y within 0.6 % of
// 4/3 sigma_y r^3 whatever the bending direction.
std::vector<Fibre> disc_fibres(double radius, int rings = 4, int sectors = 24);

// Fibre strains from section strains [Gamma1, Gamma2, Gamma3, K1, K2, K3]:
//   eps = Gamma1 + K2 z - K3 y,  gamma12 = sqrt(k) Gamma2 - K1 z,  gamma13 = sqrt(k) Gamma3 + K1 y,
// with k the shear factor (so that an elastic section gives k G A, G J, E I exactly).
Eigen::Matrix<double, 3, 6> fibre_strain_operator(const Fibre& fibre, double shear_factor);

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
