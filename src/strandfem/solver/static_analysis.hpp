// Incremental-iterative static analysis: load steps, full Newton-Raphson, increment cut-back and regrowth.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "strandfem/solver/assembler.hpp"
#include "strandfem/solver/convergence_test.hpp"
#include "strandfem/solver/increment_controller.hpp"
#include "strandfem/solver/krylov.hpp"
#include "strandfem/solver/model.hpp"
#include "strandfem/solver/stabilization.hpp"

namespace strandfem {

// Why a Newton attempt gave up (docs/theory.md, "Increment control").
enum class AttemptFailure { kNone, kNotFinite, kDiverging, kIterationLimit, kContactRounds, kRunaway, kLinearSolve };
// The reason in words, for progress lines and stop messages.
std::string describe(AttemptFailure failure);

// What a converged increment reports; during its Newton solve, what each iteration did.
struct IncrementReport {
  int step = 0;                // 0-based index of the ramp in the expanded load protocol
  std::string step_name;
  RampOrigin origin;           // the case step (and cycle) the ramp comes from
  int increment = 0;           // 1-based converged increment counter within the step
  double step_fraction = 0;    // load factor within the step, 0..1
  int iterations = 0;          // Newton iterations and contact rounds
  int corrections = 0;         // Newton corrections (tangent solves) among them
  std::vector<double> residual_history;  // relative residual (max of force and moment ratios) per iteration
  double residual_norm = 0;    // the final relative residual
  double correction_ratio = 0; // ||last Newton correction|| / ||increment motion|| (the displacement test)
  bool extrapolated = false;   // started from the extrapolated predictor (see SolverOptions::extrapolate)
  bool force_only = false;     // accepted on the force test alone (a tenfold margin after several corrections)
  int cutbacks = 0;            // failed attempts halved before this increment converged
  bool searched_recovery = false;  // converged below the nominal size after a cut-back, with line search the case does not ask for
  bool stabilized = false;     // converged with the automatic stabilization on (SolverOptions::automatic_stabilization)
  double relative_size = 1;    // the increment's size over the step's nominal increment
  // This iteration: the fraction of its correction taken (below 1: cut by an interaction's step control, or by line
  // search), or the interaction state changes (contact releases, friction switches) and stick offsets of the round
  // that preceded it instead of a correction.
  double step_length = 1;
  bool step_limited = false;   // the step control set step_length (line search may have halved it further)
  int state_changes = 0;
  int augmented_points = 0;
  AttemptFailure failure = AttemptFailure::kNone;  // why the attempt gave up (reported once, then the controller acts)
  bool kept_converged_round = false;  // it gave up after a stick augmentation round: the increment keeps the round before
  int corrections_before_rounds = -1;  // Newton corrections before the first stick augmentation round; -1: none ran
  // The corrections the increment's size cost: those before its first augmentation round, since the rounds cost
  // about the same at any size; all of them without a round, or when a round was abandoned.
  int size_corrections() const { return corrections_before_rounds >= 0 && !kept_converged_round ? corrections_before_rounds : corrections; }
};

// What the solver did: counts and wall time per phase (the linear solver's own figures are in
// linear_statistics()).
struct AnalysisStatistics {
  int newton_iterations = 0;   // tangent assemblies
  int krylov_solves = 0;       // linear solves done by GMRES (older or single-precision factors)
  int krylov_iterations = 0;
  int pattern_rebuilds = 0;    // tangent patterns rebuilt (interaction pairs changed); analyzed at their first factorization
  int rejected_extrapolations = 0;  // extrapolated predictors worse than the plain one (not used)
  int force_only_acceptances = 0;  // increments accepted on the force test alone (see IncrementReport::force_only)
  int stick_augmentations = 0;  // augmentation rounds of the stick (contact.stick_augmentations)
  int abandoned_augmentations = 0;  // rounds after which Newton failed: the increment kept the round before
  int plain_retries = 0;       // failed extrapolated increments repeated at the same size without extrapolation
  int searched_recoveries = 0; // increments converged below the nominal size after a cut-back, with line search the case does not ask for
  int stabilized_steps = 0;    // ramps in which the automatic stabilization switched on (SolverOptions)
  int limited_corrections = 0; // Newton corrections shortened by an interaction's step control (admissible_fraction)
  int double_precision_fallbacks = 0;  // single-precision factors that GMRES could not refine: solved in double
  double assembly_seconds = 0; // tangent assembly (elements and interactions) for Newton corrections
  double residual_seconds = 0; // residual evaluations (internal forces only): predictors, iterates, contact rounds
  double commit_seconds = 0;   // commits of converged increments (contact searches included, pattern rebuilds not)
  double linear_seconds = 0;   // factorizations, solves and GMRES
  double pattern_seconds = 0;  // pattern rebuilds and the symbolic analyses (METIS ordering included) of patterns
};

// Work done on the strand and energy taken by the viscous stabilization, summed over converged increments.
struct EnergyBalance {
  double external_work = 0;         // reactions at driven and supported DOFs and applied loads (trapezoidal rule), N mm
  double stabilization_energy = 0;  // dissipated by the viscous stabilization, N mm
};

// Result of run(): 0 converged, otherwise a message saying where it stopped.
struct AnalysisStatus {
  bool converged = true;
  std::string message;
};

// Squared motion below which the displacement test of an increment does not measure its corrections: for an
// increment smaller than the nominal one (after cut-backs) in a ramp that goes on loading, the motion of the last
// converged increment (last_motion2, of size last_size) scaled to the nominal size; otherwise 0. Sizes are fractions
// of the ramp; last_size 0 means there is no last increment to go by (a ramp's first, or one that turns the loading).
double cut_increment_motion_floor2(double last_motion2, double last_size, double size, double nominal);

class StaticAnalysis {
 public:
  explicit StaticAnalysis(Model& model);

