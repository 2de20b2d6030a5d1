// Global assembly of beam and contact contributions into nodal forces and a CSC tangent.
#pragma once
#include <limits>
#include <vector>

#include "strandfem/solver/linear_solver.hpp"
#include "strandfem/solver/model.hpp"
#include "strandfem/solver/model_state.hpp"
#include "strandfem/solver/stabilization.hpp"

namespace strandfem {

// Builds the tangent's sparsity pattern once per DOF map and scatters element contributions into it by node
// blocks (no triplets inside Newton). Element evaluation runs in parallel; so does the scatter, each thread
// adding the columns and forces of its own nodes in element and contribution order, so that the sums, and
// hence the results, do not depend on the thread count.
class Assembler {
 public:
  // The pattern couples each element's nodes and, for every pair of the state's interactions' element_pairs(),
  // the nodes of the two elements.
  Assembler(const Model& model, const ModelState& model_state, const DofMap& dofs);

  const SparsePattern& pattern() const { return pattern_; }

  // Internal nodal forces (beam elements and contact points) in master space (6 per node: force, moment about the node; tied slaves'
  // forces moved to their masters) and, when values != nullptr, the tangent on free DOFs. With damping, each
  // element also carries the viscous stabilization's force.
  // Element and contact histories are read from and trial values written to `model_state`.
  void assemble(const Model& model, ModelState& model_state, const std::vector<NodeState>& state,
                std::vector<double>& nodal_forces, std::vector<double>* values, const ElementDamping& damping = {});

 private:
  // Master nodes [first, last): a thread's share of the scatter.
  struct NodeRange {
    int first = 0, last = 0;
    bool contains(int node) const { return node >= first && node < last; }
  };
  NodeRange owned_nodes(int thread, int threads) const;
  // Adds a block over `nodes` (6 DOFs each) to the global forces and tangent, moving tied slaves' rows and
  // columns to their masters; tied slaves' forces are also collected for the lever-arm term. Only the forces
  // of `owned` master nodes and the tangent's columns of `owned` nodes are written.
  template <int Nodes>
  void scatter(const Model& model, const std::vector<NodeState>& state, const std::array<int, Nodes>& nodes,
               const Eigen::Matrix<double, 6 * Nodes, 1>& force, const Eigen::Matrix<double, 6 * Nodes, 6 * Nodes>* tangent,
               const NodeRange& owned, std::vector<double>& nodal_forces, std::vector<double>& slave_forces,
               std::vector<double>* values);
  // Where the block (row node, column node) sits in the tangent: the value of (row, col) is at
  // column_start[col] + base + row, for every free row of the row node and column of the column node;
  // kNoBlock when the two nodes are not coupled in the pattern.
  int block_base(int row_node, int column_node) const;
  static constexpr int kNoBlock = std::numeric_limits<int>::min();

  const DofMap& dofs_;
  SparsePattern pattern_;
  // The pattern by nodes: for each column node, its row nodes (ascending, free DOFs only) and their block bases.
  std::vector<int> node_column_start_;
  std::vector<int> node_rows_;
  std::vector<int> node_row_base_;
  std::vector<std::array<int, 9>> tie_slots_;    // master rotation-rotation slots per tie
  std::vector<BeamElement::Output> outputs_;
  std::vector<PairContribution> contributions_;
};

}  // namespace strandfem
