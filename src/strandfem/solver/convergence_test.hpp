// Newton's force test of an increment: residuals against the step's loads, and each applied load met on its own.
#pragma once
#include <vector>

#include "strandfem/solver/model.hpp"

namespace strandfem {

// Norms of a state's applied loads and reactions: the scale its residual forces and moments are measured against.
struct LoadReference {
  double force = 0;   // N
  double moment = 0;  // N mm
};

// A load applied at a free DOF in the current increment, and the largest magnitude it takes in its step.
struct AppliedLoad {
  int equation = -1;
  double largest = 0;   // N, or N mm for a moment
  bool moment = false;
};

// What the force test found at one iterate.
struct ResidualCheck {
  double relative = 0;            // max of the force and moment residual norms over their references
  bool forces_ok = false;         // both norms within their tolerances and every applied load met
  bool within_roundoff = false;   // the norms pass against the round-off scale of the internal forces
  LoadReference state;            // this iterate's own load norms
  double worst_load = 0;          // largest applied-load residual over its allowance (<= 1: every load met)
};

// Where an iterate stands in its increment, for the convergence decision.
struct IterateProgress {
  bool predictor = true;          // the attempt's starting iterate, before any correction or contact round
  int corrections = 0;            // Newton corrections made so far in this attempt
  double correction2 = 0;         // squared norm of the last correction (rotations weighted by the element length)
  double increment_motion2 = 0;   // squared motion of the increment so far (at least the cut-increment floor)
  double previous_load_norm = 0;  // the load norm of the iterate before this one
};

// The decision at an iterate.
struct Convergence {
  bool converged = false;
  bool force_only = false;  // accepted on the force test alone (the displacement test did not pass)
};

// The residual norms are taken against the larger of the iterate's load norms and the largest of the step's
// converged states (its start included), so that a strand released to zero load is measured against the load
// it carried; each applied load is met to load_tolerance of its own largest value in the step, however small it
// is beside the others (a transverse load under a large tension).
class ConvergenceTest {
 public:
  // length_scale: mean element length (moments <-> forces); force_floor: smallest meaningful force reference;
  // roundoff_force: the round-off scale of assembled internal forces.
  ConvergenceTest(const SolverOptions& options, double length_scale, double force_floor, double roundoff_force);

  // The step starts from a converged state with these load norms.
  void begin_step(const LoadReference& start) { step_reference_ = start; }
  // A converged increment's load norms join the step's largest.
  void accept(const LoadReference& converged);
  const LoadReference& step_reference() const { return step_reference_; }
  // The applied loads of the current increment.
  void set_applied_loads(std::vector<AppliedLoad> loads) { loads_ = std::move(loads); }

  // Load norms of a state: applied loads at free DOFs, internal forces (reactions) at constrained ones.
  LoadReference load_norms(const DofMap& dofs, const std::vector<double>& internal, const std::vector<double>& external) const;
  // The test at an iterate; rhs (equation-sized) becomes minus the residual at the free DOFs.
  ResidualCheck measure(const DofMap& dofs, const std::vector<double>& internal, const std::vector<double>& external,
                        std::vector<double>& rhs) const;
  // Converged: the force test, and the last correction within displacement_tolerance of the increment's motion. A
  // predictor (no correction yet) passes only with its residual far within the tolerance, so that residuals do
  // not pile up from increment to increment. After several corrections an iterate far within the force test whose
  // load norm has settled is accepted on the force test alone: along a soft mode (a wire hinging plastically
  // between crossings) the corrections keep alternating while equilibrium holds (docs/theory.md).
  Convergence decide(const ResidualCheck& check, const IterateProgress& progress) const;

 private:
  double force_tolerance_, moment_tolerance_, load_tolerance_, displacement_tolerance_;
  double length_scale_, force_floor_, roundoff_force_;
  LoadReference step_reference_;
  std::vector<AppliedLoad> loads_;
};

}  // namespace strandfem
