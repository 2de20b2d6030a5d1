#include "strandfem/io/solver_keys.hpp"

#include <limits>

namespace strandfem {
namespace {
constexpr int kMaxThreadsAsked = std::numeric_limits<int>::max();  // the program caps it at the machine's count
using Key = SettingKey<SolverOptions>;
}  // namespace

const std::vector<SettingKey<SolverOptions>>& solver_key_table() {
  static const std::vector<Key> table = {
      number_key("force_tolerance", &SolverOptions::force_tolerance, NumberRange::positive(), "",
                 "Newton converges once the force residual is below this fraction of the applied loads and reactions (docs/theory.md, \"Solver\")",
                 "rarely: every applied load is met to `load_tolerance` anyway; tighten to 1e-4 only to compare runs digit by digit"),
      number_key("moment_tolerance", &SolverOptions::moment_tolerance, NumberRange::positive(), "",
                 "the same for the moment residual", "as `force_tolerance`"),
      number_key("displacement_tolerance", &SolverOptions::displacement_tolerance, NumberRange::positive(), "",
                 "and once the last correction is below this fraction of the increment's motion", "as `force_tolerance`"),
      number_key("load_tolerance", &SolverOptions::load_tolerance, NumberRange::positive(), "",
                 "every applied load is met at its DOF to this fraction of the largest value it takes in its step (docs/theory.md, \"Solver\")",
                 "tighten when a quoted load must be met closer than 0.1 %"),
      integer_key("max_iterations", &SolverOptions::max_iterations, 1, 1000,
                  "Newton corrections of an attempt before it is cut back (with contact, counted from the last contact-state change)",
                  "more `increments` in the step is usually cheaper"),
      integer_key("max_cutbacks", &SolverOptions::max_cutbacks, 0, 30, "halvings of an increment in a row before the step stops",
                  "raise when a run stops after cut-backs at a load the strand can carry"),
      integer_key("line_search_cuts", &SolverOptions::line_search_cuts, 0, 20,
                  "halvings of a Newton correction that raises the residual, from the second correction of an attempt on; 0: full "
                  "steps, and 4 from a cut-back until the increments are back at their nominal size (docs/theory.md)",
                  "4 for a case whose increments keep failing at their first attempt (increments below their nominal size search anyway)"),
      choice_key("linear_solver", &SolverOptions::linear_solver,
                 {{"mumps_single", std::string("mumps_single")}, {"mumps", std::string("mumps")}, {"umfpack", std::string("umfpack")}},
                 "`mumps_single`: single-precision MUMPS factors precondition flexible GMRES on the double-precision tangent, to "
                 "`krylov_tolerance` within `refinement_iterations`, and a tangent they cannot refine is factored in double "
                 "(`double_precision_fallbacks` in `summary.json`); `mumps`: double-precision factors, direct solves. METIS ordering "
                 "from libmetis for both, read back into `summary.json` (docs/performance.md)",
                 "`mumps` to rule out single precision when comparing runs; `umfpack` where MUMPS is not installed"),
      integer_key("refinement_iterations", &SolverOptions::refinement_iterations, 1, 200,
                  "GMRES iterations allowed to refine a solve with fresh single-precision factors", "never for results; performance studies only"),
      integer_key("krylov_iterations", &SolverOptions::krylov_iterations, 0, 200,
                  "GMRES iterations on the current tangent preconditioned by the last factorization before refactoring (0: factor every "
                  "Newton iteration)",
                  "0 for byte-identical resumes (every tangent factored afresh)"),
      number_key("krylov_tolerance", &SolverOptions::krylov_tolerance, NumberRange::below(1), "",
                 "relative residual of those linear solves (Newton converges as with a direct solve)", "never for results"),
      number_key("newton_forcing", &SolverOptions::newton_forcing, NumberRange::closed(0, 1), "",
                 "inexact Newton: a correction's linear solve stops at a relative residual of newton_forcing × tolerance / current "
                 "relative residual, between `krylov_tolerance` and 0.1, so that iterates near convergence are confirmed with older "
                 "factors (0: every solve to `krylov_tolerance`, and resumed runs match to the last digit; docs/theory.md)",
                 "0 for runs that must repeat to the last digit after a resume"),
      boolean_key("extrapolate", &SolverOptions::extrapolate,
                  "start each increment from the last increment's motion, scaled: in steps that impose a motion (strain, end rotation, "
                  "displacement) and in steps of applied loads alone without `solver.stabilization`, within a step, and across steps "
                  "that go on loading the same way (not across reversals); such a predictor is accepted only after one correction (or "
                  "if its residual is below 1e-3 of the tolerance)",
                  "false if increments after a turn of the loading keep failing at their first attempt"),
      number_key("stabilization", &SolverOptions::stabilization, NumberRange::half_open(0, 1), "fraction of the wires' elastic stiffness",
                 "viscous stabilization: damping of the motion since the last converged state (0: off; docs/theory.md); summary.json "
                 "reports the energy it dissipated against the work done",
                 "the automatic stabilization below switches it on where a step cannot go on; set it to study a stabilized run"),
      boolean_key("stabilization_ramp_off", &SolverOptions::stabilization_ramp_off,
                  "the factor falls linearly to zero over each step; false: constant",
                  "false only with `stabilization` on elastoplastic strands whose soft modes last to the step's end"),
      boolean_key("automatic_stabilization", &SolverOptions::automatic_stabilization,
                  "when an increment cannot converge after its cut-backs, viscous (0.01) and contact (1e-4) stabilization and line "
                  "search switch on for the rest of its step, which goes on from a quarter of its nominal increment (docs/theory.md, "
                  "\"Automatic stabilization\")",
                  "false to see where a case stops without it"),
      integer_key("threads", &SolverOptions::threads, 0, kMaxThreadsAsked,
                  "OpenMP threads (0: default); `-t` on the command line overrides; a count above the machine's processors is capped "
                  "there with a warning; `summary.json` records the count used",
                  "`-t` on the command line does the same"),
  };
  return table;
}

void parse_solver_options(const YamlReader& reader, const YAML::Node& node, SolverOptions& options) {
  static const std::vector<const char*> names = key_names(solver_key_table());
  reader.check_keys(node, "solver", names);
  read_setting_keys(reader, node, "solver", solver_key_table(), options);
}

nlohmann::json resolved_solver_options(const SolverOptions& options) { return resolved_setting_keys(solver_key_table(), options); }

}  // namespace strandfem
