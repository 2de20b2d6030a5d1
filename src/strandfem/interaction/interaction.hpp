// An interaction between wires beside the beam elements (wire contact now; clamps, loading saddles later):
// one lifecycle that the Newton loop drives without knowing what the interaction is.
#pragma once
#include <array>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "strandfem/beam/beam_element.hpp"
#include "strandfem/mesh/mesh.hpp"

namespace strandfem {

// Forces and moments on the six nodes of two 3-node elements (6 per node) and their derivative with
// respect to the nodes' (displacement, spin) increments.
using PairVector = Eigen::Matrix<double, 36, 1>;
using PairMatrix = Eigen::Matrix<double, 36, 36>;

// One evaluated contribution: internal nodal forces of two elements' nodes (a0, a1, a2, b0, b1, b2).
struct PairContribution {
  std::array<int, 6> nodes{};
  const PairVector* force = nullptr;
  const PairMatrix* tangent = nullptr;   // valid when evaluated with the tangent
};

class Interaction {
 public:
  virtual ~Interaction() = default;
  // Mesh element pairs whose nodes it may couple (the tangent's sparsity pattern).
  virtual const std::vector<std::pair<int, int>>& element_pairs() const = 0;
  // Start of an increment from the last converged state. loading_continues: the loads change the way they did in
  // the last converged increment (false at a step that reverses or changes them, e.g. V back after V out).
  virtual void begin_increment(bool loading_continues) = 0;
  // Evaluates every contribution at `state` from the converged history (writes no history).
  virtual void evaluate(const Mesh& mesh, const std::vector<NodeState>& state, bool with_tangent) = 0;
  // The contributions of the last evaluation (only the active ones).
  virtual void contributions(const Mesh& mesh, std::vector<PairContribution>& out) const = 0;
  // Step control of a Newton correction. begin_correction: the last evaluation is the iterate a correction starts
  // from; admissible_fraction, once the full correction has been evaluated: the largest fraction of it, in (0, 1],
  // that keeps within what the iterate's tangent knew (1: no limit).
  virtual void begin_correction() {}
  virtual double admissible_fraction() const { return 1.0; }
  // After each accepted Newton iterate (e.g. points that closed become active).
  virtual void accept_iterate(const Mesh& mesh) = 0;
  // After accept_iterate: true once when element_pairs() gained pairs (an interaction outside the pattern
  // became active); the solver rebuilds the pattern before the next tangent.
  virtual bool element_pairs_grew() = 0;
  // Once Newton has converged for the current state logic: how many states must change (0: accept).
  virtual int changes_at_convergence() = 0;
  // Once no state changes: an augmentation round (contact: the stick takes over its elastic slip); returns how many
  // values changed (0: accept). Newton then corrects at least once before it may accept again.
  virtual int augment_at_convergence() { return 0; }
  // Augmentation is tried, not required: a round keeps the converged working state it changed, and the solver returns
  // to it (and accepts) when Newton fails after the round.
  virtual void return_to_converged_round() {}
  // Converged increment at `state`: writes the history; true when element_pairs() changed.
  virtual bool commit(const Mesh& mesh, const std::vector<NodeState>& state) = 0;
  // Energy the last commit took out of the interaction's stabilization (N mm; 0 without one): reported beside the
  // viscous stabilization's, which Abaqus asks to keep small against the work done.
  virtual double commit_stabilization_energy() const { return 0.0; }
  // Sets the interaction's own stabilization (contact: the tangential spring, a fraction of the normal penalty),
  // restarted from `state`, the converged one: the solver's recovery aid switches it on and off between increments.
  virtual void set_stabilization(double /*fraction*/, const Mesh& /*mesh*/, const std::vector<NodeState>& /*state*/) {}
  // Rejected increment (cut-back): the next begin_increment starts again from the converged history.
  virtual void revert() = 0;
  // Checkpoints: writes the converged state (history, bookkeeping); restore_state reads it back in place of the
  // initial one and evaluates at `state`, the checkpoint's converged nodal state.
  virtual void save_state(ArchiveWriter& out) const = 0;
  virtual void restore_state(ArchiveReader& in, const Mesh& mesh, const std::vector<NodeState>& state) = 0;
};

}  // namespace strandfem
