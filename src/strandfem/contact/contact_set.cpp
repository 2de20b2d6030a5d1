// A contact set's points at work: evaluated at an iterate, committed at convergence (stick, slip, release),
// and kept in the tangent's sparsity pattern. Finding the points is contact_set_detection.cpp.
#include "strandfem/contact/contact_set.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <stdexcept>

#include "strandfem/contact/wire_geometry.hpp"

namespace strandfem {

namespace {

using namespace wire_geometry;

// Stale element pairs (no point near closing) stay in the pattern until they exceed this share of the needed ones.
constexpr double kStalePatternFraction = 0.25;

}  // namespace

void ContactSet::initialize(const Mesh& mesh, const ContactSettings& settings) {
  settings.validate();
  settings_ = settings;
  settings_.strand_axis.normalize();
  points_.clear();
  in_pattern_.clear();
  element_pairs_.clear();
  pairs_grew_ = false;
  groups_.clear();
  group_of_.clear();
  wire_pair_kind_.clear();
  searches_ = 0;
  if (!settings_.enabled) return;
  reference_.clear();
  for (const MeshNode& n : mesh.nodes) reference_.push_back(n.reference);
  search(mesh, reference_);
  responses_.assign(points_.size(), ContactResponse{});
  // Wires touching in the reference configuration stick there from the start (no frictionless first
  // increment in which whole layers turn around the core held by the end planes only).
  commit(mesh, reference_);
}

double ContactSet::sliding_stabilization(const ContactPoint& p) const {
  return settings_.stabilization * p.stiffness.normal;
}

void ContactSet::evaluate_point(const Mesh& mesh, const std::vector<NodeState>& state, int index, bool with_tangent,
                                ContactResponse& r) const {
  const ContactPoint& p = points_[index];
  if (p.kind == ContactKind::kPoint) {
    const CrossingLocation c = locate_crossing(mesh, state, p);
    if (c.element_a >= 0) {
      evaluate_contact_into(p, pose(mesh, state, mesh.wires[p.wire_a].elements[c.element_a]),
                            pose(mesh, state, mesh.wires[p.wire_b].elements[c.element_b]), c.element_a, c.element_b, c.xi,
                            c.eta, settings_.strand_axis, with_tangent, c.pinned, r);
      return;
    }
  } else {
    const LineContactGroup& g = groups_[p.group];
    const auto a = pose(mesh, state, g.slave_element);
    const FootPoint foot = project_onto_wire(mesh, state, g.wire_b, g.candidates, centerline_point(a.x, p.xi), p.element_b, p.eta);
    if (foot.element >= 0) {
      const auto b = pose(mesh, state, mesh.wires[g.wire_b].elements[foot.element]);
      evaluate_contact_into(p, a, b, p.element_a, foot.element, p.xi, foot.eta, settings_.strand_axis, with_tangent,
                            PinnedParameter::kNone, r);
      return;
    }
  }
  // No partner found (a crossing off its elements, a foot past the master wire): open, far apart.
  reset_response(r, p.element_a, p.element_b, p.xi, p.eta);
  r.gap = 1e300;
}

void ContactSet::evaluate(const Mesh& mesh, const std::vector<NodeState>& state, bool with_tangent) {
  responses_.resize(points_.size());
  const int count = static_cast<int>(points_.size());
#pragma omp parallel for schedule(dynamic, 16)
  for (int i = 0; i < count; ++i) evaluate_point(mesh, state, i, with_tangent, responses_[i]);
}

void ContactSet::contributions(const Mesh& mesh, std::vector<PairContribution>& out) const {
  for (std::size_t i = 0; i < responses_.size(); ++i) {
    const ContactResponse& r = responses_[i];
    if (r.status == ContactStatus::kOpen) continue;
    out.push_back({nodes_of(mesh, static_cast<int>(i)), &r.force, &r.tangent});
  }
}

std::pair<int, int> ContactSet::elements_of(const Mesh& mesh, int index) const {
  const ContactPoint& p = points_[index];
  const int element_b = responses_[index].element_b >= 0 ? responses_[index].element_b
                        : p.element_b >= 0                ? p.element_b
                                                          : groups_[p.group].candidates.front();
  const int element_a = responses_[index].element_a >= 0 ? responses_[index].element_a : p.element_a;
  return {mesh.wires[p.wire_a].elements[element_a], mesh.wires[p.wire_b].elements[element_b]};
}

std::array<int, 6> ContactSet::nodes_of(const Mesh& mesh, int index) const {
  const auto [element_a, element_b] = elements_of(mesh, index);
  const auto &na = mesh.elements[element_a].nodes, &nb = mesh.elements[element_b].nodes;
  return {na[0], na[1], na[2], nb[0], nb[1], nb[2]};
}

void ContactSet::commit_point(const Mesh& mesh, const std::vector<NodeState>& state, std::size_t i) {
  ContactPoint& p = points_[i];
  const ContactResponse& r = responses_[i];
  ContactHistory& h = p.history;
  // Converged parameters (also of open crossings, so that they follow the wires and move on below).
  if (r.element_b >= 0) {
    p.xi = r.xi;
    p.eta = r.eta;
    if (r.element_a >= 0) p.element_a = r.element_a;
    p.element_b = r.element_b;
  }
  h.slipping = r.status == ContactStatus::kSlip && r.tangential_gap.norm() > 0;
  const bool open = r.status == ContactStatus::kOpen || r.normal_force < 0;
  if (open) {
    // An opened contact has no stick state; the slip it accumulated stays on record.
    h.stick_offset.setZero();
    h.closed = false;
    h.slipping = false;
    h.slip_since_reversal = 0;
    h.slip_direction.setZero();
  } else if (h.closed && r.status != ContactStatus::kSlip) {
    h.stick_offset = p.stick_offset;
    return;  // sticking: the anchors stay
  }
  if (r.element_b < 0) {
    h.anchored = false;
    return;
  }
  const auto [sa, sb, direction_a, direction_b] = surface_points(mesh, state, i);
  if (open || !h.anchored) {
    // An open point keeps its stick points where the two surfaces face each other now: if it closes within
    // the next increment, friction holds it from there at once (not one increment late).
    h.anchored = true;
    h.closed = !open;
    h.stick_a = sa;
    h.stick_b = sb;
    h.stick_direction_a = direction_a;
    h.stick_direction_b = direction_b;
    h.stick_offset.setZero();
    return;
  }
  h.closed = true;
  if (r.status != ContactStatus::kSlip) {  // closed within the increment and sticking there
    h.stick_offset = p.stick_offset;
    return;
  }
  // Slipping: the stick points move so that k_t |g_T - offset| = |Q| on the cone.
  const double c = r.slip_ratio;
  if (p.stick_offset.isZero()) {  // pulled toward the current contact points
    h.stick_a = sa + (h.stick_a - sa) * c;
    h.stick_b = sb + (h.stick_b - sb) * c;
    h.stick_direction_a = (direction_a + (h.stick_direction_a - direction_a) * c).normalized();
    h.stick_direction_b = (direction_b + (h.stick_direction_b - direction_b) * c).normalized();
  } else {  // augmented: onto the current contact points, the offset carrying the force on the cone
    h.stick_a = sa;
    h.stick_b = sb;
    h.stick_direction_a = direction_a;
    h.stick_direction_b = direction_b;
    h.stick_offset = -c * r.tangential_gap;
  }
  const Vec3 direction = r.tangential_gap.normalized();
  // Under the penalty stick the slip is the trial's excess over the cone; under the augmented stick the stick
  // points have not moved apart while sticking, and the slip is their whole separation along the slip.
  const Vec3 offset = p.stick_offset - r.normal.dot(p.stick_offset) * r.normal;
  const double slip = p.stick_offset.isZero() ? r.tangential_gap.norm() * (1.0 - c)
                                              : std::max(0.0, (r.tangential_gap + offset).dot(direction));
  if (direction.dot(h.slip_direction) < 0) h.slip_since_reversal = 0;
  h.slip += slip;
  h.dissipated_energy += std::max(0.0, -r.friction.dot(direction)) * slip * p.weight;
  h.slip_since_reversal += slip;
  h.slip_direction = direction;
}

ContactSet::SurfacePoints ContactSet::surface_points(const Mesh& mesh, const std::vector<NodeState>& state, std::size_t i) const {
  const ContactPoint& p = points_[i];
  const ContactResponse& r = responses_[i];
  const auto [element_a, element_b] = elements_of(mesh, static_cast<int>(i));
  return {wire_coordinate(p.element_a, r.xi), wire_coordinate(r.element_b, r.eta),
          section_direction(pose(mesh, state, element_a), r.xi, -r.normal),
          section_direction(pose(mesh, state, element_b), r.eta, r.normal)};
}

void ContactSet::set_start_points(const Mesh& mesh, const std::vector<NodeState>& state) {
  if (!(settings_.stabilization > 0)) return;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    ContactPoint& p = points_[i];
    p.start_set = responses_[i].element_b >= 0;
    if (p.start_set) std::tie(p.start_a, p.start_b, p.start_direction_a, p.start_direction_b) = surface_points(mesh, state, i);
  }
}

