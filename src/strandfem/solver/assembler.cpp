#include "strandfem/solver/assembler.hpp"

#include <algorithm>

#include "strandfem/constraints/rigid_tie.hpp"

namespace strandfem {

Assembler::Assembler(const Model& model, const ModelState& model_state, const DofMap& dofs) : dofs_(dofs) {
  const int n = dofs.equation_count;
  auto effective_equation = [&](int node, int component) {
    return dofs.equation[dofs.master_of(model, node)][component];
  };
  // Couplings are node to node (a tied slave's DOFs act on all 6 of its master's: the lever arm couples rotation
  // into translation), and equations are numbered node by node, so the pattern is built from the nodes' neighbour
  // lists: 36 times fewer entries to sort than scalar couplings (a rebuild follows every change of contact pairs).
  const int node_count = static_cast<int>(dofs.equation.size());
  std::vector<std::vector<int>> row_nodes(node_count);  // column node -> the nodes it couples with
  auto couple = [&](const std::array<int, 3>& first, const std::array<int, 3>& second) {
    for (int a : first)
      for (int b : second) row_nodes[dofs.master_of(model, b)].push_back(dofs.master_of(model, a));
  };
  for (const MeshElement& e : model.mesh.elements) couple(e.nodes, e.nodes);
  for (const Interaction* interaction : model_state.interactions())
    for (const auto& [e, f] : interaction->element_pairs()) {
      const auto &a = model.mesh.elements[e].nodes, &b = model.mesh.elements[f].nodes;
      couple(a, b);
      couple(b, a);
    }
  pattern_.size = n;
  pattern_.column_start.assign(n + 1, 0);
  for (int node = 0; node < node_count; ++node) {
    auto& rows = row_nodes[node];
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    for (int j = 0; j < 6; ++j) {
      const int col = dofs.equation[node][j];
      if (col < 0) continue;
      for (int row_node : rows)
        for (int i = 0; i < 6; ++i)
          if (dofs.equation[row_node][i] >= 0) pattern_.row_index.push_back(dofs.equation[row_node][i]);
      pattern_.column_start[col + 1] = static_cast<int>(pattern_.row_index.size());
    }
  }
  // Nodes couple as wholes, and equations are numbered node by node: a node's free DOFs are one block.
  for (std::size_t node = 0; node < dofs.equation.size(); ++node) {
    const auto& eq = dofs.equation[node];
    const auto first = std::find_if(eq.begin(), eq.end(), [](int e) { return e >= 0; });
    if (first != eq.end()) pattern_.block_start.push_back(*first);
  }
  pattern_.block_start.push_back(n);
  element_slots_.assign(model.mesh.elements.size() * 324, -1);
  for (std::size_t k = 0; k < model.mesh.elements.size(); ++k) {
    const MeshElement& e = model.mesh.elements[k];
    for (int a = 0; a < 18; ++a)
      for (int b = 0; b < 18; ++b) {
        const int row = effective_equation(e.nodes[a / 6], a % 6), col = effective_equation(e.nodes[b / 6], b % 6);
        if (row >= 0 && col >= 0) element_slots_[k * 324 + a * 18 + b] = pattern_.find(row, col);
      }
  }
  for (const RigidTie& tie : model.ties) {
    std::array<int, 9> slots;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const int row = dofs.equation[tie.master][3 + i], col = dofs.equation[tie.master][3 + j];
        slots[3 * i + j] = (row >= 0 && col >= 0) ? pattern_.find(row, col) : -1;
      }
    tie_slots_.push_back(slots);
  }
  outputs_.resize(model.mesh.elements.size());
  const std::int64_t element_count = static_cast<std::int64_t>(model.mesh.elements.size());
  std::vector<std::pair<int, int>> pairs;
  for (const Interaction* interaction : model_state.interactions())
    pairs.insert(pairs.end(), interaction->element_pairs().begin(), interaction->element_pairs().end());
  for (const auto& [e, f] : pairs) {
    const auto &a = model.mesh.elements[e].nodes, &b = model.mesh.elements[f].nodes;
    const std::array<int, 6> nodes = {a[0], a[1], a[2], b[0], b[1], b[2]};
    if (std::any_of(nodes.begin(), nodes.end(), [&](int n) { return dofs.tie_of[n] >= 0; })) continue;
    contact_pair_[e * element_count + f] = static_cast<int>(contact_slots_.size() / 1296);
    const std::size_t base = contact_slots_.size();
    contact_slots_.resize(base + 1296, -1);
    for (int j = 0; j < 36; ++j) {
      const int col = dofs.equation[nodes[j / 6]][j % 6];
      if (col < 0) continue;
      for (int a = 0; a < 6; ++a) {
        // A node's rows follow each other in a column: one search per node, then a step per DOF.
        int slot = -1;
        for (int c = 0; c < 6; ++c) {
          const int row = dofs.equation[nodes[a]][c];
          if (row < 0) continue;
          const bool next_in_column = slot >= 0 && slot + 1 < pattern_.column_start[col + 1] && pattern_.row_index[slot + 1] == row;
          slot = next_in_column ? slot + 1 : pattern_.find(row, col);
          contact_slots_[base + (6 * a + c) * 36 + j] = slot;
        }
      }
    }
  }
}

