#include "strandfem/beam/fibre_section.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace strandfem {
namespace {

constexpr int kStateSize = 7;  // plastic strains (3), back stress (3), equivalent plastic strain

FibrePlasticState load_state(const SectionHistory& h, std::size_t fibre) {
  const double* v = h.data() + kStateSize * fibre;
  FibrePlasticState s;
  s.plastic_strain = Vec3(v[0], v[1], v[2]);
  s.back_stress = Vec3(v[3], v[4], v[5]);
  s.equivalent_plastic_strain = v[6];
  return s;
}

void store_state(const FibrePlasticState& s, SectionHistory& h, std::size_t fibre) {
  double* v = h.data() + kStateSize * fibre;
  for (int i = 0; i < 3; ++i) {
    v[i] = s.plastic_strain[i];
    v[3 + i] = s.back_stress[i];
  }
  v[6] = s.equivalent_plastic_strain;
}

}  // namespace

FibreSection::FibreSection(const SectionGeometry& geometry, const Material& material)
    : geometry_(geometry), material_(material) {
  if (!material.plasticity)
    throw std::invalid_argument("material '" + material.name + "': a fibre section needs plasticity");
  if (!(geometry.contact_radius > 0))
    throw std::invalid_argument("material '" + material.name + "': plastic wires need a circular section (diameter)");
  const BilinearHardening& law = *material.plasticity;
  if (!(law.yield_stress > 0))
    throw std::invalid_argument("materials." + material.name + ".plasticity.yield_stress must be > 0");
  if (!(law.tangent_modulus >= 0 && law.tangent_modulus < material.youngs_modulus))
    throw std::invalid_argument("materials." + material.name + ".plasticity.tangent_modulus must be in [0, E)");
  const double E = material.youngs_modulus, G = material.shear_modulus();
  stiffness_ << E * geometry.area, G * geometry.shear_factor * geometry.area, G * geometry.shear_factor * geometry.area,
      G * geometry.torsion_constant, E * geometry.inertia_2, E * geometry.inertia_3;
  fibres_ = disc_fibres(geometry.contact_radius);
  for (const Fibre& f : fibres_) operators_.push_back(fibre_strain_operator(f, geometry.shear_factor));
}

SectionHistory FibreSection::initial_history() const { return SectionHistory(kStateSize * fibres_.size(), 0.0); }

SectionResponse FibreSection::evaluate(const Vec6& strain, const SectionHistory& committed, SectionHistory& trial) const {
  SectionResponse r;
  trial.resize(committed.size());
  for (std::size_t i = 0; i < fibres_.size(); ++i) {
    const Eigen::Matrix<double, 3, 6>& B = operators_[i];
    FibrePlasticState next;
    const FibreResponse f = fibre_response(B * strain, material_, load_state(committed, i), next);
    store_state(next, trial, i);
    const double area = fibres_[i].area;
    r.resultants += area * B.transpose() * f.stress;
    r.tangent += area * B.transpose() * f.tangent * B;
  }
  return r;
}

SectionPointSummary FibreSection::summary(const Vec6& strain, const SectionHistory& history) const {
  SectionPointSummary s;
  for (std::size_t i = 0; i < fibres_.size(); ++i) {
    FibrePlasticState next;
    const FibrePlasticState state = load_state(history, i);
    // At a converged state the return from the converged history is the identity on the plastic state.
    const FibreResponse f = fibre_response(operators_[i] * strain, material_, state, next);
    const double stress = von_mises(f.material_stress), plastic = next.equivalent_plastic_strain;
    s.max_von_mises = std::max(s.max_von_mises, stress);
    s.max_plastic_strain = std::max(s.max_plastic_strain, plastic);
    s.mean_von_mises += stress / fibres_.size();
    s.mean_plastic_strain += plastic / fibres_.size();
  }
  return s;
}

}  // namespace strandfem
