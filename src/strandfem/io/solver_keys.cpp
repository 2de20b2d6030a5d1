#include "strandfem/io/solver_keys.hpp"

#include "strandfem/io/case_keys.hpp"

#include <limits>

namespace strandfem {
namespace {
constexpr int kMaxThreadsAsked = std::numeric_limits<int>::max();  // the program caps it at the machine's count
}  // namespace

void parse_solver_options(const YamlReader& reader, const YAML::Node& node, SolverOptions& o) {
  reader.check_keys(node, "solver", allowed_keys("solver"));
  if (node["force_tolerance"]) o.force_tolerance = reader.positive(node["force_tolerance"], "solver.force_tolerance", "-");
  if (node["moment_tolerance"]) o.moment_tolerance = reader.positive(node["moment_tolerance"], "solver.moment_tolerance", "-");
  if (node["displacement_tolerance"]) o.displacement_tolerance = reader.positive(node["displacement_tolerance"], "solver.displacement_tolerance", "-");
  if (node["load_tolerance"]) o.load_tolerance = reader.positive(node["load_tolerance"], "solver.load_tolerance", "-");
  if (node["max_iterations"]) o.max_iterations = reader.integer(node["max_iterations"], "solver.max_iterations", 1, 1000);
  if (node["max_cutbacks"]) o.max_cutbacks = reader.integer(node["max_cutbacks"], "solver.max_cutbacks", 0, 30);
  if (node["line_search_cuts"]) o.line_search_cuts = reader.integer(node["line_search_cuts"], "solver.line_search_cuts", 0, 20);
  if (node["linear_solver"]) o.linear_solver = reader.choice(node["linear_solver"], "solver.linear_solver", {"mumps", "mumps_single", "umfpack"});
  if (node["threads"]) o.threads = reader.integer(node["threads"], "solver.threads", 0, kMaxThreadsAsked);
  if (node["krylov_iterations"]) o.krylov_iterations = reader.integer(node["krylov_iterations"], "solver.krylov_iterations", 0, 200);
  if (node["refinement_iterations"])
    o.refinement_iterations = reader.integer(node["refinement_iterations"], "solver.refinement_iterations", 1, 200);
  if (node["krylov_tolerance"]) o.krylov_tolerance = reader.positive(node["krylov_tolerance"], "solver.krylov_tolerance", "-");
  if (node["newton_forcing"]) o.newton_forcing = reader.number(node["newton_forcing"], "solver.newton_forcing");
  if (node["extrapolate"]) o.extrapolate = reader.boolean(node["extrapolate"], "solver.extrapolate");
  if (node["stabilization"]) {
    o.stabilization = reader.number(node["stabilization"], "solver.stabilization");
    if (!(o.stabilization >= 0 && o.stabilization < 1))
      reader.fail(node["stabilization"], "solver.stabilization", "expected a fraction of the wires' elastic stiffness in [0, 1)");
  }
  if (node["stabilization_ramp_off"])
    o.stabilization_ramp_off = reader.boolean(node["stabilization_ramp_off"], "solver.stabilization_ramp_off");
  if (node["automatic_stabilization"])
    o.automatic_stabilization = reader.boolean(node["automatic_stabilization"], "solver.automatic_stabilization");
}

nlohmann::json resolved_solver_options(const SolverOptions& o) {
  return {{"force_tolerance", o.force_tolerance},
          {"moment_tolerance", o.moment_tolerance},
          {"displacement_tolerance", o.displacement_tolerance},
          {"load_tolerance", o.load_tolerance},
          {"max_iterations", o.max_iterations},
          {"max_cutbacks", o.max_cutbacks},
          {"line_search_cuts", o.line_search_cuts},
          {"linear_solver", o.linear_solver},
          {"krylov_iterations", o.krylov_iterations},
          {"refinement_iterations", o.refinement_iterations},
          {"krylov_tolerance", o.krylov_tolerance},
          {"newton_forcing", o.newton_forcing},
          {"extrapolate", o.extrapolate},
          {"stabilization", o.stabilization},
          {"stabilization_ramp_off", o.stabilization_ramp_off},
          {"automatic_stabilization", o.automatic_stabilization},
          {"threads", o.threads}};
}

}  // namespace strandfem
