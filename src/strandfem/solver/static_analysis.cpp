// Newton iterations of a static analysis: one increment at a time, with its linear solves and pattern.
#include "strandfem/solver/static_analysis.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "strandfem/core/scoped_timer.hpp"
#include "strandfem/solver/attempt_budget.hpp"
#include "strandfem/solver/krylov.hpp"
#include "strandfem/solver/step_length.hpp"
#include "strandfem/solver/tangent_dump.hpp"

namespace strandfem {

namespace {
constexpr int kMaxContactRounds = 40;  // contact set changes per increment before a cut-back
// Scale of the round-off in assembled internal forces, as a fraction of the largest axial stiffness EA: sqrt of
// the machine epsilon. Measured at zero load: 9e-16 EA (7-wire strand), 1.6e-13 EA (the same with contact, whose
// penalties are far stiffer than EA / h); a real unbalance of 1.5e-8 EA is a strain of 1.5e-8 (docs/theory.md).
constexpr double kRoundoffFraction = 1.5e-8;
// Smallest force reference, as a fraction of EA: keeps the relative residual finite in a load-free state.
constexpr double kForceFloorFraction = 1e-12;
// Loosest linear solve of the inexact Newton (SolverOptions::newton_forcing): a correction accurate to 10 % still
// measures itself well enough for the displacement test.
constexpr double kMaxForcing = 0.1;

}  // namespace

std::string describe(AttemptFailure failure) {
  switch (failure) {
    case AttemptFailure::kNone: return "converged";
    case AttemptFailure::kNotFinite: return "the residual is not a finite number";
    case AttemptFailure::kDiverging:
      return "diverging: " + std::to_string(AttemptBudget::kDivergenceWindow) +
             " corrections after the last contact change the residual is above where they started";
    case AttemptFailure::kIterationLimit: return "solver.max_iterations corrections without convergence";
    case AttemptFailure::kContactRounds:
      return "the contact states kept changing at convergence (" + std::to_string(kMaxContactRounds) + " rounds)";
    case AttemptFailure::kRunaway: return "a correction longer than the model itself";
    case AttemptFailure::kLinearSolve: return "the linear solve failed";
  }
  return "";
}

StaticAnalysis::StaticAnalysis(Model& model) : model_(model), convergence_(model.options, 1.0, 0.0, 0.0) {
  model_.options.validate();
  progress_.control = IncrementController(
      {model_.options.max_cutbacks, model_.options.max_iterations, model_.options.automatic_stabilization});
  if (model_.options.threads > 0) omp_set_num_threads(model_.options.threads);
  if (model_.elements.empty()) model_.build_elements();
  model_state_ = ModelState::initial(model_);
  dofs_ = build_dof_map(model_);
  model_state_.contacts.initialize(model_.mesh, model_.contact_settings);
  solver_ = make_linear_solver(model_.options.linear_solver);
  build_pattern();
  for (const MeshNode& n : model_.mesh.nodes) state_.push_back(n.reference);
  committed_state_ = state_;
  if (model_.options.stabilization > 0) stabilization_.initialize(model_.elements, state_);
  // Scales that keep the convergence test meaningful when the reference load is zero.
  double stiffest = 0, total_length = 0;
  for (const BeamElement& e : model_.elements) {
    stiffest = std::max(stiffest, e.section().elastic_stiffness()[0]);
    total_length += e.reference_length();
  }
  length_scale_ = model_.elements.empty() ? 1.0 : total_length / model_.elements.size();
  convergence_ = ConvergenceTest(model_.options, length_scale_, kForceFloorFraction * stiffest, kRoundoffFraction * stiffest);
  Eigen::AlignedBox3d box;
  for (const NodeState& n : state_) box.extend(n.position);
  model_extent2_ = state_.empty() ? 0.0 : std::max(box.diagonal().squaredNorm(), length_scale_ * length_scale_);
  internal_forces_.assign(6 * state_.size(), 0.0);
  committed_forces_ = external_ = committed_external_ = internal_forces_;
}

void StaticAnalysis::analyze() {
  if (dofs_.equation_count == 0) return;  // all DOFs driven: nothing to factor
  const ScopedTimer timer(statistics_.pattern_seconds);
  solver_->analyze(assembler_->pattern());
  analysis_pending_ = false;
}

KrylovResult StaticAnalysis::preconditioned_solve(std::vector<double>& rhs, int max_iterations, double tolerance) {
  std::vector<double> x;
  const KrylovResult k = gmres(assembler_->pattern(), values_, [this](std::vector<double>& v) { solver_->solve(v); }, rhs,
                               x, tolerance, max_iterations);
  statistics_.krylov_iterations += k.iterations;
  if (k.converged) {
    ++statistics_.krylov_solves;
    rhs = x;
  }
  return k;
}

bool StaticAnalysis::solve_linear(std::vector<double>& rhs, double tolerance) {
  const SolverOptions& opt = model_.options;
  // The factors of an earlier tangent precondition this one, also across a pattern change: GMRES multiplies by
  // the current tangent, and the factors only need the same equations.
  if (factorization_usable_ && opt.krylov_iterations > 0) {
    const ScopedTimer timer(statistics_.linear_seconds);
    try {
      const KrylovResult k = preconditioned_solve(rhs, opt.krylov_iterations, tolerance);
      // A preconditioner that needs more than half the allowed iterations has aged: refactor next time.
      if (k.iterations > opt.krylov_iterations / 2) factorization_usable_ = false;
      if (k.converged) return true;
    } catch (const LinearSolverError&) {
      factorization_usable_ = false;
      return false;
    }
  }
  // The symbolic analysis of a new pattern waits for its first factorization, so that the old factors serve
  // until then.
  if (analysis_pending_) analyze();
  const ScopedTimer timer(statistics_.linear_seconds);
  try {
    if (opt.dump_tangent_factorization == solver_->statistics().factorizations + 1)
      write_tangent(opt.dump_tangent_path, assembler_->pattern(), values_);
    solver_->factorize(values_);
    factorization_usable_ = true;
    if (!solver_->needs_refinement()) {
      solver_->solve(rhs);
      return true;
    }
    // Single-precision factors: GMRES on the tangent brings the correction to the double-precision tolerance.
    if (preconditioned_solve(rhs, opt.refinement_iterations, tolerance).converged) return true;
    // Too ill-conditioned for single precision: this tangent is factored and solved in double.
    factorization_usable_ = false;
    if (!fallback_solver_) fallback_solver_ = make_linear_solver("mumps");
    if (!fallback_analyzed_) fallback_solver_->analyze(assembler_->pattern());
    fallback_analyzed_ = true;
    fallback_solver_->factorize(values_);
    fallback_solver_->solve(rhs);
    ++statistics_.double_precision_fallbacks;
  } catch (const LinearSolverError&) {
    factorization_usable_ = false;
    return false;
  }
  return true;
}

void StaticAnalysis::build_pattern() {
  assembler_ = std::make_unique<Assembler>(model_, model_state_, dofs_);
  analysis_pending_ = true;
  fallback_analyzed_ = false;
}

void StaticAnalysis::rebuild_pattern() {
  const ScopedTimer timer(statistics_.pattern_seconds);
  build_pattern();
  ++statistics_.pattern_rebuilds;
}

double StaticAnalysis::motion2(const std::vector<NodeState>& to, const std::vector<NodeState>& from) const {
  double total = 0;
  for (std::size_t node = 0; node < to.size(); ++node) {
    const Vec3 rotation = rotation_vector_from_quaternion(to[node].rotation * from[node].rotation.conjugate());
    total += (to[node].position - from[node].position).squaredNorm() + length_scale_ * length_scale_ * rotation.squaredNorm();
  }
  return total;
}

double StaticAnalysis::linear_tolerance(double relative_residual) const {
  const SolverOptions& opt = model_.options;
  if (opt.newton_forcing <= 0 || !(relative_residual > 0)) return opt.krylov_tolerance;
  // A linear residual of forcing x tolerance leaves the next iterate's residual at about that, as long as the
  // Newton step itself is good: the loose solves are those of iterates already near the tolerance.
  const double forcing = opt.newton_forcing * std::min(opt.force_tolerance, opt.moment_tolerance) / relative_residual;
  return std::max(opt.krylov_tolerance, std::min(forcing, kMaxForcing));  // never looser than krylov_tolerance asks
}

void StaticAnalysis::update_slaves() {
  for (const RigidTie& tie : model_.ties) state_[tie.slave] = tied_state(tie, state_[tie.master]);
}

void StaticAnalysis::extrapolate_free_motion(double factor) {
  for (std::size_t node = 0; node < state_.size(); ++node) {
    if (dofs_.tie_of[node] >= 0) continue;
    const NodeState &now = committed_state_[node], &before = previous_committed_state_[node];
    const Vec3 rotation = rotation_vector_from_quaternion(now.rotation * before.rotation.conjugate());
    Vec3 du = Vec3::Zero(), dtheta = Vec3::Zero();
    for (int c = 0; c < 6; ++c) {
      if (dofs_.equation[node][c] < 0) continue;  // driven or supported: the ramp sets it
      if (c < 3) du[c] = factor * (now.position[c] - before.position[c]);
      else dtheta[c - 3] = factor * rotation[c - 3];
    }
    state_[node].position += du;
    state_[node].rotation = (quaternion_from_rotation_vector(dtheta) * state_[node].rotation).normalized();
  }
}

void StaticAnalysis::apply_targets(double step_fraction, const std::map<ActionKey, std::pair<double, double>>& ramps) {
  external_.assign(6 * state_.size(), 0.0);
  std::vector<AppliedLoad> loads;
  for (const auto& [key, ramp] : ramps) {
    const double target = ramp.first + step_fraction * (ramp.second - ramp.first);
    if (key.kind == NodalAction::kForce) {
      external_[6 * key.node + key.component] += target;
      const int eq = dofs_.equation[key.node][key.component];
      const double largest = std::max(std::abs(ramp.first), std::abs(ramp.second));
      if (eq >= 0 && largest > 0) loads.push_back({eq, largest, key.component >= 3});
      continue;
    }
    const double delta = target - applied_motion_[key];
    applied_motion_[key] = target;
    NodeState& s = state_[key.node];
    if (key.component < 3) s.position[key.component] += delta;
    else s.rotation = (quaternion_from_rotation_vector(delta * Vec3::Unit(key.component - 3)) * s.rotation).normalized();
  }
  convergence_.set_applied_loads(std::move(loads));
  update_slaves();
}

ResidualCheck StaticAnalysis::evaluate_residual(std::vector<double>& rhs) {
  {
    const ScopedTimer timer(statistics_.residual_seconds);
    assembler_->assemble(model_, model_state_, state_, internal_forces_, nullptr, damping());
  }
  return convergence_.measure(dofs_, internal_forces_, external_, rhs);
}

double StaticAnalysis::apply_correction(const std::vector<NodeState>& start, const std::vector<double>& correction, double alpha) {
  state_ = start;
  double norm2 = 0;
  for (std::size_t node = 0; node < state_.size(); ++node) {
    if (dofs_.tie_of[node] >= 0) continue;
    Vec3 du = Vec3::Zero(), dtheta = Vec3::Zero();
    for (int c = 0; c < 6; ++c) {
      const int eq = dofs_.equation[node][c];
      if (eq < 0) continue;
      (c < 3 ? du[c] : dtheta[c - 3]) = alpha * correction[eq];
    }
    norm2 += du.squaredNorm() + length_scale_ * length_scale_ * dtheta.squaredNorm();
    state_[node].position += du;
    state_[node].rotation = (quaternion_from_rotation_vector(dtheta) * state_[node].rotation).normalized();
  }
  update_slaves();
  return norm2;
}

void StaticAnalysis::accept_iterate() {
  bool pattern_grew = false;
  for (Interaction* interaction : model_state_.interactions()) {
    interaction->accept_iterate(model_.mesh);
    pattern_grew |= interaction->element_pairs_grew();
  }
  // A contact closed outside the tangent's pattern: widen it now, so that the next tangent is complete.
  if (pattern_grew) rebuild_pattern();
}

int StaticAnalysis::changes_at_convergence() {
  int changes = 0;
  for (Interaction* interaction : model_state_.interactions()) changes += interaction->changes_at_convergence();
  return changes;
}

int StaticAnalysis::augment_at_convergence() {
  int changes = 0;
  for (Interaction* interaction : model_state_.interactions()) changes += interaction->augment_at_convergence();
  if (changes > 0) ++statistics_.stick_augmentations;
  return changes;
}

ResidualCheck StaticAnalysis::choose_predictor(double extrapolation, ResidualCheck plain, std::vector<double>& rhs, IncrementReport& report) {
  if (!(extrapolation > 0)) return plain;
  // The extrapolated predictor must beat the plain one: after slip events or contact changes the last
  // increment's motion is not proportional to the load, and extrapolating it can start Newton far off.
  const std::vector<NodeState> plain_state = state_;
  extrapolate_free_motion(extrapolation);
  update_slaves();
  const ResidualCheck extrapolated = evaluate_residual(rhs);
  if (extrapolated.relative < plain.relative) {
    report.extrapolated = true;
    return extrapolated;
  }
  state_ = plain_state;
  ++statistics_.rejected_extrapolations;
  return evaluate_residual(rhs);
}

bool StaticAnalysis::solve_increment(const IncrementAttempt& attempt, const std::map<ActionKey, std::pair<double, double>>& ramps,
                                     IncrementReport& report, const std::function<void(const IncrementReport&)>& on_progress) {
  const SolverOptions& opt = model_.options;
  // Applied loads, and imposed motions: the driven DOFs move to their targets before iterating.
  apply_targets(attempt.step_fraction, ramps);
  for (Interaction* interaction : model_state_.interactions()) interaction->begin_increment(attempt.loading_continues);
  std::vector<double> rhs(dofs_.equation_count);
  double increment_displacement2 = 0;
  last_correction2_ = 0;
  ResidualCheck current = evaluate_residual(rhs);
  // A step with nothing to do starts where the last one converged (or from the stress-free reference state), for
  // the same loads: Newton could only chase round-off, and its displacement test (correction against the
  // increment's motion, both nil) could never pass. Accepted at once when its residual is round-off; the
  // interactions keep the states they converged with (contact forces of round-off size have no sign to act on).
  if (attempt.idle_step && current.within_roundoff) {
    accept_iterate();
    report.residual_history.push_back(current.relative);
    report.residual_norm = current.relative;
    report.iterations = 0;
    if (on_progress) on_progress(report);
    return true;
  }
  current = choose_predictor(attempt.extrapolation, current, rhs, report);
  accept_iterate();
  // Newton iterations count from the last contact change (release or friction switch); the number of such
  // rounds per increment is capped separately.
  AttemptBudget budget(opt.max_iterations, current.relative);
  int rounds = 0;
  double previous_reference = 0;  // load norm of the iterate before the current one
  bool augmented = false;  // an augmentation round since the last correction: Newton must correct before accepting
  // The converged iterate before the last augmentation round: where a failure after a round returns to.
  std::vector<NodeState> converged_round;
  double round_load_norm = 0;  // the load norm there
  double round_residual = 0;   // and its relative residual
  // Rounds end once one has moved the nodes and the loads (reactions included) by less than Newton's own tests allow.
  const auto last_round_settled = [&] {
    const double motion_tolerance = opt.displacement_tolerance;
    return !converged_round.empty() && motion2(state_, converged_round) <= motion_tolerance * motion_tolerance * increment_displacement2 &&
           std::abs(current.state.force - round_load_norm) <= opt.force_tolerance * std::max(current.state.force, round_load_norm);
  };
  const auto fail = [&](AttemptFailure why) {
    report.failure = why;
    report.kept_converged_round = !converged_round.empty();
    if (on_progress) on_progress(report);
    if (converged_round.empty()) return false;
    report.failure = AttemptFailure::kNone;
    state_ = converged_round;
    for (Interaction* interaction : model_state_.interactions()) interaction->return_to_converged_round();
    evaluate_residual(rhs);
    report.residual_norm = round_residual;  // the increment's record is the iterate it keeps
    ++statistics_.abandoned_augmentations;
    return true;
  };
  for (int iteration = 0;; ++iteration, budget.next()) {
    report.residual_history.push_back(current.relative);
    report.residual_norm = current.relative;
    report.iterations = iteration;
    if (on_progress) on_progress(report);
    if (!std::isfinite(current.relative)) return fail(AttemptFailure::kNotFinite);
    if (budget.diverging(current.relative)) return fail(AttemptFailure::kDiverging);
    const Convergence decision =
        convergence_.decide(current, {iteration == 0, report.corrections, last_correction2_, increment_displacement2, previous_reference});
    if (decision.converged && (!augmented || dofs_.equation_count == 0)) {
      report.force_only = decision.force_only;
      // Converged for the interactions' current states (contact: active set, held friction); they may
      // change them (contacts left in tension open), or augment (the stick), and Newton goes on.
      report.step_length = 1;
      report.step_limited = false;
      report.state_changes = changes_at_convergence();
      report.augmented_points = 0;
      if (report.state_changes == 0) {
        if (last_round_settled()) return true;
        round_load_norm = current.state.force;
        round_residual = current.relative;
        report.augmented_points = augment_at_convergence();
        if (report.augmented_points == 0) return true;
        if (report.corrections_before_rounds < 0) report.corrections_before_rounds = report.corrections;
        converged_round = state_;  // a round changes the interactions' values, not the nodes
        augmented = true;
      }
      if (++rounds > kMaxContactRounds) return fail(AttemptFailure::kContactRounds);
      current = evaluate_residual(rhs);
      accept_iterate();
      budget.restart(current.relative);
      continue;
    }
    if (budget.spent()) return fail(AttemptFailure::kIterationLimit);
    ++statistics_.newton_iterations;
    ++report.corrections;
    {
      const ScopedTimer timer(statistics_.assembly_seconds);
      assembler_->assemble(model_, model_state_, state_, internal_forces_, &values_, damping());
    }
    if (!solve_linear(rhs, linear_tolerance(current.relative))) return fail(AttemptFailure::kLinearSolve);
    augmented = false;
    const std::vector<NodeState> start = state_;
    const std::vector<double> correction = rhs;
    // Line search on every correction but an attempt's first, which carries the load step (its residual is no
    // measure of progress); after a cut-back the first is searched too (docs/theory.md, "Line search").
    const bool first_correction = report.corrections == 1;
    const int line_search_cuts = first_correction && !attempt.after_cutback ? 0 : attempt.line_search_cuts;
    for (Interaction* interaction : model_state_.interactions()) interaction->begin_correction();
    // Step control (the interactions' admissible fraction): a correction that presses contacts its tangent did not
    // know deep into the penalty stops where they have just closed (docs/theory.md, "Step control").
    const auto try_step = [&](double alpha) {
      StepTrial t;
      t.alpha = alpha;
      t.correction2 = apply_correction(start, correction, alpha);
      t.check = evaluate_residual(rhs);
      return t;
    };
    const auto admissible = [&] {
      double fraction = 1;
      for (const Interaction* interaction : model_state_.interactions()) fraction = std::min(fraction, interaction->admissible_fraction());
      return fraction;
    };
    const StepLength step = choose_step_length(try_step, admissible, current.relative, line_search_cuts);
    if (step.limited) ++statistics_.limited_corrections;
    report.step_length = step.accepted.alpha;
    report.step_limited = step.limited;
    report.state_changes = report.augmented_points = 0;
    // The displacement test measures what Newton asked for: a correction cut by the step control has not converged
    // because its cut part is short.
    last_correction2_ = step.limited ? std::max(step.accepted.correction2, step.full_correction2) : step.accepted.correction2;
    previous_reference = current.state.force;
    current = step.accepted.check;
    if (first_correction) budget.first_correction_left(current.relative);
    accept_iterate();
    // A correction longer than the model itself is divergence, not progress: cut back at once.
    if (last_correction2_ > model_extent2_) return fail(AttemptFailure::kRunaway);
    increment_displacement2 = std::max(motion2(state_, committed_state_), attempt.motion_floor2);
    report.correction_ratio = increment_displacement2 > 0 ? std::sqrt(last_correction2_ / increment_displacement2) : 0.0;
  }
}

}  // namespace strandfem
