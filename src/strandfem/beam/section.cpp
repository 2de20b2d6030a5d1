#include "strandfem/beam/section.hpp"

#include <cmath>
#include <numbers>

namespace strandfem {

SectionGeometry SectionGeometry::circle(double diameter, double poisson_ratio) {
  const double r = 0.5 * diameter;
  SectionGeometry g;
  g.area = std::numbers::pi * r * r;
  g.inertia_2 = g.inertia_3 = std::numbers::pi * std::pow(r, 4) / 4.0;
  g.torsion_constant = 2.0 * g.inertia_2;
  // Cowper's shear coefficient of a solid circle.
  g.shear_factor = 6.0 * (1.0 + poisson_ratio) / (7.0 + 6.0 * poisson_ratio);
  g.contact_radius = r;
  return g;
}

ElasticSection::ElasticSection(const SectionGeometry& geometry, const ElasticMaterial& material)
    : geometry_(geometry), material_(material) {
  const double E = material.youngs_modulus, G = material.shear_modulus();
  stiffness_ << E * geometry.area, G * geometry.shear_factor * geometry.area,
      G * geometry.shear_factor * geometry.area, G * geometry.torsion_constant, E * geometry.inertia_2,
      E * geometry.inertia_3;
}

SectionResponse ElasticSection::evaluate(const Vec6& strain, const SectionHistory&, SectionHistory&) const {
  SectionResponse r;
  r.tangent = stiffness_.asDiagonal();
  r.resultants = stiffness_.cwiseProduct(strain);
  return r;
}

}  // namespace strandfem
