// Global assembly of beam and contact contributions into nodal forces and a CSC tangent.
#pragma once
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "strandfem/solver/linear_solver.hpp"
#include "strandfem/solver/model.hpp"
#include "strandfem/solver/model_state.hpp"
#include "strandfem/solver/stabilization.hpp"

namespace strandfem {

// Builds the tangent's sparsity pattern once per DOF map and scatters element contributions into value
// slots (no triplets inside Newton). Element evaluation runs in parallel; the scatter is sequential in
// element order so the sums, and hence the results, do not depend on the thread count.
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
  void add_interactions(const Model& model, const ModelState& model_state, const std::vector<NodeState>& state,
                        std::vector<double>& nodal_forces, std::vector<double>& slave_forces, std::vector<double>* values);
  // Adds a block over `nodes` (6 DOFs each) to the global forces and tangent, moving tied slaves' rows and
  // columns to their masters; tied slaves' forces are also collected for the lever-arm term.
  template <int Nodes>
  void scatter(const Model& model, const std::vector<NodeState>& state, const std::array<int, Nodes>& nodes,
               Eigen::Matrix<double, 6 * Nodes, 1> r, Eigen::Matrix<double, 6 * Nodes, 6 * Nodes>* K,
               std::vector<double>& nodal_forces, std::vector<double>& slave_forces, std::vector<double>* values,
               const int* slots);
  const DofMap& dofs_;
  SparsePattern pattern_;
  std::vector<int> element_slots_;               // 324 per element, -1 where row or column is constrained
  std::vector<std::array<int, 9>> tie_slots_;    // master rotation-rotation slots per tie
  // Contact element pairs whose six nodes are all untied: 1296 slots each (36 x 36, nodes a0..b2),
  // found by (slave element, master element); other pairs go through the general scatter.
  std::unordered_map<std::int64_t, int> contact_pair_;
  std::vector<int> contact_slots_;
  std::vector<BeamElement::Output> outputs_;
  std::vector<PairContribution> contributions_;
};

}  // namespace strandfem