  // Runs every load step; calls on_increment after each converged increment (state committed) and
  // on_progress after each Newton iteration (step, increment, iteration, relative residual).
  AnalysisStatus run(const std::function<void(const IncrementReport&)>& on_increment,
                     const std::function<void(const IncrementReport&)>& on_progress = {});

  const std::vector<NodeState>& state() const { return state_; }
  // Internal nodal forces of the last converged state (6 per node, master space): at constrained DOFs
  // these are the reactions, at loaded DOFs the applied loads.
  const std::vector<double>& internal_forces() const { return internal_forces_; }
  const DofMap& dofs() const { return dofs_; }
  const Model& model() const { return model_; }
  // Element section histories and the contact set at the current state (the last converged one between runs).
  const ModelState& model_state() const { return model_state_; }
  std::string linear_solver_name() const { return solver_->name(); }
  const AnalysisStatistics& statistics() const { return statistics_; }
  const EnergyBalance& energies() const { return energies_; }

  // Checkpoints: the converged state after the last increment (nodes, element and interaction histories, the
  // position in the load protocol, the statistics so far). restore_state replaces the initial state; run() then
  // continues from there.
  void save_state(ArchiveWriter& out) const;
  void restore_state(ArchiveReader& in);
  const LinearSolverStatistics& linear_statistics() const { return solver_->statistics(); }