template <int Nodes>
void Assembler::scatter(const Model& model, const std::vector<NodeState>& state, const std::array<int, Nodes>& nodes,
                        Eigen::Matrix<double, 6 * Nodes, 1> r, Eigen::Matrix<double, 6 * Nodes, 6 * Nodes>* K,
                        std::vector<double>& nodal_forces, std::vector<double>& slave_forces,
                        std::vector<double>* values, const int* slots) {
  constexpr int size = 6 * Nodes;
  // Move tied nodes' contributions to their masters: r_m = T^T r_s, K_ab = T_a^T K_ab T_b.
  Eigen::Matrix<double, size, size> transform = Eigen::Matrix<double, size, size>::Identity();
  bool any_tied = false;
  for (int a = 0; a < Nodes; ++a) {
    const int tie = dofs_.tie_of[nodes[a]];
    if (tie < 0) continue;
    any_tied = true;
    for (int c = 0; c < 6; ++c) slave_forces[6 * nodes[a] + c] += r[6 * a + c];
    const int master = model.ties[tie].master;
    transform.template block<6, 6>(6 * a, 6 * a) = tie_transform(state[nodes[a]].position - state[master].position);
  }
  if (any_tied) {
    r = transform.transpose() * r;
    if (K) *K = transform.transpose() * (*K) * transform;
  }
  for (int a = 0; a < Nodes; ++a) {
    const int target = dofs_.master_of(model, nodes[a]);
    for (int c = 0; c < 6; ++c) nodal_forces[6 * target + c] += r[6 * a + c];
  }
  if (!K) return;
  for (int a = 0; a < size; ++a) {
    const int row = dofs_.equation[dofs_.master_of(model, nodes[a / 6])][a % 6];
    if (!slots && row < 0) continue;
    for (int b = 0; b < size; ++b) {
      int slot;
      if (slots) {
        slot = slots[a * size + b];
      } else {
        const int col = dofs_.equation[dofs_.master_of(model, nodes[b / 6])][b % 6];
        if (col < 0 || (*K)(a, b) == 0.0) continue;
        slot = pattern_.find(row, col);
      }
      if (slot >= 0) (*values)[slot] += (*K)(a, b);
    }
  }
}

