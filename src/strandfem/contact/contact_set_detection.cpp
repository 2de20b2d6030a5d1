// How a contact set finds its points: each wire pair's kind from the strand's layout, the line-contact groups and
// their Gauss points, the crossings, and each new point's properties (radii, friction, penalties, initial offset).
#include "strandfem/contact/contact_set.hpp"

#include "strandfem/core/quadrature.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "strandfem/contact/contact_search.hpp"
#include "strandfem/contact/wire_geometry.hpp"

namespace strandfem {

namespace {

using namespace wire_geometry;

// How a wire lies about the strand axis (through the origin), from an element's chord in the reference
// configuration; summed over a pair's candidate elements, then their mean.
struct WireLayout {
  double hand = 0;           // sine of the lay angle, signed by the hand of the helix (0 on the axis)
  double axis_distance = 0;  // of the chord's middle node, mm
  double radial_slope = 0;   // |chord direction . radial direction|: 0 for a helix about the axis (by symmetry)
  void add(const WireLayout& other) {
    hand += other.hand;
    axis_distance += other.axis_distance;
    radial_slope += other.radial_slope;
  }
};

WireLayout chord_layout(const ElementCenterline<double>& x, const Vec3& axis, Vec3& tangent) {
  WireLayout c;
  const Vec3 middle = to_vec(x[1]);
  tangent = (to_vec(x[2]) - to_vec(x[0])).normalized();
  const Vec3 radial = middle - middle.dot(axis) * axis;
  c.axis_distance = radial.norm();
  if (c.axis_distance > 0) {
    c.hand = radial.normalized().cross(tangent).dot(axis);
    c.radial_slope = std::abs(radial.normalized().dot(tangent));
  }
  return c;
}

// Sums over a wire pair's candidate element pairs; wire[0] is the lower wire index.
struct PairLayout {
  double angle_sum = 0;
  std::array<WireLayout, 2> wire;
  int count = 0;
};

// How two wires touch. Strand wires follow the layout (paper section 2.3): wires of one layer run side by side,
// and a helix keeps its distance from a straight wire on the axis (the core), so both are line contacts;
// helices of opposite hand in different layers cross, at points, however small the angle between them (ACSR
// Cardinal's steel and first aluminum layers cross at 18 degrees). Other pairs (beam lines; layers laid the same
// way, which run nearly parallel) are line contacts when their chords are closer than `line_contact_angle`.
ContactKind classify_pair(const Mesh& mesh, int low, int high, const PairLayout& layout, double line_contact_angle) {
  const MeshWire &a = mesh.wires[low], &b = mesh.wires[high];
  const double n = layout.count;
  if (a.layer >= 0 && b.layer >= 0) {
    if (a.layer == b.layer) return ContactKind::kLine;
    // On the axis: within a tenth of the wire's radius (exactly 0 for a strand's core). A helix about the axis
    // runs square to its radius (chords within 3 degrees of that).
    auto on_axis = [&](const MeshWire& w, const WireLayout& sums) {
      return sums.axis_distance / n < 0.1 * mesh.sections[w.section]->geometry().contact_radius;
    };
    auto helix = [&](const WireLayout& sums) { return sums.radial_slope / n < 0.05; };
    const auto& [la, lb] = layout.wire;
    if ((on_axis(a, la) && helix(lb)) || (on_axis(b, lb) && helix(la))) return ContactKind::kLine;
    if (la.hand * lb.hand < 0) return ContactKind::kPoint;
  }
  return layout.angle_sum / n < line_contact_angle ? ContactKind::kLine : ContactKind::kPoint;
}

}  // namespace

void ContactSet::search(const Mesh& mesh, const std::vector<NodeState>& state) {
  std::vector<double> inflation(mesh.elements.size(), -1.0);
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    const double radius = mesh.sections[mesh.elements[e].section]->geometry().contact_radius;
    if (radius > 0) inflation[e] = radius + settings_.search_margin;
  }
  const auto pairs = find_candidate_pairs(mesh, state, inflation);
  auto wire_key = [](int a, int b) { return std::make_pair(std::min(a, b), std::max(a, b)); };
  // Classify each new wire pair once, from the candidate elements' chords in the reference configuration (the
  // strand's layout, not where bending has moved it).
  std::map<std::pair<int, int>, PairLayout> layouts;
  for (const auto& [e, f] : pairs) {
    const int we = mesh.elements[e].wire, wf = mesh.elements[f].wire;
    const auto key = wire_key(we, wf);
    if (wire_pair_kind_.count(key)) continue;
    auto& layout = layouts[key];
    Vec3 te, tf;
    const WireLayout ce = chord_layout(centerline(mesh, reference_, e), settings_.strand_axis, te);
    const WireLayout cf = chord_layout(centerline(mesh, reference_, f), settings_.strand_axis, tf);
    layout.angle_sum += std::acos(std::min(1.0, std::abs(te.dot(tf)))) * 180.0 / M_PI;
    layout.wire[0].add(we < wf ? ce : cf);
    layout.wire[1].add(we < wf ? cf : ce);
    layout.count += 1;
  }
  for (const auto& [key, layout] : layouts)
    wire_pair_kind_[key] = classify_pair(mesh, key.first, key.second, layout, settings_.line_contact_angle);

