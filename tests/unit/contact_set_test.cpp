// The contact set on meshes: line loads, the tangent's pattern, crossings held over element ends and kinks, and
// the search against the helix layout (eq. 2.4).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <set>
#include <utility>
#include <vector>

#include "strandfem/contact/contact_set.hpp"
#include "strandfem/mesh/mesh.hpp"
#include "strandfem/post/analytic.hpp"

namespace strandfem {
namespace {

// Two straight parallel steel wires (d = 2 mm) along z: "master" on the axis, "slave" at x = offset.
Mesh parallel_lines(int master_elements, int slave_elements, double length, double offset) {
  Mesh mesh;
  mesh.sections.push_back(std::make_unique<ElasticSection>(SectionGeometry::circle(2.0, 0.3), Material{200000, 0.3, 0, "steel"}));
  auto line = [length](double x) {
    return [x, length](double t) { return std::make_pair(Vec3(x, 0, t * length), Mat3::Identity()); };
  };
  mesh.add_line("master", -1, 0, 0, master_elements, line(0.0));
  mesh.add_line("slave", -1, 1, 0, slave_elements, line(offset));
  return mesh;
}

// Contact on, every other setting at its default.
ContactSettings enabled_contact() {
  ContactSettings settings;
  settings.enabled = true;
  return settings;
}

std::vector<NodeState> reference_state(const Mesh& mesh) {
  std::vector<NodeState> state;
  for (const MeshNode& n : mesh.nodes) state.push_back(n.reference);
  return state;
}

// Two straight parallel wires (slave 2 elements, master 3 elements, so foot points cross master element
// ends) pressed together: the line load must integrate to p L exactly, without loss or double counting.
TEST(ContactSet, ParallelWiresCarryTheUniformLineLoad) {
  const double length = 30, offset = 1.95;
  const Mesh mesh = parallel_lines(3, 2, length, offset);
  ContactSettings settings;
  settings.enabled = true;
  settings.initial_overlap = InitialOverlap::kKeep;
  ContactSet contacts;
  contacts.initialize(mesh, settings);
  EXPECT_EQ(contacts.lateral_pair_count(), 2);
  EXPECT_EQ(contacts.radial_point_count(), 0);
  const std::vector<NodeState> state = reference_state(mesh);
  contacts.evaluate(mesh, state, false);
  const double youngs_modulus = 200000;
  const double line_stiffness = settings.normal_factor * youngs_modulus * settings.normal_multiplier;  // fKn E xi_n
  const double pressure = line_stiffness * (2.0 - offset);
  Vec3 on_master = Vec3::Zero();
  for (std::size_t i = 0; i < contacts.points().size(); ++i) {
    const ContactResponse& r = contacts.responses()[i];
    ASSERT_EQ(r.status, ContactStatus::kStick);
    EXPECT_NEAR(r.normal_force, pressure, 1e-9 * pressure);
    for (int k = 0; k < 3; ++k) on_master -= r.force.segment<3>(18 + 6 * k);
  }
  EXPECT_NEAR(on_master.x(), -pressure * length, 1e-9 * pressure * length);
  EXPECT_NEAR(on_master.y(), 0.0, 1e-9);
}

// Wires held apart by more than the pattern margin keep their element pairs out of the tangent's pattern;
// a point that closes during Newton widens it at once, and the pairs leave again once the wires are apart.
TEST(ContactSet, PatternHoldsOnlyPairsThatAreClosedOrNearlySo) {
  const Mesh mesh = parallel_lines(3, 2, 30, 2.3);  // gap 0.3 mm: within the search margin, beyond 0.01 (r_a + r_b)
  ContactSet contacts;
  contacts.initialize(mesh, enabled_contact());
  ASSERT_EQ(contacts.lateral_pair_count(), 2);
  EXPECT_TRUE(contacts.element_pairs().empty());
  std::vector<NodeState> state = reference_state(mesh);
  for (std::size_t n = 0; n < state.size(); ++n)
    if (mesh.nodes[n].wire == 1) state[n].position.x() -= 0.31;  // pressed 0.01 mm into the master
  contacts.begin_increment(true);
  contacts.evaluate(mesh, state, false);
  contacts.accept_iterate(mesh);
  EXPECT_TRUE(contacts.element_pairs_grew());
  EXPECT_FALSE(contacts.element_pairs_grew());  // reported once
  EXPECT_GE(contacts.element_pairs().size(), 2u);  // each of the two slave elements with its master candidates
  // Back at 0.3 mm (beyond twice the margin) the pairs leave at the next commit.
  EXPECT_TRUE(contacts.commit(mesh, reference_state(mesh)));
  EXPECT_TRUE(contacts.element_pairs().empty());
  // Within the margin, a pair enters without touching.
  std::vector<NodeState> near = reference_state(mesh);
  for (std::size_t n = 0; n < near.size(); ++n)
    if (mesh.nodes[n].wire == 1) near[n].position.x() -= 0.29;  // gap 0.01 mm < 0.02 mm
  EXPECT_TRUE(contacts.commit(mesh, near));
  EXPECT_FALSE(contacts.element_pairs().empty());
}

// Pairs no longer needed stay in the pattern while they are at most a quarter of the needed ones (a change costs
// an analysis and a fresh factorization); a point that closes again on such a pair does not widen the pattern.
TEST(ContactSet, PatternKeepsAFewStalePairsUntilTheyAreAQuarterOfIt) {
  const Mesh mesh = parallel_lines(12, 10, 100, 2.3);
  ContactSet contacts;
  contacts.initialize(mesh, enabled_contact());
  ASSERT_TRUE(contacts.element_pairs().empty());
  // The slave pressed 0.01 mm into the master where z < from_z, 0.3 mm apart beyond.
  auto pressed_below = [&](double from_z) {
    std::vector<NodeState> state = reference_state(mesh);
    for (std::size_t n = 0; n < state.size(); ++n)
      if (mesh.nodes[n].wire == 1 && state[n].position.z() < from_z) state[n].position.x() -= 0.31;
    return state;
  };
  EXPECT_TRUE(contacts.commit(mesh, pressed_below(1e3)));
  const auto all = contacts.element_pairs();
  ASSERT_GE(all.size(), 10u);
  // The last slave element lifts off: its pairs are stale but stay.
  EXPECT_FALSE(contacts.commit(mesh, pressed_below(85)));
  EXPECT_EQ(contacts.element_pairs(), all);
  contacts.begin_increment(true);
  contacts.evaluate(mesh, pressed_below(1e3), false);
  contacts.accept_iterate(mesh);
  EXPECT_FALSE(contacts.element_pairs_grew());  // closing again on pairs the pattern kept
  // Half the slave lifts off: the stale pairs are too many and leave.
  EXPECT_TRUE(contacts.commit(mesh, pressed_below(45)));
  EXPECT_LT(contacts.element_pairs().size(), all.size() * 3 / 4);
  for (const auto& [a, b] : contacts.element_pairs()) EXPECT_TRUE(std::count(all.begin(), all.end(), std::make_pair(a, b)));
}

// A line contact's points couple their slave element only with the master elements their feet lie on, not with
// every candidate of the search: the candidates within the search margin overlap the neighbours and only add fill.
TEST(ContactSet, LinePointsPutOnlyTheMasterElementsOfTheirFeetInThePattern) {
  const Mesh mesh = parallel_lines(12, 10, 100, 2.3);  // masters 8.33 mm long, slaves 10 mm
  ContactSet contacts;
  contacts.initialize(mesh, enabled_contact());
  std::vector<NodeState> state = reference_state(mesh);
  for (std::size_t n = 0; n < state.size(); ++n)
    if (mesh.nodes[n].wire == 1) state[n].position.x() -= 0.31;  // pressed 0.01 mm into the master all along
  EXPECT_TRUE(contacts.commit(mesh, state));
  std::set<std::pair<int, int>> expected;
  for (const ContactPoint& p : contacts.points()) {
    ASSERT_EQ(p.kind, ContactKind::kLine);
    const double z = 10.0 * p.element_a + 5.0 * (1.0 + p.xi);  // the point's height on the straight slave
    const int master = std::min(11, static_cast<int>(z / (100.0 / 12.0)));
    expected.insert({mesh.wires[1].elements[p.element_a], mesh.wires[0].elements[master]});
  }
  const auto& pairs = contacts.element_pairs();
  const std::set<std::pair<int, int>> in_pattern(pairs.begin(), pairs.end());
  EXPECT_EQ(in_pattern, expected);
  EXPECT_EQ(expected.size(), 20u);  // each slave element straddles one end of a master element
}

// A steel wire (d = 2 mm, layer 1) from z = 0 to 20 in two straight elements meeting at (0, 0, 10): a V in the x-z
// plane with arms of the given slope (0: straight), to which a test adds the wire that crosses it.
Mesh v_wire_mesh(double slope) {
  Mesh mesh;
  mesh.sections.push_back(std::make_unique<ElasticSection>(SectionGeometry::circle(2.0, 0.3), Material{200000, 0.3, 0, "steel"}));
  mesh.add_line("kinked", 1, 0, 0, 2, [slope](double t) {
    return std::make_pair(Vec3(slope * std::abs(t - 0.5) * 20.0, 0, 20.0 * t), Mat3::Identity());
  });
  return mesh;
}

// A straight wire along z and one across it (along y at z = 5) pressed 0.05 mm into it.
Mesh pressed_crossing_mesh() {
  Mesh mesh = v_wire_mesh(0.0);
  mesh.add_line("across", 2, 0, 0, 2, [](double t) { return std::make_pair(Vec3(-1.95, 20.0 * t - 10.0, 5.0), Mat3::Identity()); });
  return mesh;
}

// Index of the (single) crossing among a contact set's points.
std::size_t crossing_index(const ContactSet& contacts) {
  const auto& points = contacts.points();
  return std::find_if(points.begin(), points.end(), [](const ContactPoint& p) { return p.kind == ContactKind::kPoint; }) - points.begin();
}

// A wire slides across a node where the other wire's two straight elements meet at an angle (a V). Near the node
// the closest point of each element lies past its end; the crossing is then held at the node, so the gap is the
// true distance between the wires all along, without the jump an element's extrapolation beyond its end gave
// when the crossing moved over (docs/theory.md, "Locating a crossing as the nearest pair of points").
TEST(ContactSet, CrossingSlidesOverAKinkWithAContinuousGap) {
  const double slope = 0.2, offset = -2.05;  // V apex at (0, 0, 10); the other wire along y at x = offset
  Mesh mesh = v_wire_mesh(slope);
  auto across_at = [&](double z) {
    return [z, offset](double t) { return std::make_pair(Vec3(offset, 20.0 * t - 10.0, z), Mat3::Identity()); };
  };
  mesh.add_line("across", 2, 0, 0, 1, across_at(8.0));
  ContactSet contacts;
  contacts.initialize(mesh, enabled_contact());
  ASSERT_EQ(contacts.radial_point_count(), 1);
  // Distance in the x-z plane from the other wire's axis to the V (two segments), minus the radii.
  auto true_gap = [&](double z) {
    auto to_segment = [&](double x0, double z0, double x1, double z1) {
      const double dx = x1 - x0, dz = z1 - z0;
      const double s = std::clamp(((offset - x0) * dx + (z - z0) * dz) / (dx * dx + dz * dz), 0.0, 1.0);
      return std::hypot(offset - x0 - s * dx, z - z0 - s * dz);
    };
    return std::min(to_segment(slope * 10, 0, 0, 10), to_segment(0, 10, slope * 10, 20)) - 2.0;
  };
  std::vector<NodeState> state = reference_state(mesh);
  for (double z : {8.0, 9.0, 9.5, 9.7, 9.9, 10.0, 10.1, 10.3, 10.5, 11.0, 12.0}) {
    for (std::size_t n = 0; n < state.size(); ++n)
      if (mesh.nodes[n].wire == 1) state[n].position.z() = z;
    contacts.evaluate(mesh, state, false);
    EXPECT_NEAR(contacts.responses()[crossing_index(contacts)].gap, true_gap(z), 1e-9) << "z = " << z;
  }
}

// The same V, crossed by an inclined wire that has an angle of its own at a node near the crossing (bent toward or
// away from the V). Near both nodes the closest points of both wires can lie past their elements' ends at once.
// The gap must be the true distance between the two polylines whatever element pair the crossing was committed on
// before: the wire slides one way and back, committing at each position (on S32 under bending a crossing held at one
// wire's node or the other's gave 160 N or 784 N for the same state, depending on the elements it started from).
TEST(ContactSet, CrossingNearTwoKinksIsTheNearestPairOfPointsWhateverItsHistory) {
  const double slope = 0.2, offset = -2.05, incline = 0.5;  // V apex at (0, 0, 10); the other wire z = z0 + incline y
  // Distance between segments [p0, p1] and [q0, q1]: convex in both parameters, nested ternary searches.
  auto ternary = [](const std::function<double(double)>& f) {
    double lo = 0, hi = 1;
    for (int k = 0; k < 100; ++k) {
      const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
      if (f(m1) < f(m2)) hi = m2;
      else lo = m1;
    }
    return f(0.5 * (lo + hi));
  };
  auto segment_distance = [&](const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
    return ternary([&](double s) { return ternary([&](double t) { return (p0 + s * (p1 - p0) - q0 - t * (q1 - q0)).norm(); }); });
  };
  for (double bend : {-0.02, 0.0, 0.02})
    for (double node_y : {-0.04, -0.01, 0.01, 0.04}) {
      Mesh mesh = v_wire_mesh(slope);
      auto across = [&](double y) { return Vec3(offset - bend * std::abs(y - node_y), y, 9.0 + incline * y); };
      mesh.add_line("across", 2, 0, 0, 2, [&](double t) { return std::make_pair(across(20.0 * t - 10.0 + node_y), Mat3::Identity()); });
      ContactSet contacts;
      contacts.initialize(mesh, enabled_contact());
      ASSERT_EQ(contacts.radial_point_count(), 1);
      std::vector<NodeState> state = reference_state(mesh);
      const std::vector<double> forth = {9.0, 9.6, 9.8, 9.9, 9.95, 10.0, 10.05, 10.1, 10.2, 10.4, 11.0};
      std::vector<double> path = forth;
      path.insert(path.end(), forth.rbegin() + 1, forth.rend());
      for (double z0 : path) {
        const Vec3 shift(0, 0, z0 - 9.0), apex(0, 0, 10), a0(slope * 10, 0, 0), a2(slope * 10, 0, 20);
        const Vec3 b0 = across(-10.0 + node_y) + shift, b1 = across(node_y) + shift, b2 = across(10.0 + node_y) + shift;
        const double true_gap = std::min({segment_distance(a0, apex, b0, b1), segment_distance(a0, apex, b1, b2),
                                          segment_distance(apex, a2, b0, b1), segment_distance(apex, a2, b1, b2)}) - 2.0;
        for (std::size_t n = 0; n < state.size(); ++n)
          if (mesh.nodes[n].wire == 1) state[n].position = mesh.nodes[n].reference.position + shift;
        contacts.evaluate(mesh, state, false);
        EXPECT_NEAR(contacts.responses()[crossing_index(contacts)].gap, true_gap, 1e-8) << "bend " << bend << ", node at y = " << node_y << ", z0 = " << z0;
        contacts.commit(mesh, state);
      }
    }
}

// A crossing that slides past a wire's end leaves the wire: it opens, even while held active within an increment
// (on S32 under bending such a crossing near a clamp was placed 2.3 mm away on the wire's far node and, active,
// pulled with 1.5e7 N). And an active point whose wires have separated by more than a wobble opens.
TEST(ContactSet, CrossingPastAWiresEndOpens) {
  const double offset = -1.95;  // wires of radius 1 pressed 0.05 mm together
  Mesh mesh = v_wire_mesh(0.0);  // straight, along z
  mesh.add_line("across", 2, 0, 0, 2, [&](double t) { return std::make_pair(Vec3(offset, 20.0 * t - 10.0, 1.0), Mat3::Identity()); });
  ContactSettings settings = enabled_contact();
  settings.initial_overlap = InitialOverlap::kKeep;
  settings.normal_smoothing = 0.0;  // the plain law, whose active points hold a tension within an increment
  ContactSet contacts;
  contacts.initialize(mesh, settings);
  ASSERT_EQ(contacts.radial_point_count(), 1);
  const std::size_t crossing = crossing_index(contacts);
  std::vector<NodeState> state = reference_state(mesh);
  auto place = [&](double z, double x) {
    for (std::size_t n = 0; n < state.size(); ++n)
      if (mesh.nodes[n].wire == 1) state[n].position = Vec3(x, mesh.nodes[n].reference.position.y(), z);
  };
  contacts.commit(mesh, state);
  contacts.begin_increment(true);
  contacts.evaluate(mesh, state, false);
  contacts.accept_iterate(mesh);  // the crossing is active
  ASSERT_EQ(contacts.responses()[crossing].status, ContactStatus::kStick);
  EXPECT_NEAR(contacts.responses()[crossing].gap, -0.05, 1e-9);
  place(0.5, offset);  // still on the wire, near its first node
  contacts.evaluate(mesh, state, false);
  EXPECT_NE(contacts.responses()[crossing].status, ContactStatus::kOpen);
  EXPECT_NEAR(contacts.responses()[crossing].gap, -0.05, 1e-9);
  place(-0.5, offset);  // past the wire's first node
  contacts.evaluate(mesh, state, false);
  EXPECT_EQ(contacts.responses()[crossing].status, ContactStatus::kOpen);
  EXPECT_EQ(contacts.responses()[crossing].force.norm(), 0.0);
  place(1.0, offset - 0.5);  // back on the wire, 0.45 mm apart: separated, not an iterate's wobble
  contacts.evaluate(mesh, state, false);
  EXPECT_EQ(contacts.responses()[crossing].status, ContactStatus::kOpen);
  place(1.0, offset - 0.06);  // 0.01 mm apart: an active point holds on (tension, released at convergence)
  contacts.evaluate(mesh, state, false);
  EXPECT_EQ(contacts.responses()[crossing].status, ContactStatus::kStick);
  EXPECT_LT(contacts.responses()[crossing].normal_force, 0.0);
}

// Friction acts from the increment in which a point closes, held from where the surfaces faced each other at the
// last converged state: a crossing 0.05 mm open is pressed 0.05 mm together and slid 0.2 mm along the straight wire
// in one increment (well past the elastic slip). It slides at the Coulomb limit |Q| = mu P, against the slide.
// Before, a point open at the last converged state was frictionless for its whole first closed increment.
TEST(ContactSet, FrictionHoldsAPointFromTheIncrementItClosesIn) {
  Mesh mesh = v_wire_mesh(0.0);  // straight, along z
  mesh.add_line("across", 2, 0, 0, 2, [](double t) { return std::make_pair(Vec3(-2.05, 20.0 * t - 10.0, 5.0), Mat3::Identity()); });
  ContactSettings settings = enabled_contact();
  settings.friction = 0.3;
  ContactSet contacts;
  contacts.initialize(mesh, settings);
  ASSERT_EQ(contacts.radial_point_count(), 1);
  const std::size_t crossing = crossing_index(contacts);
  std::vector<NodeState> state = reference_state(mesh);
  contacts.commit(mesh, state);
  ASSERT_EQ(contacts.responses()[crossing].status, ContactStatus::kOpen);
  contacts.begin_increment(true);
  for (std::size_t n = 0; n < state.size(); ++n)
    if (mesh.nodes[n].wire == 1) state[n].position += Vec3(0.1, 0.0, 0.2);
  contacts.evaluate(mesh, state, false);
  const ContactResponse& r = contacts.responses()[crossing];
  ASSERT_NE(r.status, ContactStatus::kOpen);
  EXPECT_NEAR(r.gap, -0.05, 1e-9);
  EXPECT_EQ(r.status, ContactStatus::kSlip);
  EXPECT_NEAR(r.friction.norm(), 0.3 * r.normal_force, 1e-9 * r.normal_force);
  // Along the slide (z) and against it: the across wire moved +z relative to the straight one.
  const double across_is_slave = contacts.points()[crossing].wire_a == 1 ? 1.0 : -1.0;
  EXPECT_NEAR(across_is_slave * r.friction.z(), -0.3 * r.normal_force, 1e-9 * r.normal_force);
  // Committed: the slide past the elastic slip is the point's slip, and friction's work over it mu P slip.
  const double normal_force = r.normal_force;
  contacts.commit(mesh, state);
  const ContactPoint& p = contacts.points()[crossing];
  ASSERT_GT(p.allowed_slip, 0.0);
  EXPECT_NEAR(p.history.slip, 0.2 - p.allowed_slip, 1e-9);
  EXPECT_NEAR(p.history.dissipated_energy, 0.3 * normal_force * (0.2 - p.allowed_slip), 1e-9 * normal_force);
  EXPECT_DOUBLE_EQ(contacts.dissipated_energy(), p.history.dissipated_energy);
}

// While the loading goes on, points that slipped start an increment holding their slip; where it turns (V back
// after V out) they start free, so that the plain law sticks them as they unload (docs/theory.md, "Newton with
// contact"). The crossing of the test above, slid 0.2 mm and committed, is moved back by a tenth of its elastic slip.
TEST(ContactSet, SlippingPointsStartFreeWhereTheLoadingTurns) {
  const Mesh mesh = pressed_crossing_mesh();
  ContactSettings settings = enabled_contact();
  settings.friction = 0.3;
  settings.initial_overlap = InitialOverlap::kKeep;
  ContactSet contacts;
  contacts.initialize(mesh, settings);
  const std::size_t crossing = crossing_index(contacts);
  std::vector<NodeState> state = reference_state(mesh);
  contacts.commit(mesh, state);
  contacts.begin_increment(true);
  auto slide = [&](double dz) {
    for (std::size_t n = 0; n < state.size(); ++n)
      if (mesh.nodes[n].wire == 1) state[n].position.z() += dz;
  };
  slide(0.2);
  contacts.evaluate(mesh, state, false);
  ASSERT_EQ(contacts.responses()[crossing].status, ContactStatus::kSlip);
  contacts.commit(mesh, state);
  const ContactPoint& p = contacts.points()[crossing];
  ASSERT_TRUE(p.history.slipping);
  slide(-0.1 * p.allowed_slip);
  contacts.begin_increment(true);  // loading goes on: held in its slip, it slides on at the cone
  EXPECT_EQ(p.friction_mode, FrictionMode::kHeldSlip);
  contacts.evaluate(mesh, state, false);
  EXPECT_EQ(contacts.responses()[crossing].status, ContactStatus::kSlip);
  contacts.begin_increment(false);  // the loading turns: free, the plain law sticks it
  EXPECT_EQ(p.friction_mode, FrictionMode::kFree);
  contacts.evaluate(mesh, state, false);
  const ContactResponse& r = contacts.responses()[crossing];
  EXPECT_EQ(r.status, ContactStatus::kStick);
  EXPECT_NEAR(r.friction.norm(), 0.9 * 0.3 * r.normal_force, 1e-6 * r.normal_force);  // 0.9 of the cone
  contacts.accept_iterate(mesh);
  EXPECT_EQ(p.friction_mode, FrictionMode::kHeldStick);
}

// A frictionless crossing with the contact stabilization resists only the slide since the last converged increment: slid
// 0.2 mm it pushes back k_s 0.2 against the slide; the commit restarts the spring there (the same state then
// carries no tangential force) and reports the energy it held, k_s 0.2^2 / 2; a further 0.1 mm gives k_s 0.1.
TEST(ContactSet, StabilizationResistsOnlyTheSlideWithinAnIncrement) {
  const Mesh mesh = pressed_crossing_mesh();
  ContactSettings settings = enabled_contact();
  settings.stabilization = 1e-4;
  settings.initial_overlap = InitialOverlap::kKeep;
  ContactSet contacts;
  contacts.initialize(mesh, settings);
  const std::size_t crossing = crossing_index(contacts);
  const ContactPoint& p = contacts.points()[crossing];
  ASSERT_EQ(p.mu1, 0.0);
  const double k = p.sliding_stabilization;
  ASSERT_DOUBLE_EQ(k, 1e-4 * p.stiffness.normal);
  std::vector<NodeState> state = reference_state(mesh);
  contacts.commit(mesh, state);
  const double across_is_slave = p.wire_a == 1 ? 1.0 : -1.0;
  auto slide_and_evaluate = [&](double dz) {
    contacts.begin_increment(true);
    for (std::size_t n = 0; n < state.size(); ++n)
      if (mesh.nodes[n].wire == 1) state[n].position.z() += dz;
    contacts.evaluate(mesh, state, false);
    return contacts.responses()[crossing];
  };
  const ContactResponse first = slide_and_evaluate(0.2);
  ASSERT_NE(first.status, ContactStatus::kOpen);
  EXPECT_NEAR(across_is_slave * first.stabilization.z(), -k * 0.2, 1e-9 * k);
  EXPECT_NEAR(first.stabilization.norm(), k * 0.2, 1e-9 * k);
  EXPECT_EQ(first.friction.norm(), 0.0);
  contacts.commit(mesh, state);
  EXPECT_NEAR(contacts.commit_stabilization_energy(), 0.5 * k * 0.2 * 0.2, 1e-9 * k);
  contacts.begin_increment(true);
  contacts.evaluate(mesh, state, false);  // the same state: the spring starts from here
  EXPECT_NEAR(contacts.responses()[crossing].stabilization.norm(), 0.0, 1e-9 * k);
  EXPECT_EQ(p.history.dissipated_energy, 0.0);  // not friction's work
  const ContactResponse second = slide_and_evaluate(0.1);
  EXPECT_NEAR(across_is_slave * second.stabilization.z(), -k * 0.1, 1e-9 * k);
}

// Friction 0.3 with three augmentation rounds; the reference overlaps are kept, so pressed wires carry force at once.
ContactSettings augmented_friction() {
  ContactSettings settings = enabled_contact();
  settings.friction = 0.3;
  settings.initial_overlap = InitialOverlap::kKeep;
  settings.stick_augmentations = 3;
  return settings;
}

// Augmented stick: a round takes a sticking point's elastic slip into its offset, so that at the same state the
// stick force doubles and, with the stick points back together, the force stays (Uzawa's update); a point within
// the tolerance is left alone, and the offset never leaves the cone.
TEST(ContactSet, AugmentationTakesTheStickElasticSlipIntoItsOffset) {
  const Mesh mesh = pressed_crossing_mesh();
  ContactSet contacts;
  contacts.initialize(mesh, augmented_friction());
  const std::size_t crossing = crossing_index(contacts);
  std::vector<NodeState> state = reference_state(mesh);
  contacts.commit(mesh, state);
  const ContactPoint& p = contacts.points()[crossing];
  const double s = p.allowed_slip;
  ASSERT_GT(s, 0.0);
  auto slide_to = [&](double z) {
    std::vector<NodeState> moved = state;
    for (std::size_t n = 0; n < moved.size(); ++n)
      if (mesh.nodes[n].wire == 1) moved[n].position.z() += z;
    contacts.evaluate(mesh, moved, false);
    return contacts.responses()[crossing];
  };
  contacts.begin_increment(true);
  const ContactResponse penalty = slide_to(0.2 * s);
  ASSERT_EQ(penalty.status, ContactStatus::kStick);
  const double force = penalty.friction.norm();
  EXPECT_NEAR(force, 0.3 * penalty.normal_force * 0.2, 1e-6 * penalty.normal_force);
  EXPECT_EQ(contacts.augment_stick(), 1);
  EXPECT_NEAR((p.stick_offset + Vec3(0, 0, p.wire_a == 1 ? 0.2 * s : -0.2 * s)).norm(), 0.0, 1e-9 * s);
  EXPECT_NEAR(slide_to(0.2 * s).friction.norm(), 2 * force, 1e-6 * force);
  const ContactResponse back = slide_to(0.0);  // stick points together again: the force stays
  EXPECT_NEAR(back.friction.norm(), force, 1e-6 * force);
  EXPECT_EQ(contacts.augment_stick(), 0);  // no elastic slip left
  // Held apart as before, the point's separation did not shrink: the round extrapolates (Aitken, at most tenfold),
  // up to the cone, and a point driven on then slides on it.
  slide_to(0.2 * s);
  EXPECT_EQ(contacts.augment_stick(), 1);
  EXPECT_NEAR(p.stick_offset.norm(), s, 1e-12 * s);
  const ContactResponse driven = slide_to(0.4 * s);
  EXPECT_EQ(driven.status, ContactStatus::kSlip);
  EXPECT_NEAR(driven.friction.norm(), 0.3 * driven.normal_force, 1e-9 * driven.normal_force);
  EXPECT_EQ(contacts.augmentation_rounds(), 2);
  // A new increment starts from the committed offset (none: nothing was committed).
  contacts.begin_increment(true);
  EXPECT_TRUE(p.stick_offset.isZero());
}

// The augmented stick acts on every crossing and on the line contacts that carry load: a straight wire crossed by
// two wires and touched along its length by two of its own layer, one of each kind pressed 0.05 mm deep and one
// 0.002 mm (a 25th of its normal force), all slid by a fifth of their elastic slip. Both crossings and the pressed
// line contact take their elastic slip into an offset; the lightly pressed line contact keeps the penalty stick.
TEST(ContactSet, AugmentationLeavesLightlyPressedLineContactsOnThePenaltyStick) {
  Mesh mesh = v_wire_mesh(0.0);
  mesh.add_line("pressed crossing", 2, 0, 0, 2, [](double t) { return std::make_pair(Vec3(-1.95, 20.0 * t - 10.0, 5.0), Mat3::Identity()); });
  mesh.add_line("touching crossing", 2, 1, 0, 2, [](double t) { return std::make_pair(Vec3(-1.998, 20.0 * t - 10.0, 15.0), Mat3::Identity()); });
  auto beside = [](double distance, double side) {  // a wire of the straight wire's layer, at 60 degrees on one side
    return [distance, side](double t) { return std::make_pair(Vec3(0.5 * distance, side * 0.866025 * distance, 20.0 * t), Mat3::Identity()); };
  };
  mesh.add_line("pressed neighbour", 1, 1, 0, 2, beside(1.95, 1.0));
  mesh.add_line("touching neighbour", 1, 2, 0, 2, beside(1.998, -1.0));
  ContactSet contacts;
  contacts.initialize(mesh, augmented_friction());
  std::vector<NodeState> state = reference_state(mesh);
  contacts.commit(mesh, state);
  contacts.begin_increment(true);
  const double s = contacts.points()[0].allowed_slip;
  ASSERT_GT(s, 0.0);
  for (std::size_t n = 0; n < state.size(); ++n)
    if (mesh.nodes[n].wire > 0) state[n].position.z() += 0.2 * s;
  contacts.evaluate(mesh, state, false);
  std::array<double, 5> force{};  // largest normal force on each wire's points (wire 0: none)
  std::array<ContactKind, 5> kind{};
  for (std::size_t i = 0; i < contacts.points().size(); ++i) {
    const ContactPoint& p = contacts.points()[i];
    const ContactResponse& r = contacts.responses()[i];
    if (r.status == ContactStatus::kOpen) continue;
    ASSERT_EQ(std::min(p.wire_a, p.wire_b), 0);
    ASSERT_EQ(r.status, ContactStatus::kStick);
    const int wire = std::max(p.wire_a, p.wire_b);
    force[wire] = std::max(force[wire], r.normal_force);
    kind[wire] = p.kind;
  }
  EXPECT_EQ(kind[1], ContactKind::kPoint);
  EXPECT_EQ(kind[2], ContactKind::kPoint);
  EXPECT_EQ(kind[3], ContactKind::kLine);
  EXPECT_EQ(kind[4], ContactKind::kLine);
  EXPECT_NEAR(force[2] / force[1], 0.04, 0.002);
  EXPECT_NEAR(force[4] / force[3], 0.04, 0.002);
  EXPECT_GT(contacts.augment_stick(), 2);
  for (std::size_t i = 0; i < contacts.points().size(); ++i) {
    const ContactPoint& p = contacts.points()[i];
    if (contacts.responses()[i].status == ContactStatus::kOpen) continue;
    EXPECT_EQ(p.stick_offset.isZero(), std::max(p.wire_a, p.wire_b) == 4) << "point between wires " << p.wire_a << " and " << p.wire_b;
  }
}

// Once one sticking point is above the tolerance, a round updates every sticking point (Uzawa): a crossing slid by
// a fiftieth of its elastic slip, below the tolerance (a twentieth), takes that slip too, exactly, while the one
// above extrapolates (Aitken) in the next round. Alone below the tolerance, it starts no round.
TEST(ContactSet, AugmentationUpdatesEveryStickingPointOnceOneIsAboveTheTolerance) {
  Mesh mesh = v_wire_mesh(0.0);
  mesh.add_line("far crossing", 2, 0, 0, 2, [](double t) { return std::make_pair(Vec3(-1.95, 20.0 * t - 10.0, 5.0), Mat3::Identity()); });
  mesh.add_line("near crossing", 2, 1, 0, 2, [](double t) { return std::make_pair(Vec3(-1.95, 20.0 * t - 10.0, 15.0), Mat3::Identity()); });
  ContactSet contacts;
  contacts.initialize(mesh, augmented_friction());
  const std::vector<NodeState> start = reference_state(mesh);
  contacts.commit(mesh, start);
  contacts.begin_increment(true);
  const double s = contacts.points()[0].allowed_slip;
  ASSERT_GT(s, 0.0);
  auto slide = [&](double far, double near) {
    std::vector<NodeState> state = start;
    for (std::size_t n = 0; n < state.size(); ++n)
      state[n].position.z() += mesh.nodes[n].wire == 1 ? far : mesh.nodes[n].wire == 2 ? near : 0.0;
    contacts.evaluate(mesh, state, false);
  };
  auto offset_of_wire = [&](int wire) {
    for (std::size_t i = 0; i < contacts.points().size(); ++i) {
      const ContactPoint& p = contacts.points()[i];
      if (contacts.responses()[i].status != ContactStatus::kOpen && std::max(p.wire_a, p.wire_b) == wire) return p.stick_offset.norm();
    }
    ADD_FAILURE() << "no closed point on wire " << wire;
    return 0.0;
  };
  slide(0.0, 0.02 * s);
  EXPECT_EQ(contacts.augment_stick(), 0);
  slide(0.2 * s, 0.02 * s);
  EXPECT_EQ(contacts.augment_stick(), 2);
  EXPECT_NEAR(offset_of_wire(1), 0.2 * s, 1e-9 * s);
  EXPECT_NEAR(offset_of_wire(2), 0.02 * s, 1e-9 * s);
  slide(0.2 * s, 0.02 * s);  // both held apart as before: the far one extrapolates to the cone, the near one does not
  EXPECT_EQ(contacts.augment_stick(), 2);
  EXPECT_NEAR(offset_of_wire(1), s, 1e-9 * s);
  EXPECT_NEAR(offset_of_wire(2), 0.04 * s, 1e-9 * s);
}

// Step control: a correction that closes a point its starting iterate had open (or within the smoothing band)
// deeper than kDeepClosing closing depths is cut to where that point just reaches one closing depth, the gap taken
// as linear in the fraction; points already in the penalty regime, and shallow closings, leave it whole.
TEST(ContactSet, StepControlCutsACorrectionThatClosesAnOpenPointDeep) {
  const Mesh mesh = parallel_lines(2, 2, 20, 2.3);  // gap 0.3 mm
  ContactSettings settings = enabled_contact();
  settings.initial_overlap = InitialOverlap::kKeep;
  ContactSet contacts;
  contacts.initialize(mesh, settings);
  ASSERT_FALSE(contacts.points().empty());
  auto slave_moved = [&](double dx) {
    std::vector<NodeState> state = reference_state(mesh);
    for (std::size_t n = 0; n < state.size(); ++n)
      if (mesh.nodes[n].wire == 1) state[n].position.x() += dx;
    return state;
  };
  const double depth = kClosingDepthFraction * 2.0;  // r_a + r_b = 2 mm, no smoothing
  auto fraction_for = [&](double start_dx, double end_dx) {
    contacts.begin_increment(true);
    contacts.evaluate(mesh, slave_moved(start_dx), true);
    contacts.begin_correction();
    contacts.evaluate(mesh, slave_moved(end_dx), false);
    return contacts.admissible_fraction();
  };
  // Open at 0.3 mm, pressed 0.05 mm deep: cut to a depth of 5e-4 mm.
  EXPECT_NEAR(fraction_for(0.0, -0.35), (0.3 + depth) / 0.35, 1e-9);
  // Closing shallower than ten depths (4e-3 mm): whole.
  EXPECT_EQ(fraction_for(0.0, -0.304), 1.0);
  // Already pressed 0.001 mm into the penalty regime, pressed further: whole (its tangent knew it).
  EXPECT_EQ(fraction_for(-0.301, -0.35), 1.0);
  // Within a smoothing band of 0.01 mm the stiffness is partial: a point at +0.005 mm pressed 0.2 mm deep is cut to
  // one band width.
  ContactSettings smoothed = settings;
  smoothed.normal_smoothing = 0.01;
  contacts = ContactSet();
  contacts.initialize(mesh, smoothed);
  EXPECT_NEAR(fraction_for(-0.295, -0.5), (0.005 + 0.01) / 0.205, 1e-9);
  EXPECT_EQ(fraction_for(-0.295, -0.35), 1.0);  // 0.05 mm: five band widths
}

TEST(ContactSet, InitialOverlapIsOffset) {
  const Mesh mesh = parallel_lines(2, 2, 20, 1.9);
  ContactSet contacts;
  contacts.initialize(mesh, enabled_contact());
  std::vector<NodeState> state = reference_state(mesh);
  contacts.evaluate(mesh, state, false);
  // Touching: the 0.1 mm nominal overlap is taken out; what remains is the onset's force at zero gap, k_n s / 4,
  // that of a penetration of a quarter of the onset width s (the default, 1e-5 of the 2 mm diameter).
  const double onset_width = kNormalOnsetPerDiameter * 2.0;
  for (const ContactResponse& r : contacts.responses()) {
    EXPECT_NEAR(r.gap, 0.0, 1e-12);
    EXPECT_NEAR(r.normal_force, normal_force(contacts.points()[0].stiffness.normal, onset_width, 0.0), 1e-9);
    EXPECT_NEAR(r.normal_force, contacts.points()[0].stiffness.normal * onset_width / 4, 1e-9);
  }
  // Pressing 0.01 mm further closes the contacts with the penalty force of 0.01 mm only.
  for (std::size_t n = 0; n < state.size(); ++n)
    if (mesh.nodes[n].wire == 1) state[n].position.x() -= 0.01;
  contacts.evaluate(mesh, state, false);
  for (const ContactResponse& r : contacts.responses()) EXPECT_NEAR(r.gap, -0.01, 1e-9);
}

// The search finds every crossing the helix geometry implies: crossings per layer interface against the helix
// count (tight, away from the ends where crossings are cut off) and against eq. 2.4, which puts both helices on
// R_ct (a few percent off). Lateral (line) contacts only within a layer and between the core and layer 1.
// `layers`: wires, diameter, lay angle in degrees, core first.
void expect_contacts_follow_the_layout(const std::vector<std::array<double, 3>>& layers) {
  StrandSpec strand;
  strand.length = 200;
  strand.materials["steel"] = {188000, 0.3, 0, "steel"};
  const double deg = M_PI / 180;
  const auto directions = default_lay_directions(static_cast<int>(layers.size()));
  for (std::size_t i = 0; i < layers.size(); ++i)
    strand.layers.push_back({static_cast<int>(layers[i][0]), layers[i][1], "steel", layers[i][2] * deg, directions[i], 0});
  const Mesh mesh = mesh_strand(strand, MeshSpec{0, 22});
  ContactSet contacts;
  contacts.initialize(mesh, enabled_contact());
  const std::vector<NodeState> reference = reference_state(mesh);
  for (int layer = 2; layer < static_cast<int>(strand.layers.size()); ++layer) {
    int total = 0, interior = 0;
    for (const ContactPoint& p : contacts.points()) {
      if (p.kind != ContactKind::kPoint || mesh.wires[p.wire_a].layer != layer - 1 || mesh.wires[p.wire_b].layer != layer) continue;
      ++total;
      const auto& nodes = mesh.elements[mesh.wires[p.wire_a].elements[p.element_a]].nodes;
      const double z = reference[nodes[1]].position.z() + 0.5 * p.xi * (reference[nodes[2]].position.z() - reference[nodes[0]].position.z());
      if (z > 0.25 * strand.length && z <= 0.75 * strand.length) ++interior;
    }
    const double helix = radial_contact_count_helix(strand, layer), eq24 = radial_contact_count_eq24(strand, layer);
    EXPECT_NEAR(interior, 0.5 * helix, 0.02 * helix + 2) << "layer " << layer;
    // Ends cut at most one crossing per wire pair.
    EXPECT_NEAR(total, helix, strand.layers[layer].wires * strand.layers[layer - 1].wires) << "layer " << layer;
    EXPECT_NEAR(total / eq24, 1.0, 0.10) << "layer " << layer << ": " << total << " crossings, eq. 2.4 " << eq24;
  }
  for (const ContactPoint& p : contacts.points())
    if (p.kind == ContactKind::kLine)
      EXPECT_TRUE(mesh.wires[p.wire_a].layer == mesh.wires[p.wire_b].layer || (mesh.wires[p.wire_b].layer == 0 && mesh.wires[p.wire_a].layer == 1));
}

// Paper's 120-wire strand (Table 3 geometry), straight.
TEST(ContactSet, RadialCrossingsMatchEquation24) {
  expect_contacts_follow_the_layout({{1, 5.8, 0}, {7, 4.3, 11.94}, {17, 3.2, 14.75}, {14, 5.3, 14.37}, {21, 5.0, 15.23}, {27, 5.0, 15.66}, {33, 5.0, 15.95}});
}

// ACSR Cardinal (Table 5): the steel layer and the first aluminum layer cross at only 18 degrees (6.06 + 11.99),
// and they still touch at crossings (the paper's interface 1-2, Fig. 14), not along lines.
TEST(ContactSet, CardinalSteelAndAluminumLayersCrossAtPoints) {
  expect_contacts_follow_the_layout({{1, 3.34, 0}, {6, 3.34, 6.06}, {12, 3.32, 11.99}, {18, 3.32, 11.80}, {24, 3.32, 13.10}});
}

}  // namespace
}  // namespace strandfem