void ContactSet::set_stabilization(double fraction, const Mesh& mesh, const std::vector<NodeState>& state) {
  if (!settings_.enabled || fraction == settings_.stabilization) return;
  settings_.stabilization = fraction;
  for (ContactPoint& p : points_) {
    p.sliding_stabilization = sliding_stabilization(p);
    p.start_set = false;
  }
  evaluate(mesh, state, false);  // the contact points of the converged state, where the springs start
  set_start_points(mesh, state);
}

double ContactSet::dissipated_energy() const {
  double total = 0;
  for (const ContactPoint& p : points_) total += p.history.dissipated_energy;
  return total;
}

bool ContactSet::commit(const Mesh& mesh, const std::vector<NodeState>& state) {
  if (!settings_.enabled) return false;
  evaluate(mesh, state, false);
  // The stabilization's springs restart from here; the energy they held is what the stabilization took.
  commit_stabilization_energy_ = 0;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const ContactPoint& p = points_[i];
    if (p.sliding_stabilization > 0) commit_stabilization_energy_ += 0.5 * responses_[i].stabilization.squaredNorm() / p.sliding_stabilization * p.weight;
    commit_point(mesh, state, i);
  }
  double moved = 0;
  for (std::size_t n = 0; n < state.size(); ++n) moved = std::max(moved, (state[n].position - searched_positions_[n]).norm());
  const std::size_t committed = points_.size();
  if (moved > 0.5 * settings_.search_margin) search(mesh, state);
  responses_.resize(points_.size());
  evaluate(mesh, state, false);  // the committed state's forces and statuses, for output
  // Points the search just added (it only appends) get their stick points here, so that friction holds them from
  // their first increment.
  for (std::size_t i = committed; i < points_.size(); ++i) commit_point(mesh, state, i);
  set_start_points(mesh, state);
  update_pattern_membership(true);
  // The pattern keeps pairs that are no longer needed until they are a sizeable share of it: each change costs
  // a new analysis and a fresh factorization, and under load cycles the same pairs come and go again.
  const auto needed = collect_element_pairs(mesh);
  if (std::includes(element_pairs_.begin(), element_pairs_.end(), needed.begin(), needed.end()) &&
      element_pairs_.size() - needed.size() <= kStalePatternFraction * needed.size())
    return false;
  element_pairs_ = needed;
  return true;
}

