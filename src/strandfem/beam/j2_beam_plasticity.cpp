#include "strandfem/beam/j2_beam_plasticity.hpp"

#include <cmath>
#include <limits>

namespace strandfem {
namespace {
constexpr int kMaxReturnIterations = 60;
constexpr double kYieldTolerance = 1e-12;  // relative to the yield stress
const Vec3 kMisesWeights(1.0, 3.0, 3.0);   // P: sigma_eq^2 = eta^T P eta

// The response at a non-physical Newton iterate (wild first corrections reach shear strains of 2): NaN, so
// that the residual turns non-finite and the Newton loop rejects the iterate and cuts back. Throwing instead
// would end the run from inside the threaded assembly.
FibreResponse rejected_iterate() {
  FibreResponse r;
  r.stress = r.material_stress = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  r.tangent = Mat3::Constant(std::numeric_limits<double>::quiet_NaN());
  return r;
}
}  // namespace

double von_mises(const Vec3& stress) { return std::sqrt(stress.cwiseProduct(stress).dot(kMisesWeights)); }

FibreResponse j2_fibre_return(const Vec3& strain, const Material& material, const FibrePlasticState& committed,
                              FibrePlasticState& trial) {
  const double E = material.youngs_modulus, G = material.shear_modulus();
  const Vec3 elastic(E, G, G);
  FibreResponse r;
  trial = committed;
  r.stress = elastic.cwiseProduct(strain - committed.plastic_strain);
  r.tangent = elastic.asDiagonal();
  if (!material.plasticity) return r;
  const double yield = material.plasticity->yield_stress;
  const double H = material.plasticity->plastic_modulus(E);
  const Vec3 relative_trial = r.stress - committed.back_stress;  // eta_trial
  if (von_mises(relative_trial) <= yield * (1.0 + kYieldTolerance)) return r;

  // eta = A eta_trial with A_i = 1 / (1 + t d_i), d = C P + H; t = Delta lambda / sigma_y solves
  // g(t) = sum P_i eta_trial_i^2 A_i^2 - sigma_y^2 = 0. g is convex and decreasing, so Newton from t = 0
  // approaches the root from below without overshoot.
  const Vec3 d = elastic.cwiseProduct(kMisesWeights) + Vec3::Constant(H);
  const Vec3 weighted_trial2 = kMisesWeights.cwiseProduct(relative_trial.cwiseProduct(relative_trial));
  double t = 0;
  bool converged = false;
  for (int it = 0; it < kMaxReturnIterations; ++it) {
    const Vec3 a = (Vec3::Ones() + t * d).cwiseInverse();
    const double g = weighted_trial2.dot(a.cwiseProduct(a)) - yield * yield;
    if (std::abs(g) <= 2.0 * kYieldTolerance * yield * yield) {
      converged = true;
      break;
    }
    const double slope = -2.0 * weighted_trial2.dot(d.cwiseProduct(a.cwiseProduct(a.cwiseProduct(a))));
    t -= g / slope;
  }
  if (!converged) return rejected_iterate();  // trial stays the committed state
  const Vec3 a = (Vec3::Ones() + t * d).cwiseInverse();
  const Vec3 eta = a.cwiseProduct(relative_trial);
  trial.back_stress = committed.back_stress + t * H * eta;
  trial.plastic_strain = committed.plastic_strain + t * kMisesWeights.cwiseProduct(eta);
  trial.equivalent_plastic_strain = committed.equivalent_plastic_strain + t * yield;
  r.stress = (1.0 + t * H) * eta + committed.back_stress;
  r.yielding = true;
  // d sigma = (1 + t H) d eta + H eta dt, d eta = A C d eps - D A eta dt, dt from eta^T P d eta = 0.
  const Vec3 v = H * eta - (1.0 + t * H) * d.cwiseProduct(a.cwiseProduct(eta));
  const Vec3 w = elastic.cwiseProduct(a.cwiseProduct(kMisesWeights.cwiseProduct(eta)));
  const double s = eta.dot(kMisesWeights.cwiseProduct(d.cwiseProduct(a.cwiseProduct(eta))));
  r.tangent = ((1.0 + t * H) * a.cwiseProduct(elastic)).asDiagonal();
  r.tangent += v * w.transpose() / s;
  return r;
}

FibreResponse fibre_response(const Vec3& strain, const Material& material, const FibrePlasticState& committed,
                             FibrePlasticState& trial) {
  const bool logarithmic =
      material.plasticity && material.plasticity->stress_measure == StressMeasure::true_stress;
  if (!logarithmic) {
    FibreResponse r = j2_fibre_return(strain, material, committed, trial);
    r.material_stress = r.stress;
    return r;
  }
  const double stretch = 1.0 + strain[0];
  if (!(stretch > 0)) {
    trial = committed;  // a fibre squeezed to zero length has no logarithmic strain
    return rejected_iterate();
  }
  const Vec3 log_strain(std::log(stretch), strain[1], strain[2]);
  FibreResponse r = j2_fibre_return(log_strain, material, committed, trial);
  r.material_stress = r.stress;
  // s = S tau with S = diag(1/stretch, 1, 1) = d log_strain / d strain, so ds/deps = S D S + dS/deps tau.
  const Vec3 scale(1.0 / stretch, 1.0, 1.0);
  r.stress = scale.cwiseProduct(r.material_stress);
  r.tangent = scale.asDiagonal() * r.tangent * scale.asDiagonal();
  r.tangent(0, 0) -= r.material_stress[0] / (stretch * stretch);
  return r;
}

}  // namespace strandfem