// Interaction contributions act on their six nodes; sequential, in order (deterministic).
void Assembler::add_interactions(const Model& model, const ModelState& model_state, const std::vector<NodeState>& state,
                                 std::vector<double>& nodal_forces, std::vector<double>& slave_forces,
                                 std::vector<double>* values) {
  const bool with_tangent = values != nullptr;
  const std::int64_t element_count = static_cast<std::int64_t>(model.mesh.elements.size());
  contributions_.clear();
  for (const Interaction* interaction : model_state.interactions()) interaction->contributions(model.mesh, contributions_);
  for (const PairContribution& c : contributions_) {
    const auto cached = contact_pair_.find(c.elements.first * element_count + c.elements.second);
    if (cached != contact_pair_.end()) {
      for (int a = 0; a < 6; ++a)
        for (int k = 0; k < 6; ++k) nodal_forces[6 * c.nodes[a] + k] += (*c.force)[6 * a + k];
      if (with_tangent) {
        const int* slots = &contact_slots_[static_cast<std::size_t>(cached->second) * 1296];
        const PairMatrix& K = *c.tangent;
        for (int a = 0; a < 36; ++a)
          for (int b = 0; b < 36; ++b)
            if (slots[36 * a + b] >= 0) (*values)[slots[36 * a + b]] += K(a, b);
      }
      continue;
    }
    PairMatrix K = with_tangent ? *c.tangent : PairMatrix::Zero();
    scatter<6>(model, state, c.nodes, *c.force, with_tangent ? &K : nullptr, nodal_forces, slave_forces, values, nullptr);
  }
}

void Assembler::assemble(const Model& model, ModelState& model_state, const std::vector<NodeState>& state,
                         std::vector<double>& nodal_forces, std::vector<double>* values, const ElementDamping& damping) {
  const bool damped = damping.stabilization && damping.factor > 0;
  const bool with_tangent = values != nullptr;
  const int element_count = static_cast<int>(model.elements.size());
#pragma omp parallel for schedule(dynamic, 8)
  for (int k = 0; k < element_count; ++k) {
    const BeamElement& element = model.elements[k];
    std::array<NodeState, 3> local;
    for (int i = 0; i < 3; ++i) local[i] = state[element.nodes()[i]];
    element.evaluate(local, model_state.elements[k], with_tangent, outputs_[k]);
    if (damped) {
      std::array<NodeState, 3> converged;
      for (int i = 0; i < 3; ++i) converged[i] = (*damping.converged)[element.nodes()[i]];
      damping.stabilization->add(k, local, converged, damping.factor, outputs_[k].residual,
                                 with_tangent ? &outputs_[k].tangent : nullptr);
    }
  }
  for (Interaction* interaction : model_state.interactions()) interaction->evaluate(model.mesh, state, with_tangent);
  const std::size_t node_count = model.mesh.nodes.size();
  nodal_forces.assign(6 * node_count, 0.0);
  std::vector<double> slave_forces(6 * node_count, 0.0);
  if (with_tangent) values->assign(pattern_.nonzeros(), 0.0);
  for (int k = 0; k < element_count; ++k) {
    ElementMatrix K;
    if (with_tangent) K = outputs_[k].tangent;
    scatter<3>(model, state, model.elements[k].nodes(), outputs_[k].residual, with_tangent ? &K : nullptr, nodal_forces,
               slave_forces, values, &element_slots_[static_cast<std::size_t>(k) * 324]);
  }
  add_interactions(model, model_state, state, nodal_forces, slave_forces, values);
  if (!with_tangent) return;
  // Rotation of the lever arm: d(arm x f)/dtheta_m = f^ arm^ (f: the slave's force, held fixed).
  for (std::size_t t = 0; t < model.ties.size(); ++t) {
    const RigidTie& tie = model.ties[t];
    const Vec3 f(slave_forces[6 * tie.slave], slave_forces[6 * tie.slave + 1], slave_forces[6 * tie.slave + 2]);
    const Mat3 geometric = skew(f) * skew(state[tie.slave].position - state[tie.master].position);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (tie_slots_[t][3 * i + j] >= 0) (*values)[tie_slots_[t][3 * i + j]] += geometric(i, j);
  }
}

}  // namespace strandfem
