#include "strandfem/solver/model.hpp"

#include <stdexcept>
#include <string>

namespace strandfem {

void SolverOptions::validate() const {
  auto positive = [](double v, const char* key) {
    if (!(v > 0)) throw std::invalid_argument(std::string("solver.") + key + " must be > 0, got " + std::to_string(v));
  };
  positive(force_tolerance, "force_tolerance");
  positive(moment_tolerance, "moment_tolerance");
  positive(displacement_tolerance, "displacement_tolerance");
  positive(load_tolerance, "load_tolerance");
  if (max_iterations < 1) throw std::invalid_argument("solver.max_iterations must be >= 1");
  if (line_search_cuts < 0 || line_search_cuts > 20) throw std::invalid_argument("solver.line_search_cuts must be in 0..20");
  if (krylov_iterations < 0 || krylov_iterations > 200) throw std::invalid_argument("solver.krylov_iterations must be in 0..200");
  if (refinement_iterations < 1 || refinement_iterations > 200)
    throw std::invalid_argument("solver.refinement_iterations must be in 1..200");
  if (!(krylov_tolerance > 0 && krylov_tolerance < 1)) throw std::invalid_argument("solver.krylov_tolerance must be in (0, 1)");
  if (!(newton_forcing >= 0 && newton_forcing <= 1))
    throw std::invalid_argument("solver.newton_forcing must be in [0, 1], got " + std::to_string(newton_forcing));
  if (!(stabilization >= 0 && stabilization < 1)) throw std::invalid_argument("solver.stabilization must be in [0, 1), got " + std::to_string(stabilization));
  if (max_cutbacks < 0) throw std::invalid_argument("solver.max_cutbacks must be >= 0");
  if (threads < 0) throw std::invalid_argument("solver.threads must be >= 0");
  if (linear_solver != "mumps" && linear_solver != "mumps_single" && linear_solver != "umfpack")
    throw std::invalid_argument("solver.linear_solver must be 'mumps', 'mumps_single' or 'umfpack', got '" + linear_solver + "'");
}

void Model::build_elements() {
  elements.clear();
  elements.reserve(mesh.elements.size());
  for (const MeshElement& e : mesh.elements) {
    std::array<NodeState, 3> reference;
    for (int i = 0; i < 3; ++i) reference[i] = mesh.nodes[e.nodes[i]].reference;
    elements.emplace_back(e.nodes, mesh.sections[e.section].get(), reference);
  }
}

DofMap build_dof_map(const Model& model) {
  const int n = static_cast<int>(model.mesh.nodes.size());
  DofMap map;
  map.tie_of.assign(n, -1);
  map.equation.assign(n, {-2, -2, -2, -2, -2, -2});  // -2: free, not yet numbered
  for (std::size_t t = 0; t < model.ties.size(); ++t) {
    const RigidTie& tie = model.ties[t];
    if (map.tie_of[tie.slave] >= 0) throw std::invalid_argument("node " + std::to_string(tie.slave) + " is tied twice");
    map.tie_of[tie.slave] = static_cast<int>(t);
  }
  for (const RigidTie& tie : model.ties)
    if (map.tie_of[tie.master] >= 0)
      throw std::invalid_argument("tie master node " + std::to_string(tie.master) + " is itself tied");
  auto constrain = [&](int node, int component, const char* what) {
    if (map.tie_of[node] >= 0)
      throw std::invalid_argument(std::string(what) + " on node " + std::to_string(node) +
                                  ", which is tied to an end plane: apply it to the core end node");
    map.equation[node][component] = -1;
  };
  for (const Support& s : model.supports)
    for (int c = 0; c < 6; ++c)
      if (s.fixed[c]) constrain(s.node, c, "support");
  for (const LoadStep& step : model.steps)
    for (const NodalAction& a : step.actions) {
      if (a.kind == NodalAction::kMotion) constrain(a.node, a.component, "imposed motion");
      else if (map.tie_of[a.node] >= 0)
        throw std::invalid_argument("load on node " + std::to_string(a.node) + ", which is tied to an end plane");
    }
  int next = 0;
  for (int node = 0; node < n; ++node)
    for (int c = 0; c < 6; ++c) {
      if (map.tie_of[node] >= 0) map.equation[node][c] = -1;
      else if (map.equation[node][c] == -2) map.equation[node][c] = next++;
    }
  map.equation_count = next;
  return map;
}

}  // namespace strandfem
