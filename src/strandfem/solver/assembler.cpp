#include "strandfem/solver/assembler.hpp"

#include <algorithm>

#include "strandfem/constraints/rigid_tie.hpp"

namespace strandfem {

Assembler::Assembler(const Model& model, const DofMap& dofs) : dofs_(dofs) {
  const int n = dofs.equation_count;
  std::vector<std::vector<int>> rows_of_column(n);
  auto effective_equation = [&](int node, int component) {
    return dofs.equation[dofs.master_of(model, node)][component];
  };
  // A tied slave's DOFs act on all 6 master DOFs (the lever arm couples rotation into translation).
  for (const MeshElement& e : model.mesh.elements)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        for (int i = 0; i < 6; ++i)
          for (int j = 0; j < 6; ++j) {
            const int row = effective_equation(e.nodes[a], i), col = effective_equation(e.nodes[b], j);
            if (row >= 0 && col >= 0) rows_of_column[col].push_back(row);
          }
  pattern_.size = n;
  pattern_.column_start.assign(n + 1, 0);
  for (int c = 0; c < n; ++c) {
    auto& rows = rows_of_column[c];
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    pattern_.column_start[c + 1] = pattern_.column_start[c] + static_cast<int>(rows.size());
    pattern_.row_index.insert(pattern_.row_index.end(), rows.begin(), rows.end());
  }
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
}

void Assembler::assemble(Model& model, const std::vector<NodeState>& state, std::vector<double>& nodal_forces,
                         std::vector<double>* values) {
  const bool with_tangent = values != nullptr;
  const int element_count = static_cast<int>(model.elements.size());
#pragma omp parallel for schedule(dynamic, 8)
  for (int k = 0; k < element_count; ++k) {
    BeamElement& element = model.elements[k];
    std::array<NodeState, 3> local;
    for (int i = 0; i < 3; ++i) local[i] = state[element.nodes()[i]];
    element.evaluate(local, with_tangent, outputs_[k]);
  }
  const std::size_t node_count = model.mesh.nodes.size();
  nodal_forces.assign(6 * node_count, 0.0);
  std::vector<double> slave_forces(6 * node_count, 0.0);
  if (with_tangent) values->assign(pattern_.nonzeros(), 0.0);
  for (int k = 0; k < element_count; ++k) {
    const auto& nodes = model.elements[k].nodes();
    ElementVector r = outputs_[k].residual;
    ElementMatrix K;
    if (with_tangent) K = outputs_[k].tangent;
    // Move tied nodes' contributions to their masters: r_m = T^T r_s, K_ab = T_a^T K_ab T_b.
    Eigen::Matrix<double, 18, 18> transform = Eigen::Matrix<double, 18, 18>::Identity();
    bool any_tied = false;
    for (int a = 0; a < 3; ++a) {
      const int tie = dofs_.tie_of[nodes[a]];
      if (tie < 0) continue;
      any_tied = true;
      for (int c = 0; c < 6; ++c) slave_forces[6 * nodes[a] + c] += r[6 * a + c];
      const int master = model.ties[tie].master;
      transform.block<6, 6>(6 * a, 6 * a) = tie_transform(state[nodes[a]].position - state[master].position);
    }
    if (any_tied) {
      r = transform.transpose() * r;
      if (with_tangent) K = transform.transpose() * K * transform;
    }
    for (int a = 0; a < 3; ++a) {
      const int target = dofs_.master_of(model, nodes[a]);
      for (int c = 0; c < 6; ++c) nodal_forces[6 * target + c] += r[6 * a + c];
    }
    if (with_tangent) {
      const int* slots = &element_slots_[static_cast<std::size_t>(k) * 324];
      for (int a = 0; a < 18; ++a)
        for (int b = 0; b < 18; ++b)
          if (slots[a * 18 + b] >= 0) (*values)[slots[a * 18 + b]] += K(a, b);
    }
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
