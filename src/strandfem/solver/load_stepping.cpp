// Load stepping of a static analysis: the protocol's ramps, increment sizes, cut-backs and regrowth, commits.
#include <algorithm>
#include <cstdio>
#include <cmath>

#include "strandfem/core/scoped_timer.hpp"
#include "strandfem/solver/static_analysis.hpp"

namespace strandfem {
namespace {
constexpr int kRecoveryLineSearchCuts = 4;  // halvings per correction after a failed attempt, and while stabilized
// The automatic stabilization: viscous damping of this fraction of the wires' elastic stiffness, and contact springs
// of this fraction of the normal penalty, on the motion since the last converged increment (docs/theory.md,
// "Automatic stabilization"); IncrementController decides when it acts.
constexpr double kAutomaticViscousStabilization = 0.01;
constexpr double kAutomaticContactStabilization = 1e-4;
}  // namespace

void StaticAnalysis::set_automatic_stabilization(bool on) {
  if (on && !stabilization_.initialized()) {
    std::vector<NodeState> reference;
    for (const MeshNode& n : model_.mesh.nodes) reference.push_back(n.reference);
    stabilization_.initialize(model_.elements, reference);
  }
  const double contact = model_.contact_settings.stabilization;
  for (Interaction* interaction : model_state_.interactions())
    interaction->set_stabilization(on ? std::max(contact, kAutomaticContactStabilization) : contact, model_.mesh, committed_state_);
}

std::string StaticAnalysis::stop_message(const std::string& step_name, int ramp, int increment, double converged_fraction,
                                         double target, double nominal, const IncrementReport& last) const {
  const SolverOptions& opt = model_.options;
  char text[1024];
  std::snprintf(text, sizeof text,
                "step %d '%s', increment %d: Newton did not converge from load fraction %.6g to %.6g of the step "
                "(last relative residual %.3g against the tolerance %.3g after %d corrections; the last attempt gave up: "
                "%s).\n",
                ramp + 1, step_name.c_str(), increment, converged_fraction, target, last.residual_norm,
                std::min(opt.force_tolerance, opt.moment_tolerance), last.corrections, describe(last.failure).c_str());
  std::string message = text;
  const int cuts = std::max(opt.line_search_cuts, kRecoveryLineSearchCuts);
  const std::string search = opt.line_search_cuts >= kRecoveryLineSearchCuts ? "" : " from the first cut-back on";
  std::snprintf(text, sizeof text,
                "  tried: the plain predictor where the extrapolated one failed, the contact step control, line search "
                "(%d halvings per correction)%s, and halving the increment %d times, down to %.3g of the nominal size "
                "(%.3g of the step).\n",
                cuts, search.c_str(), opt.max_cutbacks, std::ldexp(1.0, -opt.max_cutbacks),
                nominal * std::ldexp(1.0, -opt.max_cutbacks));
  message += text;
  if (opt.automatic_stabilization)
    message += "  then the automatic stabilization (viscous and contact, with line search) for the rest of the step, from a "
               "quarter of the nominal increment, with the same halvings.\n";
  message +=
      "  check: a load or motion beyond what the strand can carry at this point (a wire yielding through, or sliding "
      "without end); wires that overlap in the reference geometry (`strandfem info` gives each layer's "
      "lateral_clearance_mm and radial_overlap_mm); too few increments for this step (raise its `increments`).";
  return message;
}

double cut_increment_motion_floor2(double last_motion2, double last_size, double size, double nominal) {
  if (!(last_size > 0) || size >= nominal * (1.0 - 1e-9)) return 0.0;
  const double scale = nominal / last_size;
  return last_motion2 * scale * scale;
}

AnalysisStatus StaticAnalysis::run(const std::function<void(const IncrementReport&)>& on_increment,
                                   const std::function<void(const IncrementReport&)>& on_progress) {
  const std::vector<LoadRamp> protocol = expand_load_steps(model_.steps);
  Progress& p = progress_;  // a restored checkpoint resumes mid-step, with the sizes it had
  IncrementController& control = p.control;
  while (p.ramp < static_cast<int>(protocol.size())) {
    const LoadRamp& step = protocol[p.ramp];
    std::map<ActionKey, std::pair<double, double>> ramps;
    for (const auto& [key, value] : p.totals) ramps[key] = {value, value};
    for (const NodalAction& a : step.actions) {
      const ActionKey key{a.node, a.component, a.kind};
      const double start = p.totals.count(key) ? p.totals[key] : 0.0;
      ramps[key] = {start, a.value};
    }
    bool idle_step = true;  // no action changes over the step
    bool moves_driven_dofs = false;  // an imposed motion changes over the step
    for (const auto& [key, ramp] : ramps) {
      idle_step = idle_step && ramp.first == ramp.second;
      moves_driven_dofs = moves_driven_dofs || (key.kind == NodalAction::kMotion && ramp.first != ramp.second);
    }
    if (!p.in_step) {
      p.in_step = true;
      if (control.sizes().stabilized) set_automatic_stabilization(false);
      convergence_.begin_step(convergence_.load_norms(dofs_, committed_forces_, committed_external_));
      control.begin_step(step.increments, carried_last_size(ramps));
    } else {
      control.resume_step(step.increments);
    }
    const double nominal = control.nominal();
    while (!control.step_done()) {
      const IncrementController::Sizes& c = control.sizes();
      const double target = control.target();
      IncrementReport report;
      report.step = p.ramp;
      report.step_name = step.name;
      report.origin = step.origin;
      report.increment = c.converged_increments + 1;
      report.step_fraction = target;
      report.cutbacks = control.cutbacks();
      report.relative_size = (target - c.fraction) / nominal;
      // Extrapolate within a step or across steps that load the same way (not across a reversal), and not on
      // the retry of a failed increment: a poor predictor must not cost the whole cut-back sequence. Once a plain
      // retry has converged where the extrapolated predictor failed, the step goes on without extrapolating: past
      // a yield knee each extrapolated attempt would otherwise fail again (docs/theory.md).
      // Not under applied loads alone while the viscous stabilization acts: the damped soft modes (contacts settling)
      // lag, so the last increment's motion holds a decaying transient that a secant predictor overshoots, while the
      // plain predictor's first correction, from a converged state with its tangent, is the tangent predictor
      // (on Cardinal's tension ramp the extrapolated predictor takes two to four times the corrections).
      // Where the step moves driven DOFs the plain predictor strains the elements next to them alone (docs/theory.md).
      const bool secant_predictor = moves_driven_dofs || !(model_.options.stabilization > 0 || c.stabilized);
      const double extrapolation = model_.options.extrapolate && secant_predictor && !idle_step && control.may_extrapolate()
                                       ? (target - c.fraction) / c.last_size
                                       : 0.0;
      // Ramped off: the factor falls linearly from its full value at the step's start to zero at its end.
      stabilization_factor_ = model_.options.stabilization * (model_.options.stabilization_ramp_off ? 1.0 - c.fraction : 1.0);
      if (c.stabilized) stabilization_factor_ = std::max(stabilization_factor_, kAutomaticViscousStabilization);
      // From a cut-back until the sizes are back at the nominal one, and while the automatic stabilization acts, the
      // attempts search their corrections where the case runs without line search (docs/theory.md, "Increment control").
      const bool searched = (control.recovering() || c.stabilized) && model_.options.line_search_cuts < kRecoveryLineSearchCuts;
      // Within a ramp, or across ramps that load the same way, there is a last increment to continue from; the first
      // increment of a ramp that turns the loading has none (last_size 0).
      const bool loading_continues = c.last_size > 0;
      // A cut increment's corrections are measured against the motion a nominal increment would have (the last
      // converged one's, scaled to the nominal size), not against its own: halving an increment must not tighten the
      // displacement test in absolute terms, or contact chatter of a fixed size (stick/slip, the normal band) keeps
      // cut increments from converging at all (docs/theory.md, "Displacement test of a cut increment").
      const double motion_floor2 =
          loading_continues && !previous_committed_state_.empty()
              ? cut_increment_motion_floor2(motion2(committed_state_, previous_committed_state_), c.last_size,
                                            target - c.fraction, nominal)
              : 0.0;
      const IncrementAttempt attempt{target, extrapolation, idle_step, loading_continues, motion_floor2, control.cutbacks() > 0,
                                     searched ? kRecoveryLineSearchCuts : model_.options.line_search_cuts};
      if (solve_increment(attempt, ramps, report, on_progress)) {
        const bool recovered_by_search = searched && !c.stabilized;  // the stabilized mode searches as part of it
        if (recovered_by_search) ++statistics_.searched_recoveries;
        report.searched_recovery = recovered_by_search;
        report.stabilized = c.stabilized;
        if (report.force_only) ++statistics_.force_only_acceptances;
        bool pattern_changed = false;
        {
          const ScopedTimer timer(statistics_.commit_seconds);
          for (BeamElementState& e : model_state_.elements) e.commit();
          for (Interaction* interaction : model_state_.interactions()) pattern_changed |= interaction->commit(model_.mesh, state_);
        }
        if (pattern_changed) rebuild_pattern();  // element pairs entered or left the pattern
        convergence_.accept(convergence_.load_norms(dofs_, internal_forces_, external_));
        add_increment_work();
        previous_committed_state_ = committed_state_;
        committed_state_ = state_;
        committed_motion_ = applied_motion_;
        control.converged(report.size_corrections());
        if (control.step_done()) end_step(ramps);
        // Last: the callback may save a checkpoint, which must hold the progress as it now stands.
        if (on_increment) on_increment(report);
        continue;
      }
      for (BeamElementState& e : model_state_.elements) e.revert();
      for (Interaction* interaction : model_state_.interactions()) interaction->revert();
      state_ = committed_state_;
      applied_motion_ = committed_motion_;
      assembler_->assemble(model_, model_state_, state_, internal_forces_, nullptr);
      switch (control.failed(report.extrapolated)) {
        case Recovery::kPlainRetry: ++statistics_.plain_retries; break;
        case Recovery::kHalve: break;
        case Recovery::kStabilize:
          set_automatic_stabilization(true);
          ++statistics_.stabilized_steps;
          break;
        case Recovery::kStop: {
          AnalysisStatus status;
          status.converged = false;
          status.message = stop_message(step.name, p.ramp, c.converged_increments + 1, c.fraction, target, nominal, report);
          return status;
        }
      }
    }
    if (p.in_step) end_step(ramps);  // not reached: the last increment closes the step
  }
  return {};
}

double StaticAnalysis::carried_last_size(const std::map<ActionKey, std::pair<double, double>>& ramps) const {
  // A step that goes on loading the same way as the previous one (every action changes by the same positive
  // multiple c of its previous change) extrapolates from that step's last increment, which measures 1/c of it.
  const Progress& p = progress_;
  double c = 0, largest = 0;
  for (const auto& [key, ramp] : ramps) {
    const double before = p.previous_change.count(key) ? p.previous_change.at(key) : 0.0;
    if (std::abs(before) > largest) largest = std::abs(before), c = (ramp.second - ramp.first) / before;
  }
  if (!(c > 0)) return 0.0;
  for (const auto& [key, ramp] : ramps) {
    const double before = p.previous_change.count(key) ? p.previous_change.at(key) : 0.0, now = ramp.second - ramp.first;
    if (std::abs(now - c * before) > 1e-9 * (std::abs(now) + std::abs(before))) return 0.0;
  }
  return p.previous_last_size / c;
}

void StaticAnalysis::add_increment_work() {
  energies_.stabilization_energy +=
      stabilization_.dissipated_energy(model_.elements, state_, committed_state_, stabilization_factor_);
  for (const Interaction* interaction : model_state_.interactions()) energies_.stabilization_energy += interaction->commit_stabilization_energy();
  // Forces conjugate to the motion: reactions where the DOF is driven or supported, applied loads where it is free.
  double work = 0;
  for (std::size_t node = 0; node < state_.size(); ++node) {
    if (dofs_.tie_of[node] >= 0) continue;
    const Vec3 displacement = state_[node].position - committed_state_[node].position;
    const Vec3 rotation = rotation_vector_from_quaternion(state_[node].rotation * committed_state_[node].rotation.conjugate());
    for (int c = 0; c < 6; ++c) {
      const std::size_t i = 6 * node + c;
      const bool free = dofs_.equation[node][c] >= 0;
      const double before = free ? committed_external_[i] : committed_forces_[i], now = free ? external_[i] : internal_forces_[i];
      work += 0.5 * (before + now) * (c < 3 ? displacement[c] : rotation[c - 3]);
    }
  }
  energies_.external_work += work;
  committed_forces_ = internal_forces_;
  committed_external_ = external_;
}

void StaticAnalysis::end_step(const std::map<ActionKey, std::pair<double, double>>& ramps) {
  Progress& p = progress_;
  p.previous_change.clear();
  for (const auto& [key, ramp] : ramps) {
    p.totals[key] = ramp.second;
    p.previous_change[key] = ramp.second - ramp.first;
  }
  p.previous_last_size = p.control.sizes().last_size;
  p.in_step = false;
  ++p.ramp;
}

}  // namespace strandfem