void ContactSet::accept_iterate(const Mesh& mesh) {
  activate_closed();
  // Also when no point entered: a crossing may have moved to the next element.
  update_pattern_membership(false);
  const auto needed = collect_element_pairs(mesh);
  if (std::includes(element_pairs_.begin(), element_pairs_.end(), needed.begin(), needed.end())) return;
  std::vector<std::pair<int, int>> widened;
  std::set_union(element_pairs_.begin(), element_pairs_.end(), needed.begin(), needed.end(), std::back_inserter(widened));
  element_pairs_ = std::move(widened);
  pairs_grew_ = true;
}

void ContactSet::begin_correction() {
  correction_start_gaps_.resize(responses_.size());
  for (std::size_t i = 0; i < responses_.size(); ++i) correction_start_gaps_[i] = responses_[i].gap;
}

double ContactSet::admissible_fraction() const {
  if (correction_start_gaps_.size() != responses_.size()) return 1.0;
  double fraction = 1.0;
  for (std::size_t i = 0; i < responses_.size(); ++i) {
    const ContactPoint& p = points_[i];
    const double smoothing = p.stiffness.smoothing, start = correction_start_gaps_[i], end = responses_[i].gap;
    if (!(start > -smoothing) || !std::isfinite(start)) continue;  // fully in the penalty regime already
    const double depth = closing_depth(smoothing, p.radius_a + p.radius_b);
    if (!(end < -kDeepClosing * depth)) continue;
    // The gap is taken as linear in the fraction (the correction is short against the wires' curvature).
    fraction = std::min(fraction, (start + depth) / (start - end));
  }
  return fraction;
}

bool ContactSet::update_pattern_membership(bool may_leave) {
  bool entered = false;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const ContactPoint& p = points_[i];
    const ContactResponse& r = responses_[i];
    const double margin = settings_.pattern_margin * (p.radius_a + p.radius_b);
    const bool near = r.status != ContactStatus::kOpen || r.gap < margin;
    if (near && !in_pattern_[i]) {
      in_pattern_[i] = 1;
      entered = true;
    } else if (may_leave && in_pattern_[i] && r.gap > 2.0 * margin) {  // apart: no compressive force either way
      in_pattern_[i] = 0;
    }
  }
  return entered;
}

std::vector<std::pair<int, int>> ContactSet::collect_element_pairs(const Mesh& mesh) const {
  // The element pair each point was committed on and, within an increment, the pair it is evaluated on now (a
  // crossing moving to the next element, a line point's foot moving to the next master element).
  std::vector<std::pair<int, int>> pairs;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    if (!in_pattern_[i]) continue;
    const ContactPoint& p = points_[i];
    const auto& elements_a = mesh.wires[p.wire_a].elements;
    const auto& elements_b = mesh.wires[p.wire_b].elements;
    if (p.element_a >= 0 && p.element_b >= 0) pairs.emplace_back(elements_a[p.element_a], elements_b[p.element_b]);
    if (i < responses_.size() && responses_[i].element_a >= 0 && responses_[i].element_b >= 0)
      pairs.emplace_back(elements_a[responses_[i].element_a], elements_b[responses_[i].element_b]);
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

int ContactSet::radial_point_count() const {
  return static_cast<int>(std::count_if(points_.begin(), points_.end(), [](const ContactPoint& p) { return p.kind == ContactKind::kPoint; }));
}

}  // namespace strandfem
