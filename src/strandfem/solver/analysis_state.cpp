// Checkpoints of a static analysis: its converged state and where it stands in the load protocol.
#include "strandfem/core/archive.hpp"
#include "strandfem/solver/static_analysis.hpp"

namespace strandfem {
namespace {

// 2: adds the energy balance and the applied loads of the converged state.
// 3: the statistics add the residual and commit times.
// 4: the statistics add the corrections cut by the step control (limited_corrections). Only this version is read:
//    the statistics of the earlier ones have another layout.
// 5: adds the load norms the step's convergence test measures against, and the statistics the searched recoveries.
// 6: adds whether the automatic stabilization is on, and the statistics the steps it switched on in.
constexpr int kStateVersion = 7;

void save_nodes(ArchiveWriter& out, const std::vector<NodeState>& nodes) {
  out.value(static_cast<std::uint64_t>(nodes.size()));
  for (const NodeState& n : nodes) {
    out.vec3(n.position);
    out.quaternion(n.rotation);
  }
}

void load_nodes(ArchiveReader& in, std::vector<NodeState>& nodes) {
  in.expect(static_cast<std::uint64_t>(nodes.size()), "the node count");
  for (NodeState& n : nodes) {
    n.position = in.vec3();
    n.rotation = in.quaternion();
  }
}

}  // namespace

void StaticAnalysis::save_state(ArchiveWriter& out) const {
  out.section("analysis");
  out.value(kStateVersion);
  out.value(static_cast<std::uint64_t>(model_.elements.size()));
  out.value(dofs_.equation_count);
  const Progress& p = progress_;
  const IncrementController::Sizes& c = p.control.sizes();
  out.value(p.ramp);
  out.value(p.in_step);
  out.value(std::array<double, 5>{c.fraction, c.size, c.largest_size, c.last_size, p.previous_last_size});
  out.value(std::array<int, 2>{c.easy_at_cap, c.converged_increments});
  out.value(c.extrapolation_failed);
  out.value(c.stabilized);
  out.map(p.totals);
  out.map(p.previous_change);
  out.value(convergence_.step_reference());
  save_nodes(out, committed_state_);
  save_nodes(out, previous_committed_state_.empty() ? committed_state_ : previous_committed_state_);
  out.map(committed_motion_);
  out.value(statistics_);
  out.value(energies_);
  out.vector(committed_external_);
  out.section("elements");
  for (const BeamElementState& e : model_state_.elements) e.save_history(out);
  for (const Interaction* interaction : model_state_.interactions()) interaction->save_state(out);
  out.section("end");
}

void StaticAnalysis::restore_state(ArchiveReader& in) {
  in.section("analysis");
  const int version = in.value<int>();
  if (version != kStateVersion) throw ArchiveError("checkpoint was written by another version of StrandFEM");
  in.expect(static_cast<std::uint64_t>(model_.elements.size()), "the element count");
  in.expect(dofs_.equation_count, "the equation count");
  Progress p = progress_;
  IncrementController::Sizes c;
  in.value(p.ramp);
  in.value(p.in_step);
  const auto sizes = in.value<std::array<double, 5>>();
  c.fraction = sizes[0], c.size = sizes[1], c.largest_size = sizes[2], c.last_size = sizes[3];
  p.previous_last_size = sizes[4];
  const auto counts = in.value<std::array<int, 2>>();
  c.easy_at_cap = counts[0], c.converged_increments = counts[1];
  in.value(c.extrapolation_failed);
  in.value(c.stabilized);
  p.control.restore(c);
  in.map(p.totals);
  in.map(p.previous_change);
  const auto step_reference = in.value<LoadReference>();
  load_nodes(in, committed_state_);
  previous_committed_state_ = committed_state_;
  load_nodes(in, previous_committed_state_);
  in.map(committed_motion_);
  in.value(statistics_);
  in.value(energies_);
  in.vector(committed_external_);
  in.section("elements");
  for (BeamElementState& e : model_state_.elements) e.restore_history(in);
  for (Interaction* interaction : model_state_.interactions()) interaction->restore_state(in, model_.mesh, committed_state_);
  in.section("end");
  progress_ = p;
  convergence_.begin_step(step_reference);
  state_ = committed_state_;
  if (c.stabilized) set_automatic_stabilization(true);
  applied_motion_ = committed_motion_;
  build_pattern();  // the interactions' element pairs of the checkpoint (not a rebuild the run would count)
  assembler_->assemble(model_, model_state_, state_, internal_forces_, nullptr);
  committed_forces_ = internal_forces_;
}

}  // namespace strandfem
