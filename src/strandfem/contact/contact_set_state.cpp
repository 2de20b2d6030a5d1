// Checkpoints of a contact set: every point (fixed data, history, working state), the line-contact groups and
// the search bookkeeping, so that a resumed run continues exactly where the saved one stood.
#include "strandfem/contact/contact_set.hpp"

#include "strandfem/core/archive.hpp"

namespace strandfem {
namespace {

void save_point(ArchiveWriter& out, const ContactPoint& p) {
  out.value(p.kind);
  out.value(std::array<int, 6>{p.wire_a, p.wire_b, p.element_a, p.element_b, p.group, p.normal_switches});
  out.value(std::array<double, 9>{p.xi, p.eta, p.weight, p.radius_a, p.radius_b, p.gap_offset, p.mu1, p.mu2, p.allowed_slip});
  out.value(p.stiffness);
  const ContactHistory& h = p.history;
  out.value(std::array<bool, 4>{h.closed, h.slipping, p.active, h.anchored});
  out.value(std::array<double, 5>{h.stick_a, h.stick_b, h.slip, h.slip_since_reversal, h.dissipated_energy});
  out.vec3(h.stick_direction_a);
  out.vec3(h.stick_direction_b);
  out.vec3(h.slip_direction);
  out.vec3(h.stick_offset);
  out.vec3(p.stick_offset);
  out.value(p.friction_mode);
  out.value(p.friction_switches);
  out.value(p.slip_direction);
}

ContactPoint load_point(ArchiveReader& in) {
  ContactPoint p;
  in.value(p.kind);
  const auto ints = in.value<std::array<int, 6>>();
  p.wire_a = ints[0], p.wire_b = ints[1], p.element_a = ints[2], p.element_b = ints[3], p.group = ints[4];
  p.normal_switches = ints[5];
  const auto reals = in.value<std::array<double, 9>>();
  p.xi = reals[0], p.eta = reals[1], p.weight = reals[2], p.radius_a = reals[3], p.radius_b = reals[4];
  p.gap_offset = reals[5], p.mu1 = reals[6], p.mu2 = reals[7], p.allowed_slip = reals[8];
  in.value(p.stiffness);
  ContactHistory& h = p.history;
  const auto flags = in.value<std::array<bool, 4>>();
  h.closed = flags[0], h.slipping = flags[1], p.active = flags[2], h.anchored = flags[3];
  const auto history = in.value<std::array<double, 5>>();
  h.stick_a = history[0], h.stick_b = history[1], h.slip = history[2], h.slip_since_reversal = history[3];
  h.dissipated_energy = history[4];
  h.stick_direction_a = in.vec3();
  h.stick_direction_b = in.vec3();
  h.slip_direction = in.vec3();
  h.stick_offset = in.vec3();
  p.stick_offset = in.vec3();
  in.value(p.friction_mode);
  in.value(p.friction_switches);
  in.value(p.slip_direction);
  return p;
}

}  // namespace

void ContactSet::save_state(ArchiveWriter& out) const {
  out.section("contact");
  out.value(settings_.enabled);
  out.value(static_cast<std::uint64_t>(points_.size()));
  for (const ContactPoint& p : points_) save_point(out, p);
  out.value(static_cast<std::uint64_t>(groups_.size()));
  for (const LineContactGroup& g : groups_) {
    out.value(std::array<int, 2>{g.slave_element, g.wire_b});
    out.vector(g.candidates);
  }
  out.map(wire_pair_kind_);
  out.vector(element_pairs_);
  out.vector(in_pattern_);
  out.value(static_cast<std::uint64_t>(searched_positions_.size()));
  for (const Vec3& x : searched_positions_) out.vec3(x);
  out.value(searches_);
}

void ContactSet::restore_state(ArchiveReader& in, const Mesh& mesh, const std::vector<NodeState>& state) {
  in.section("contact");
  in.expect(settings_.enabled, "contact.enabled");
  const auto point_count = in.value<std::uint64_t>();
  std::vector<ContactPoint> points;
  for (std::uint64_t i = 0; i < point_count; ++i) {
    points.push_back(load_point(in));
    ContactPoint& p = points.back();
    // From the settings, as set_point_properties does.
    p.sliding_stabilization = sliding_stabilization(p);
    p.direction_along_slave_wire = settings_.friction_direction == FrictionDirection::kSlaveWire;
    const int wires = static_cast<int>(mesh.wires.size());
    if (p.wire_a < 0 || p.wire_a >= wires || p.wire_b < 0 || p.wire_b >= wires)
      throw ArchiveError("checkpoint does not match this model: a contact point names a wire it does not have");
  }
  std::vector<LineContactGroup> groups(in.value<std::uint64_t>());
  for (LineContactGroup& g : groups) {
    const auto ids = in.value<std::array<int, 2>>();
    g.slave_element = ids[0];
    g.wire_b = ids[1];
    g.candidates = in.vector<int>();
  }
  in.map(wire_pair_kind_);
  element_pairs_ = in.vector<std::pair<int, int>>();
  in_pattern_ = in.vector<char>();
  searched_positions_.assign(in.value<std::uint64_t>(), Vec3::Zero());
  for (Vec3& x : searched_positions_) x = in.vec3();
  in.value(searches_);
  if (in_pattern_.size() != points.size() || searched_positions_.size() != state.size())
    throw ArchiveError("checkpoint does not match this model: contact bookkeeping differs");
  points_ = std::move(points);
  groups_ = std::move(groups);
  group_of_.clear();
  for (std::size_t g = 0; g < groups_.size(); ++g) group_of_[{groups_[g].slave_element, groups_[g].wire_b}] = static_cast<int>(g);
  pairs_grew_ = false;
  responses_.assign(points_.size(), ContactResponse{});
  evaluate(mesh, state, false);  // the committed state's forces and statuses, for output
  set_start_points(mesh, state);  // where the saved run's commit put them: the contact points of that state
}

}  // namespace strandfem