 private:
  struct ActionKey {
    int node, component, kind;
    auto operator<=>(const ActionKey&) const = default;
  };
  // extrapolation: multiple of the last converged increment's free motion added to the predictor (0: none).
  // idle_step: no load or motion changes in this step, so its start is already in equilibrium (docs/theory.md).
  // Where the analysis stands in its load protocol; saved in checkpoints, so that a resumed run goes on with the
  // increment sizes and predictor it had.
  struct Progress {
    int ramp = 0;                 // the ramp (expanded load step) being solved
    bool in_step = false;         // the ramp has begun (control holds its sizes)
    IncrementController control;  // the ramp's increment sizes, cut-backs and recovery
    std::map<ActionKey, double> totals;           // action values at the end of the previous ramp
    std::map<ActionKey, double> previous_change;  // each action's change over the previous ramp
    double previous_last_size = 0;                // that ramp's last converged increment (its fraction units)
  };
  void end_step(const std::map<ActionKey, std::pair<double, double>>& ramps);
  // The last increment of the previous ramp in this ramp's fraction units where this ramp goes on loading the same
  // way (0: it does not).
  double carried_last_size(const std::map<ActionKey, std::pair<double, double>>& ramps) const;
  // What a stop says: where Newton failed, what the controller tried, and what in the case to check.
  std::string stop_message(const std::string& step_name, int ramp, int increment, double converged_fraction, double target,
                           double nominal, const IncrementReport& last) const;
  // One Newton solve of an increment, as the load stepping asks for it.
  struct IncrementAttempt {
    double step_fraction = 0;    // the load fraction of the ramp the increment ends at
    double extrapolation = 0;    // multiple of the last increment's free motion added to the predictor (0: none)
    bool idle_step = false;      // nothing changes over the ramp: its start may already be in equilibrium
    bool loading_continues = false;  // the loads change the way they did in the last converged increment
    double motion_floor2 = 0;    // squared motion below which the displacement test does not measure a correction
    bool after_cutback = false;  // follows a failed attempt: its first correction is searched too
    int line_search_cuts = 0;    // halvings per correction (SolverOptions::line_search_cuts, or the recovery's)
  };
  bool solve_increment(const IncrementAttempt& attempt, const std::map<ActionKey, std::pair<double, double>>& ramps,
                       IncrementReport& report, const std::function<void(const IncrementReport&)>& on_progress);
  // The pieces of an increment's Newton solve.
  // Applied loads at this load fraction into external_ (and the convergence test's list); imposed motions moved.
  void apply_targets(double step_fraction, const std::map<ActionKey, std::pair<double, double>>& ramps);
  // The residual at the current state: rhs = -residual on free DOFs, its relative norm and the force test.
  ResidualCheck evaluate_residual(std::vector<double>& rhs);
  // state_ = start + alpha * correction (spins for rotations); returns the squared correction norm.
  double apply_correction(const std::vector<NodeState>& start, const std::vector<double>& correction, double alpha);
  // The interactions take the current iterate (contact: active set, friction states); the pattern widens if needed.
  void accept_iterate();
  // Changes the interactions make to their states at a converged iterate (contacts in tension released...).
  int changes_at_convergence();
  int augment_at_convergence();
  // The extrapolated predictor (factor > 0) where it beats the plain one, whose residual is `plain`.
  ResidualCheck choose_predictor(double extrapolation, ResidualCheck plain, std::vector<double>& rhs, IncrementReport& report);
  void update_slaves();
  void extrapolate_free_motion(double factor);  // adds factor x (committed - previous committed) on free DOFs
  // Squared motion of every node from `from` to `to`, rotations weighted by the mean element length.
  double motion2(const std::vector<NodeState>& to, const std::vector<NodeState>& from) const;
  void analyze();                              // symbolic analysis of the current pattern
  void build_pattern();                        // pattern of the interactions' element pairs; its analysis pending
  void rebuild_pattern();                      // build_pattern() because the pairs changed (counted)
  // rhs in, Newton correction out, to a relative linear residual `tolerance`; false if the solve failed.
  bool solve_linear(std::vector<double>& rhs, double tolerance);
  // Tolerance of the linear solve of a correction from an iterate with this relative residual (newton_forcing).
  double linear_tolerance(double relative_residual) const;
  // GMRES on the current tangent preconditioned by the current factors; rhs becomes the solution if it converged.
  KrylovResult preconditioned_solve(std::vector<double>& rhs, int max_iterations, double tolerance);

  Model& model_;
  ModelState model_state_;
  DofMap dofs_;
  std::unique_ptr<Assembler> assembler_;
  std::unique_ptr<LinearSolver> solver_;
  // Double-precision MUMPS for the solves that single-precision factors cannot precondition (made on first use).
  std::unique_ptr<LinearSolver> fallback_solver_;
  bool fallback_analyzed_ = false;  // for the current pattern
  std::vector<NodeState> state_, committed_state_;
  std::vector<NodeState> previous_committed_state_;  // the converged state before committed_state_
  std::map<ActionKey, double> applied_motion_, committed_motion_;
  std::vector<double> internal_forces_, values_;
  double length_scale_ = 0;
  ConvergenceTest convergence_;
  double model_extent2_ = 0;  // squared diagonal of the reference bounding box
  double last_correction2_ = 0;
  void add_increment_work();
  // Switches the automatic stabilization (SolverOptions::automatic_stabilization) on or off from the converged state;
  // the increment controller decides when.
  void set_automatic_stabilization(bool on);
  // The stabilization for the assembler: this increment's factor against the last converged state.
  ElementDamping damping() const { return {&stabilization_, &committed_state_, stabilization_factor_}; }  // the converged increment's external work and stabilization energy into energies_
  ViscousStabilization stabilization_;
  double stabilization_factor_ = 0;         // this increment's factor (SolverOptions::stabilization, ramped)
  std::vector<double> external_;            // applied nodal loads of the current increment (6 per node)
  std::vector<double> committed_external_;  // and of the last converged one
  std::vector<double> committed_forces_;    // internal forces of the last converged state
  EnergyBalance energies_;
  bool factorization_usable_ = false;  // the last factorization may precondition GMRES on the current tangent
  bool analysis_pending_ = true;       // the current pattern is not analyzed yet (done before its first factorization)
  AnalysisStatistics statistics_;
  Progress progress_;
};

}  // namespace strandfem