  std::vector<int> new_groups;
  for (const auto& [e, f] : pairs) {
    const int we = mesh.elements[e].wire, wf = mesh.elements[f].wire;
    const MeshWire &a = mesh.wires[we], &b = mesh.wires[wf];
    if (wire_pair_kind_.at(wire_key(we, wf)) == ContactKind::kLine) {
      // Slave: the outer layer (core-layer contacts: the helical wire); within a layer, the higher index.
      const bool e_is_slave = a.layer != b.layer ? a.layer > b.layer : we > wf;
      const int slave = e_is_slave ? e : f, master = e_is_slave ? f : e;
      const int wire_b = mesh.elements[master].wire;
      auto [it, inserted] = group_of_.try_emplace({slave, wire_b}, static_cast<int>(groups_.size()));
      if (inserted) groups_.push_back(LineContactGroup{slave, wire_b, {}});
      auto& candidates = groups_[it->second].candidates;
      const int local = local_index(mesh, master);
      if (std::find(candidates.begin(), candidates.end(), local) == candidates.end()) candidates.push_back(local);
      std::sort(candidates.begin(), candidates.end());
      if (inserted) new_groups.push_back(it->second);
    } else {
      // Point contacts: slave on the inner layer, as the paper maps its contact elements.
      const bool e_is_slave = a.layer != b.layer ? a.layer < b.layer : we < wf;
      const int slave = e_is_slave ? e : f, master = e_is_slave ? f : e;
      // Newton from a few starts: from the middle alone it can run to a far stationary point.
      const auto xs = centerline(mesh, state, slave), xm = centerline(mesh, state, master);
      const int ls = local_index(mesh, slave), lm = local_index(mesh, master);
      auto find_crossing = [&] {
        for (double start_xi : {0.0, -0.7, 0.7})
          for (double start_eta : {0.0, -0.7, 0.7}) {
            double xi = start_xi, eta = start_eta;
            if (closest_points(xs, xm, xi, eta) && in_range(xi, ls) && in_range(eta, lm)) {
              add_crossing(mesh, slave, master, xi, eta);
              return;
            }
          }
      };
      find_crossing();
    }
  }
  // Points of new groups once their candidate lists are complete (the overlap offset projects onto them).
  for (int g : new_groups) add_line_points(mesh, g);
  responses_.resize(points_.size());
  searched_positions_.clear();
  for (const NodeState& s : state) searched_positions_.push_back(s.position);
  ++searches_;
  in_pattern_.resize(points_.size(), 0);  // new points join the pattern at the commit that follows
}
void ContactSet::set_point_properties(const Mesh& mesh, ContactPoint& p, const Vec3& reference_position) {
  const Section& sa = *mesh.sections[mesh.wires[p.wire_a].section];
  const Section& sb = *mesh.sections[mesh.wires[p.wire_b].section];
  p.radius_a = sa.geometry().contact_radius;
  p.radius_b = sb.geometry().contact_radius;
  const double modulus = std::min(sa.material().youngs_modulus, sb.material().youngs_modulus);
  const double diameter = 2.0 * std::min(p.radius_a, p.radius_b);
  const double element_size = arc_length(centerline(mesh, reference_, mesh.wires[p.wire_a].elements[p.element_a]));
  const ContactInterface interface = contact_interface(mesh.wires[p.wire_a].layer, mesh.wires[p.wire_b].layer);
  p.mu1 = settings_.friction_at(sa.material().name, sb.material().name, interface, reference_position.dot(settings_.strand_axis));
  p.mu2 = p.mu1 * settings_.orthotropy_at(sa.material().name, sb.material().name, interface);
  p.direction_along_slave_wire = settings_.friction_direction == FrictionDirection::kSlaveWire;
  p.stiffness = penalty_stiffness(settings_, p.kind == ContactKind::kLine, modulus, diameter, element_size, p.mu1);
  p.allowed_slip = settings_.tangential_penalty == TangentialPenalty::kElasticSlip ? settings_.elastic_slip * element_size : 0.0;
  p.sliding_stabilization = sliding_stabilization(p);
}
void ContactSet::add_line_points(const Mesh& mesh, int group) {
  const LineContactGroup& g = groups_[group];
  std::vector<double> gp, gw;
  gauss_legendre(settings_.line_points, gp, gw);
  const ElementCenterline<double> x = centerline(mesh, reference_, g.slave_element);
  for (int k = 0; k < settings_.line_points; ++k) {
    ContactPoint p;
    p.kind = ContactKind::kLine;
    p.wire_a = mesh.elements[g.slave_element].wire;
    p.wire_b = g.wire_b;
    p.element_a = local_index(mesh, g.slave_element);
    p.group = group;
    p.xi = gp[k];
    const V3<double> t = centerline_tangent(x, gp[k]);
    p.weight = gw[k] * std::sqrt(dot(t, t));
    set_point_properties(mesh, p, to_vec(centerline_point(x, gp[k])));
    p.gap_offset = initial_offset(mesh, p);
    points_.push_back(p);
  }
}

