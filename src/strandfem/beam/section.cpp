#include "strandfem/beam/section.hpp"

#include "strandfem/beam/fibre_section.hpp"

#include <cmath>
#include <algorithm>
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

ElasticSection::ElasticSection(const SectionGeometry& geometry, const Material& material)
    : geometry_(geometry), material_(material) {
  const double E = material.youngs_modulus, G = material.shear_modulus();
  stiffness_ << E * geometry.area, G * geometry.shear_factor * geometry.area,
      G * geometry.shear_factor * geometry.area, G * geometry.torsion_constant, E * geometry.inertia_2,
      E * geometry.inertia_3;
  fibres_ = disc_fibres(geometry.contact_radius > 0 ? geometry.contact_radius : std::sqrt(geometry.area / std::numbers::pi));
}

SectionResponse ElasticSection::evaluate(const Vec6& strain, const SectionHistory&, SectionHistory&) const {
  SectionResponse r;
  r.tangent = stiffness_.asDiagonal();
  r.resultants = stiffness_.cwiseProduct(strain);
  return r;
}

SectionPointSummary ElasticSection::summary(const Vec6& strain, const SectionHistory&) const {
  const double E = material_.youngs_modulus, G = material_.shear_modulus();
  SectionPointSummary s;
  for (const Fibre& f : fibres_) {
    const Vec3 e = fibre_strain_operator(f, geometry_.shear_factor) * strain;
    const double stress = von_mises(Vec3(E * e[0], G * e[1], G * e[2]));
    s.max_von_mises = std::max(s.max_von_mises, stress);
    s.mean_von_mises += stress / fibres_.size();
  }
  return s;
}

std::unique_ptr<Section> make_section(const SectionGeometry& geometry, const Material& material) {
  if (material.plasticity) return std::make_unique<FibreSection>(geometry, material);
  return std::make_unique<ElasticSection>(geometry, material);
}

}  // namespace strandfem
