#include "strandfem/solver/assembler.hpp"

#include <algorithm>

#include <omp.h>

#include "strandfem/constraints/rigid_tie.hpp"

namespace strandfem {

Assembler::Assembler(const Model& model, const ModelState& model_state, const DofMap& dofs) : dofs_(dofs) {
  const int n = dofs.equation_count;
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
  // Equations are numbered node by node: a node's free DOFs are one run, from its first equation on.
  std::vector<int> first_equation(node_count, -1), free_count(node_count, 0);
  for (int node = 0; node < node_count; ++node)
    for (int e : dofs.equation[node])
      if (e >= 0) {
        if (free_count[node]++ == 0) first_equation[node] = e;
      }
  pattern_.size = n;
  pattern_.column_start.assign(n + 1, 0);
  node_column_start_.assign(node_count + 1, 0);
  for (int node = 0; node < node_count; ++node) {
    auto& rows = row_nodes[node];
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    // Every column of this node holds the same rows: a row node's place in them is one number per node pair.
    int offset = 0;
    for (int row_node : rows) {
      if (free_count[row_node] == 0) continue;
      node_rows_.push_back(row_node);
      node_row_base_.push_back(offset - first_equation[row_node]);
      offset += free_count[row_node];
    }
    node_column_start_[node + 1] = static_cast<int>(node_rows_.size());
    for (int j = 0; j < 6; ++j) {
      const int col = dofs.equation[node][j];
      if (col < 0) continue;
      for (int k = node_column_start_[node]; k < node_column_start_[node + 1]; ++k)
        for (int i = 0; i < free_count[node_rows_[k]]; ++i) pattern_.row_index.push_back(first_equation[node_rows_[k]] + i);
      pattern_.column_start[col + 1] = static_cast<int>(pattern_.row_index.size());
    }
  }
  // Nodes couple as wholes: a node's free DOFs are one block of the orderings' graph.
  for (int node = 0; node < node_count; ++node)
    if (free_count[node] > 0) pattern_.block_start.push_back(first_equation[node]);
  pattern_.block_start.push_back(n);
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
}

int Assembler::block_base(int row_node, int column_node) const {
  const auto begin = node_rows_.begin() + node_column_start_[column_node];
  const auto end = node_rows_.begin() + node_column_start_[column_node + 1];
  const auto it = std::lower_bound(begin, end, row_node);
  return (it != end && *it == row_node) ? node_row_base_[it - node_rows_.begin()] : kNoBlock;
}

template <int Nodes>
void Assembler::scatter(const Model& model, const std::vector<NodeState>& state, const std::array<int, Nodes>& nodes,
                        const Eigen::Matrix<double, 6 * Nodes, 1>& force, const Eigen::Matrix<double, 6 * Nodes, 6 * Nodes>* tangent,
                        const NodeRange& owned, std::vector<double>& nodal_forces, std::vector<double>& slave_forces,
                        std::vector<double>* values) {
  constexpr int size = 6 * Nodes;
  std::array<int, Nodes> masters;
  bool any_tied = false, any_owned = false;
  for (int a = 0; a < Nodes; ++a) {
    masters[a] = dofs_.master_of(model, nodes[a]);
    any_tied = any_tied || masters[a] != nodes[a];
    any_owned = any_owned || owned.contains(masters[a]);
  }
  if (!any_owned) return;
  const Eigen::Matrix<double, size, 1>* r = &force;
  const Eigen::Matrix<double, size, size>* K = tangent;
  Eigen::Matrix<double, size, 1> moved_force;
  Eigen::Matrix<double, size, size> moved_tangent;
  if (any_tied) {
    // Move tied nodes' contributions to their masters, block by block: r_m = T^T r_s, K_ab = T_a^T K_ab T_b.
    std::array<Mat6, Nodes> transform;
    moved_force = force;
    for (int a = 0; a < Nodes; ++a) {
      if (masters[a] == nodes[a]) continue;
      if (owned.contains(masters[a]))
        for (int c = 0; c < 6; ++c) slave_forces[6 * nodes[a] + c] += force[6 * a + c];
      transform[a] = tie_transform(state[nodes[a]].position - state[masters[a]].position);
      moved_force.template segment<6>(6 * a) = transform[a].transpose() * force.template segment<6>(6 * a);
    }
    r = &moved_force;
    if (tangent) {
      moved_tangent = *tangent;
      for (int a = 0; a < Nodes; ++a) {
        if (masters[a] == nodes[a]) continue;
        for (int b = 0; b < Nodes; ++b) {
          const Mat6 rows_moved = transform[a].transpose() * moved_tangent.template block<6, 6>(6 * a, 6 * b);
          moved_tangent.template block<6, 6>(6 * a, 6 * b) = rows_moved;
        }
      }
      for (int b = 0; b < Nodes; ++b) {
        if (masters[b] == nodes[b]) continue;
        for (int a = 0; a < Nodes; ++a) {
          const Mat6 columns_moved = moved_tangent.template block<6, 6>(6 * a, 6 * b) * transform[b];
          moved_tangent.template block<6, 6>(6 * a, 6 * b) = columns_moved;
        }
      }
      K = &moved_tangent;
    }
  }
  for (int a = 0; a < Nodes; ++a)
    if (owned.contains(masters[a]))
      for (int c = 0; c < 6; ++c) nodal_forces[6 * masters[a] + c] += (*r)[6 * a + c];
  if (!K) return;
  const std::vector<int>& column_start = pattern_.column_start;
  for (int b = 0; b < Nodes; ++b) {
    if (!owned.contains(masters[b])) continue;
    for (int a = 0; a < Nodes; ++a) {
      // Outside the pattern (an interaction that entered within the iteration): the pattern grows at acceptance.
      const int base = block_base(masters[a], masters[b]);
      if (base == kNoBlock) continue;
      const auto &rows = dofs_.equation[masters[a]], &columns = dofs_.equation[masters[b]];
      for (int j = 0; j < 6; ++j) {
        if (columns[j] < 0) continue;
        double* column = values->data() + column_start[columns[j]] + base;
        for (int c = 0; c < 6; ++c)
          if (rows[c] >= 0) column[rows[c]] += (*K)(6 * a + c, 6 * b + j);
      }
    }
  }
}

Assembler::NodeRange Assembler::owned_nodes(int thread, int threads) const {
  // Equal shares of the pattern's node blocks, a fair measure of the scatter's work per column node.
  const int node_count = static_cast<int>(node_column_start_.size()) - 1;
  auto boundary = [&](int t) {
    if (t >= threads) return node_count;
    const std::int64_t share = static_cast<std::int64_t>(node_column_start_.back()) * t / threads;
    return static_cast<int>(std::lower_bound(node_column_start_.begin(), node_column_start_.end(), share) -
                            node_column_start_.begin());
  };
  return {boundary(thread), boundary(thread + 1)};
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
  contributions_.clear();
  for (const Interaction* interaction : model_state.interactions()) interaction->contributions(model.mesh, contributions_);
  // Each thread owns a range of nodes (their columns and forces) and walks every element and contribution in
  // order: each value receives its terms in the same order whatever the thread count (deterministic sums).
#pragma omp parallel
  {
    const NodeRange owned = owned_nodes(omp_get_thread_num(), omp_get_num_threads());
    for (int k = 0; k < element_count; ++k)
      scatter<3>(model, state, model.elements[k].nodes(), outputs_[k].residual,
                 with_tangent ? &outputs_[k].tangent : nullptr, owned, nodal_forces, slave_forces, values);
    for (const PairContribution& c : contributions_)
      scatter<6>(model, state, c.nodes, *c.force, with_tangent ? c.tangent : nullptr, owned, nodal_forces, slave_forces,
                 values);
  }
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