void ContactSet::add_crossing(const Mesh& mesh, int element_a, int element_b, double xi, double eta) {
  ContactPoint p;
  p.kind = ContactKind::kPoint;
  p.wire_a = mesh.elements[element_a].wire;
  p.wire_b = mesh.elements[element_b].wire;
  p.element_a = local_index(mesh, element_a);
  p.element_b = local_index(mesh, element_b);
  p.xi = xi;
  p.eta = eta;
  const double sa = wire_coordinate(p.element_a, xi), sb = wire_coordinate(p.element_b, eta);
  for (const ContactPoint& q : points_)
    if (q.kind == ContactKind::kPoint && q.wire_a == p.wire_a && q.wire_b == p.wire_b &&
        std::abs(wire_coordinate(q.element_a, q.xi) - sa) < 0.5 && std::abs(wire_coordinate(q.element_b, q.eta) - sb) < 0.5)
      return;  // the same crossing, already tracked
  set_point_properties(mesh, p, to_vec(centerline_point(centerline(mesh, reference_, element_a), xi)));
  p.gap_offset = initial_offset(mesh, p);
  points_.push_back(p);
  responses_.resize(points_.size());
}

double ContactSet::initial_offset(const Mesh& mesh, const ContactPoint& p) const {
  if (settings_.initial_overlap != InitialOverlap::kOffset) return 0.0;
  const double gap = reference_gap(mesh, p);
  return gap < settings_.touch_tolerance * (p.radius_a + p.radius_b) ? gap : 0.0;
}

double ContactSet::reference_gap(const Mesh& mesh, const ContactPoint& p) const {
  const std::vector<NodeState>& reference = reference_;
  const double radii = p.radius_a + p.radius_b;
  if (p.kind == ContactKind::kPoint) {
    double xi = p.xi, eta = p.eta;
    const auto a = centerline(mesh, reference, mesh.wires[p.wire_a].elements[p.element_a]);
    const auto b = centerline(mesh, reference, mesh.wires[p.wire_b].elements[p.element_b]);
    if (!closest_points(a, b, xi, eta)) return 0.0;
    const V3<double> d = sub(centerline_point(a, xi), centerline_point(b, eta));
    return std::sqrt(dot(d, d)) - radii;
  }
  const LineContactGroup& g = groups_[p.group];
  const FootPoint foot = project_onto_wire(mesh, reference, g.wire_b, g.candidates, centerline_point(centerline(mesh, reference, g.slave_element), p.xi), -1, 0.0);
  return foot.element >= 0 ? foot.distance - radii : 0.0;
}

}  // namespace strandfem
