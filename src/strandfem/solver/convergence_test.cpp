#include "strandfem/solver/convergence_test.hpp"

#include <algorithm>
#include <cmath>

namespace strandfem {
namespace {
constexpr double kPredictorAcceptance = 1e-3;  // of the tolerance, for a predictor taken without correction
constexpr int kForceOnlyAfter = 4;             // corrections before the force test alone may accept
constexpr double kForceOnlyMargin = 0.1;       // of the tolerance, for such an acceptance
}  // namespace

ConvergenceTest::ConvergenceTest(const SolverOptions& options, double length_scale, double force_floor, double roundoff_force)
    : force_tolerance_(options.force_tolerance),
      moment_tolerance_(options.moment_tolerance),
      load_tolerance_(options.load_tolerance),
      displacement_tolerance_(options.displacement_tolerance),
      length_scale_(length_scale),
      force_floor_(force_floor),
      roundoff_force_(roundoff_force) {}

void ConvergenceTest::accept(const LoadReference& converged) {
  step_reference_.force = std::max(step_reference_.force, converged.force);
  step_reference_.moment = std::max(step_reference_.moment, converged.moment);
}

namespace {
// Squared norms over the nodes that are not tied: residual forces and moments at free DOFs, and the loads (applied
// at free DOFs, reactions at constrained ones); rhs, if given, becomes minus the residual.
struct SquaredNorms {
  double free_force = 0, free_moment = 0, load_force = 0, load_moment = 0;
};
SquaredNorms squared_norms(const DofMap& dofs, const std::vector<double>& internal, const std::vector<double>& external,
                           std::vector<double>* rhs) {
  SquaredNorms n;
  for (std::size_t node = 0; node < dofs.equation.size(); ++node) {
    if (dofs.tie_of[node] >= 0) continue;
    for (int c = 0; c < 6; ++c) {
      const int eq = dofs.equation[node][c];
      const double f_int = internal[6 * node + c], f_ext = external[6 * node + c];
      const double load = eq >= 0 ? f_ext : f_int;
      (c < 3 ? n.load_force : n.load_moment) += load * load;
      if (eq < 0) continue;
      const double residual = f_int - f_ext;
      if (rhs) (*rhs)[eq] = -residual;
      (c < 3 ? n.free_force : n.free_moment) += residual * residual;
    }
  }
  return n;
}
}  // namespace

LoadReference ConvergenceTest::load_norms(const DofMap& dofs, const std::vector<double>& internal,
                                          const std::vector<double>& external) const {
  const SquaredNorms n = squared_norms(dofs, internal, external, nullptr);
  return {std::sqrt(n.load_force), std::sqrt(n.load_moment)};
}

ResidualCheck ConvergenceTest::measure(const DofMap& dofs, const std::vector<double>& internal,
                                       const std::vector<double>& external, std::vector<double>& rhs) const {
  const SquaredNorms n = squared_norms(dofs, internal, external, &rhs);
  ResidualCheck r;
  r.state = {std::sqrt(n.load_force), std::sqrt(n.load_moment)};
  // Each reference borrows from the other through the mean element length, so that a case loaded only by moments
  // (or only by forces) still has a meaningful scale for both residuals.
  const double force_norm = std::max(r.state.force, step_reference_.force);
  const double moment_norm = std::max(r.state.moment, step_reference_.moment);
  const double force_ref = std::max({force_norm, moment_norm / length_scale_, force_floor_});
  const double moment_ref = std::max(moment_norm, force_ref * length_scale_);
  const double force_residual = std::sqrt(n.free_force), moment_residual = std::sqrt(n.free_moment);
  r.relative = std::max(force_residual / force_ref, moment_residual / moment_ref);
  const double roundoff_moment = roundoff_force_ * length_scale_;
  for (const AppliedLoad& load : loads_) {
    const double allowance = std::max(load_tolerance_ * load.largest, load.moment ? roundoff_moment : roundoff_force_);
    r.worst_load = std::max(r.worst_load, std::abs(rhs[load.equation]) / allowance);
  }
  const bool loads_met = r.worst_load <= 1.0;
  r.forces_ok = loads_met && force_residual <= force_tolerance_ * force_ref && moment_residual <= moment_tolerance_ * moment_ref;
  r.within_roundoff = force_residual <= force_tolerance_ * std::max(force_ref, roundoff_force_) &&
                      moment_residual <= moment_tolerance_ * std::max(moment_ref, roundoff_moment);
  return r;
}

Convergence ConvergenceTest::decide(const ResidualCheck& check, const IterateProgress& progress) const {
  const double tolerance = std::min(force_tolerance_, moment_tolerance_);
  const bool displacement_ok =
      !progress.predictor
          ? progress.correction2 <= displacement_tolerance_ * displacement_tolerance_ * progress.increment_motion2
          : check.relative <= kPredictorAcceptance * tolerance;
  const double margin = kForceOnlyMargin * tolerance;
  const bool force_margin = progress.corrections >= kForceOnlyAfter && check.relative <= margin &&
                            std::abs(check.state.force - progress.previous_load_norm) <=
                                margin * std::max(check.state.force, step_reference_.force);
  Convergence c;
  c.converged = check.forces_ok && (displacement_ok || force_margin);
  c.force_only = c.converged && !displacement_ok;
  return c;
}

}  // namespace strandfem
