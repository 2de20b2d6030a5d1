// Contact kinematics, force law and linearization against finite differences and closed-form limits.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <tuple>

#include "strandfem/contact/contact_set.hpp"

namespace strandfem {
namespace {

using Vector36 = Eigen::Matrix<double, 36, 1>;

// Two slightly curved elements: a along x, b crossing it (angle set by `angle`) just above, overlapping.
// Node rotations differ from node to node so that the section interpolation is exercised.
struct PairFixture {
  ElementPose<double> a, b;
  PairFixture(double angle, double height) {
    a.x = {V3<double>{-1.0, 0.0, 0.0}, V3<double>{0.0, 0.05, 0.02}, V3<double>{1.1, 0.0, 0.0}};
    const double c = std::cos(angle), s = std::sin(angle);
    b.x = {V3<double>{-c, -s, height}, V3<double>{0.03, 0.0, height - 0.03}, V3<double>{c, s, height + 0.02}};
    for (int i = 0; i < 3; ++i) {
      a.q[i] = quat_from_rotation_vector(V3<double>{0.1 * i, -0.05, 0.2 + 0.1 * i});
      b.q[i] = quat_from_rotation_vector(V3<double>{-0.2, 0.1 * i, 0.3 * i});
    }
  }
};

ContactPoint make_point(ContactKind kind) {
  ContactPoint p;
  p.kind = kind;
  p.element_a = 0;
  p.element_b = 0;
  p.radius_a = 1.0;
  p.radius_b = 0.9;
  p.weight = kind == ContactKind::kLine ? 0.7 : 1.0;
  p.stiffness = {1.0e4, 4.0e3};
  p.mu1 = 0.3;
  p.mu2 = 0.3;
  return p;
}

// The poses moved by the increments du (translations) and spins dtheta (6 per node, nodes a0..b2).
std::array<ElementPose<double>, 2> moved(const PairFixture& f, const Vector36& increment) {
  std::array<ElementPose<double>, 2> out{f.a, f.b};
  for (int node = 0; node < 6; ++node) {
    ElementPose<double>& e = out[node / 3];
    const int i = node % 3;
    for (int c = 0; c < 3; ++c) e.x[i][c] += increment[6 * node + c];
    const V3<double> spin{increment[6 * node + 3], increment[6 * node + 4], increment[6 * node + 5]};
    e.q[i] = multiply(quat_from_rotation_vector(spin), e.q[i]);
  }
  return out;
}

// The response after the increment, with the parameters solved there.
// A crossing pinned on one wire (PinnedParameter) keeps that wire's parameter at p.xi (slave) or p.eta (master).
ContactResponse response_at(const ContactPoint& p, const PairFixture& f, const Vector36& increment, bool tangent,
                            const Vec3& axis, PinnedParameter pinned = PinnedParameter::kNone) {
  const auto poses = moved(f, increment);
  const bool slave_fixed = p.kind == ContactKind::kLine || pinned == PinnedParameter::kSlave;
  double xi = slave_fixed ? p.xi : 0.0, eta = pinned == PinnedParameter::kMaster ? p.eta : 0.0;
  bool ok = slave_fixed                            ? project_point(centerline_point(poses[0].x, xi), poses[1].x, eta)
            : pinned == PinnedParameter::kMaster ? project_point(centerline_point(poses[1].x, eta), poses[0].x, xi)
                                                 : closest_points(poses[0].x, poses[1].x, xi, eta);
  EXPECT_TRUE(ok);
  return evaluate_contact(p, poses[0], poses[1], p.element_a, 0, xi, eta, axis, tangent, pinned);
}
ContactResponse response_at(const ContactPoint& p, const PairFixture& f, bool tangent, const Vec3& axis,
                            PinnedParameter pinned = PinnedParameter::kNone) {
  return response_at(p, f, Vector36::Zero(), tangent, axis, pinned);
}

// Central differences of the forces and moments against the exact tangent (translations and spins).
double tangent_error(const ContactPoint& p, const PairFixture& f, const Vec3& axis, ContactStatus expected,
                     PinnedParameter pinned = PinnedParameter::kNone) {
  const ContactResponse r = response_at(p, f, true, axis, pinned);
  EXPECT_EQ(r.status, expected);
  ContactMatrix fd;
  const double h = 1e-6;
  for (int k = 0; k < 36; ++k) {
    Vector36 plus = Vector36::Zero(), minus = Vector36::Zero();
    plus[k] = h;
    minus[k] = -h;
    fd.col(k) = (response_at(p, f, plus, false, axis, pinned).force - response_at(p, f, minus, false, axis, pinned).force) /
                (2 * h);
  }
  return (fd - r.tangent).cwiseAbs().maxCoeff() / r.tangent.cwiseAbs().maxCoeff();
}

// Stick points offset from the current contact point by `offset` in both parameters and turned by
// `turn` (rad) about each wire's section axis 1, as a committed history would hold them.
void set_stick(ContactPoint& p, const PairFixture& f, double offset, double turn = 0.0,
               PinnedParameter pinned = PinnedParameter::kNone) {
  const ContactResponse r = response_at(p, f, false, Vec3::UnitX(), pinned);
  p.history.closed = true;
  p.history.anchored = true;
  p.history.stick_a = wire_coordinate(0, r.xi + offset);
  p.history.stick_b = wire_coordinate(0, r.eta - 0.7 * offset);
  const Eigen::AngleAxisd about_axis(turn, Vec3::UnitX());
  p.history.stick_direction_a = about_axis * section_direction(f.a, r.xi, -r.normal);
  p.history.stick_direction_b = about_axis * section_direction(f.b, r.eta, r.normal);
}

// Friction coefficient lookup: zones over material pairs over the default; pairs in either order.
TEST(ContactSettings, FrictionPerMaterialPairAndAxialZone) {
  constexpr ContactInterface lateral = ContactInterface::kLateral;
  ContactSettings s;
  s.friction = 0.1;
  s.pair_friction = {{"steel", "aluminum", 0.5}};
  s.zone_friction = {{0.0, 20.0, 0.9}};
  EXPECT_DOUBLE_EQ(s.friction_at("steel", "steel", lateral, 50), 0.1);
  EXPECT_DOUBLE_EQ(s.friction_at("aluminum", "steel", lateral, 50), 0.5);
  EXPECT_DOUBLE_EQ(s.friction_at("steel", "aluminum", lateral, 50), 0.5);
  EXPECT_DOUBLE_EQ(s.friction_at("steel", "steel", lateral, 10), 0.9);
  EXPECT_DOUBLE_EQ(s.friction_at("steel", "aluminum", lateral, 20), 0.9);
  // A zone limited to aluminum contacts (the paper's section 5.2): steel-steel keeps its coefficient there.
  s.zone_friction = {{0.0, 20.0, 0.7, {{"aluminum", "aluminum"}, {"aluminum", "steel"}}}};
  EXPECT_DOUBLE_EQ(s.friction_at("steel", "steel", lateral, 10), 0.1);
  EXPECT_DOUBLE_EQ(s.friction_at("steel", "aluminum", lateral, 10), 0.7);
  EXPECT_DOUBLE_EQ(s.friction_at("aluminum", "aluminum", lateral, 10), 0.7);
  EXPECT_DOUBLE_EQ(s.friction_at("aluminum", "aluminum", lateral, 30), 0.1);
}

// The paper's two interfaces (section 2.2): lateral within a layer and from the core to the first layer, radial
// between two helical layers.
TEST(ContactSettings, LateralAndRadialInterfaces) {
  EXPECT_EQ(contact_interface(2, 2), ContactInterface::kLateral);
  EXPECT_EQ(contact_interface(0, 1), ContactInterface::kLateral);
  EXPECT_EQ(contact_interface(1, 0), ContactInterface::kLateral);
  EXPECT_EQ(contact_interface(1, 2), ContactInterface::kRadial);
  EXPECT_EQ(contact_interface(4, 3), ContactInterface::kRadial);
  EXPECT_EQ(contact_interface(-1, -1), ContactInterface::kLateral);  // beam lines outside a strand
}

// Section 5.2 changes mu_a on the radial aluminum contacts only: a zone limited to radial contacts leaves the
// lateral ones at their pair's coefficient, and a pair entry limited to one interface leaves the other alone.
TEST(ContactSettings, ZonesAndPairsLimitedToAnInterface) {
  constexpr ContactInterface lateral = ContactInterface::kLateral, radial = ContactInterface::kRadial;
  ContactSettings s;
  s.friction = 0.5;
  s.pair_friction = {{"steel", "steel", 0.3}};
  s.zone_friction = {{0.0, 100.0, 0.9, {{"aluminum", "aluminum"}}, radial}};
  EXPECT_DOUBLE_EQ(s.friction_at("aluminum", "aluminum", radial, 50), 0.9);
  EXPECT_DOUBLE_EQ(s.friction_at("aluminum", "aluminum", lateral, 50), 0.5);
  EXPECT_DOUBLE_EQ(s.friction_at("aluminum", "aluminum", radial, 150), 0.5);
  s.pair_friction.push_back({"steel", "aluminum", 0.4, std::nullopt, lateral});
  EXPECT_DOUBLE_EQ(s.friction_at("aluminum", "steel", lateral, 150), 0.4);
  EXPECT_DOUBLE_EQ(s.friction_at("aluminum", "steel", radial, 150), 0.5);
  EXPECT_NO_THROW(s.validate());
  s.pair_friction.push_back({"aluminum", "aluminum", std::nullopt, std::nullopt, radial});
  EXPECT_THROW(s.validate(), std::invalid_argument);  // an entry that sets nothing
}

// mu2 / mu1 per material pair over the contact's ratio (Fig. 19: aluminum contacts orthotropic, steel pairs not).
TEST(ContactSettings, OrthotropyPerMaterialPair) {
  constexpr ContactInterface lateral = ContactInterface::kLateral, radial = ContactInterface::kRadial;
  ContactSettings s;
  s.orthotropy_ratio = 10;
  s.pair_friction = {{"steel", "steel", 0.3, 1.0}, {"steel", "aluminum", 0.5}};
  EXPECT_DOUBLE_EQ(s.orthotropy_at("steel", "steel", radial), 1.0);
  EXPECT_DOUBLE_EQ(s.orthotropy_at("aluminum", "steel", radial), 10.0);  // an entry without a ratio takes the contact's
  EXPECT_DOUBLE_EQ(s.orthotropy_at("aluminum", "aluminum", radial), 10.0);
  // The paper defines direction 2 at the radial contact points: lateral aluminum contacts kept isotropic by an
  // entry that sets only their ratio; their coefficient stays the contact's.
  s.pair_friction.push_back({"aluminum", "aluminum", std::nullopt, 1.0, lateral});
  EXPECT_DOUBLE_EQ(s.orthotropy_at("aluminum", "aluminum", lateral), 1.0);
  EXPECT_DOUBLE_EQ(s.orthotropy_at("aluminum", "aluminum", radial), 10.0);
  s.friction = 0.7;
  EXPECT_DOUBLE_EQ(s.friction_at("aluminum", "aluminum", lateral, 0), 0.7);
  s.pair_friction[0].orthotropy_ratio = -1;
  EXPECT_THROW(s.validate(), std::invalid_argument);
}

// Eqs. 2.5-2.6 as documented: point contacts N/mm, line contacts the same divided by d (N/mm^2).
TEST(ContactSettings, PenaltyStiffnessFormulas) {
  ContactSettings s;  // fKn 1, xi_n 10, fKt 50, xi_t 3.75
  const double E = 188000, d = 3.73, h = 8.5, mu = 0.115;
  const PenaltyStiffness point = penalty_stiffness(s, false, E, d, h, mu);
  EXPECT_DOUBLE_EQ(point.normal, E * d * 10);
  EXPECT_DOUBLE_EQ(point.tangential, 50 * mu * E * d * d * 3.75 / h);
  const PenaltyStiffness line = penalty_stiffness(s, true, E, d, h, mu);
  EXPECT_DOUBLE_EQ(line.normal, E * 10);
  EXPECT_NEAR(line.tangential, point.tangential / d, 1e-9 * line.tangential);
}

// The normal onset: 1e-5 of the thinner wire's diameter unless the case sets a width (0: the plain law).
TEST(ContactSettings, NormalOnsetWidthFollowsTheWireSizeUnlessSet) {
  ContactSettings s;
  EXPECT_DOUBLE_EQ(penalty_stiffness(s, false, 188000, 3.5, 10, 0.3).smoothing, 3.5e-5);
  EXPECT_DOUBLE_EQ(penalty_stiffness(s, true, 188000, 5.0, 10, 0.3).smoothing, 5.0e-5);
  s.normal_smoothing = 1e-3;
  EXPECT_DOUBLE_EQ(penalty_stiffness(s, true, 188000, 5.0, 10, 0.3).smoothing, 1e-3);
  s.normal_smoothing = 0.0;
  EXPECT_DOUBLE_EQ(penalty_stiffness(s, true, 188000, 5.0, 10, 0.3).smoothing, 0.0);
  s.normal_smoothing = -1e-3;
  EXPECT_THROW(s.validate(), std::invalid_argument);
}

TEST(ContactKinematics, ClosestPointsOfCrossingLines) {
  ElementCenterline<double> a = {V3<double>{-1, 0, 0}, V3<double>{0, 0, 0}, V3<double>{1, 0, 0}};
  ElementCenterline<double> b = {V3<double>{0.3, -1, 2}, V3<double>{0.3, 0, 2}, V3<double>{0.3, 1, 2}};
  double xi = 0, eta = 0.5;
  ASSERT_TRUE(closest_points(a, b, xi, eta));
  EXPECT_NEAR(xi, 0.3, 1e-12);
  EXPECT_NEAR(eta, 0.0, 1e-12);
}

TEST(ContactKinematics, ProjectionOntoCurvedMasterNearParallel) {
  // Master: a circular arc of radius 20 sampled by a quadratic element; the point projects radially.
  const double radius = 20, half = 0.4;
  ElementCenterline<double> b = {V3<double>{radius * std::cos(-half), radius * std::sin(-half), 0},
                                 V3<double>{radius, 0, 0}, V3<double>{radius * std::cos(half), radius * std::sin(half), 0}};
  const V3<double> p{18.0 * std::cos(0.1), 18.0 * std::sin(0.1), 0.0};
  double eta = 0;
  ASSERT_TRUE(project_point(p, b, eta));
  const V3<double> d = sub(p, centerline_point(b, eta));
  EXPECT_NEAR(dot(d, centerline_tangent(b, eta)), 0.0, 1e-10);
  EXPECT_NEAR(std::atan2(centerline_point(b, eta)[1], centerline_point(b, eta)[0]), 0.1, 2e-3);  // quadratic arc
}

TEST(ContactKinematics, ProjectionPastTheEndLeavesTheElement) {
  ElementCenterline<double> b = {V3<double>{0, 0, 0}, V3<double>{0, 0, 5}, V3<double>{0, 0, 10}};
  double eta = 0;
  ASSERT_TRUE(project_point(V3<double>{1.9, 0, 12.0}, b, eta));
  EXPECT_NEAR(eta, 1.4, 1e-12);  // beyond +1: the neighbouring element holds the foot point
}

TEST(ContactForceLaw, PointContactNormalForceIsThePenaltyLimit) {
  PairFixture f(M_PI / 2, 1.85);
  ContactPoint p = make_point(ContactKind::kPoint);
  const ContactResponse r = response_at(p, f, false, Vec3::UnitX());
  ASSERT_EQ(r.status, ContactStatus::kStick);
  EXPECT_NEAR(r.normal_force, -p.stiffness.normal * r.gap, 1e-9);
  // Equal and opposite nodal forces: no net force, and the slave is pushed away from the master.
  Vec3 on_a = Vec3::Zero(), on_b = Vec3::Zero();
  for (int i = 0; i < 3; ++i) on_a -= r.force.segment<3>(6 * i), on_b -= r.force.segment<3>(18 + 6 * i);
  EXPECT_NEAR((on_a + on_b).norm(), 0.0, 1e-9);
  EXPECT_NEAR(on_a.norm(), r.normal_force, 1e-9);
  EXPECT_LT(on_a.z(), 0.0);
}

TEST(ContactTangent, PointContactFrictionlessStickSlipOrthotropic) {
  const Vec3 axis = Vec3(1.0, 0.3, 0.2).normalized();
  for (double angle : {M_PI / 2, 0.5}) {
    PairFixture f(angle, 1.8);
        ContactPoint p = make_point(ContactKind::kPoint);
    EXPECT_LT(tangent_error(p, f, axis, ContactStatus::kStick), 1e-6) << "frictionless, angle " << angle;
    set_stick(p, f, 0.005, 0.002);
    EXPECT_LT(tangent_error(p, f, axis, ContactStatus::kStick), 1e-6) << "stick, angle " << angle;
    set_stick(p, f, 0.2, 0.1);
    EXPECT_LT(tangent_error(p, f, axis, ContactStatus::kSlip), 1e-6) << "slip, angle " << angle;
    p.mu2 = 0.1;
    EXPECT_LT(tangent_error(p, f, axis, ContactStatus::kSlip), 1e-6) << "orthotropic slip, angle " << angle;
  }
}

// A crossing held at a node where a wire's elements meet at an angle: one parameter fixed, the other wire's
// projected; the tangent still matches finite differences, frictionless, sticking and slipping.
TEST(ContactTangent, CrossingPinnedAtANodeOfEitherWire) {
  const Vec3 axis = Vec3(1.0, 0.3, 0.2).normalized();
  PairFixture f(M_PI / 2, 1.8);
  for (PinnedParameter pinned : {PinnedParameter::kSlave, PinnedParameter::kMaster}) {
    ContactPoint p = make_point(ContactKind::kPoint);
    p.xi = 0.08;  // used when the slave is pinned (the free closest point lies near 0)
    p.eta = -0.06;  // used when the master is pinned
    const int which = static_cast<int>(pinned);
    EXPECT_LT(tangent_error(p, f, axis, ContactStatus::kStick, pinned), 1e-6) << "frictionless, pinned " << which;
    set_stick(p, f, 0.005, 0.002, pinned);
    EXPECT_LT(tangent_error(p, f, axis, ContactStatus::kStick, pinned), 1e-6) << "stick, pinned " << which;
    set_stick(p, f, 0.2, 0.1, pinned);
    EXPECT_LT(tangent_error(p, f, axis, ContactStatus::kSlip, pinned), 1e-6) << "slip, pinned " << which;
  }
}

// The smoothed normal law: C1 at both ends of its band, quadratic inside, exact tangent there.
TEST(ContactForceLaw, SmoothedNormalLawIsC1AndItsTangentExact) {
  const double k = 1e4, s = 0.3, h = 1e-7;
  EXPECT_NEAR(normal_force(k, s, -s), k * s, 1e-9);
  EXPECT_NEAR(normal_force(k, s, -s - h), normal_force(k, s, -s + h), 3 * k * h);
  EXPECT_NEAR((normal_force(k, s, -s + h) - normal_force(k, s, -s - h)) / (2 * h), -k, 1e-3 * k);
  EXPECT_EQ(normal_force(k, s, s), 0.0);
  EXPECT_NEAR((normal_force(k, s, s - h) - normal_force(k, s, s - 2 * h)) / h, 0.0, 1e-3 * k);
  EXPECT_DOUBLE_EQ(normal_force(k, s, 0.0), k * s / 4);
  PairFixture f(M_PI / 2, 1.8);
  ContactPoint p = make_point(ContactKind::kPoint);
  p.stiffness.smoothing = s;
  const ContactResponse r = response_at(p, f, false, Vec3::UnitX());
  ASSERT_GT(r.gap, -s);
  ASSERT_LT(r.gap, s);
  EXPECT_NEAR(r.normal_force, k / (4 * s) * (r.gap - s) * (r.gap - s), 1e-9 * k);
  EXPECT_LT(tangent_error(p, f, Vec3::UnitX(), ContactStatus::kStick), 1e-6);
  set_stick(p, f, 0.2, 0.1);
  EXPECT_LT(tangent_error(p, f, Vec3::UnitX(), ContactStatus::kSlip), 1e-6);
}

// The elastic-slip law: stick stiffness mu P / s from the current pressure, exact tangent in stick and slip;
// a point slides once its elastic slip exceeds s, whatever the pressure.
TEST(ContactTangent, ElasticSlipLaw) {
  PairFixture f(0.5, 1.8);
  ContactPoint p = make_point(ContactKind::kPoint);
  p.allowed_slip = 0.05;
  set_stick(p, f, 0.005, 0.002);
  const ContactResponse stick = response_at(p, f, false, Vec3::UnitX());
  ASSERT_LT(stick.tangential_gap.norm(), p.allowed_slip);
  EXPECT_NEAR(stick.friction.norm(), p.mu1 * stick.normal_force / p.allowed_slip * stick.tangential_gap.norm(), 1e-9);
  EXPECT_LT(tangent_error(p, f, Vec3::UnitX(), ContactStatus::kStick), 1e-6);
  set_stick(p, f, 0.2, 0.1);
  const ContactResponse slip = response_at(p, f, false, Vec3::UnitX());
  ASSERT_GT(slip.tangential_gap.norm(), p.allowed_slip);
  EXPECT_NEAR(slip.friction.norm(), p.mu1 * slip.normal_force, 1e-9 * slip.normal_force);
  EXPECT_LT(tangent_error(p, f, Vec3::UnitX(), ContactStatus::kSlip), 1e-6);
  // Orthotropic (mu2/mu1 = 5, stick stiffness mu_i P / slip per direction), along an oblique axis.
  const Vec3 axis = Vec3(1.0, 0.3, 0.2).normalized();
  p.mu2 = 5.0 * p.mu1;
  set_stick(p, f, 0.005, 0.002);
  EXPECT_LT(tangent_error(p, f, axis, ContactStatus::kStick), 1e-6);
  set_stick(p, f, 0.2, 0.1);
  EXPECT_LT(tangent_error(p, f, axis, ContactStatus::kSlip), 1e-6);
}

// Augmented stick: the offset shifts the trial force by k_t o (projected on the current contact plane), in stick
// and in slip, and the tangent stays exact.
TEST(ContactTangent, AugmentedStickOffset) {
  PairFixture f(0.5, 1.8);
  ContactPoint p = make_point(ContactKind::kPoint);
  p.allowed_slip = 0.05;
  set_stick(p, f, 0.005, 0.002);
  const ContactResponse plain = response_at(p, f, false, Vec3::UnitX());
  p.stick_offset = -plain.tangential_gap;  // one Uzawa round: the same separation now carries twice the force
  const ContactResponse augmented = response_at(p, f, false, Vec3::UnitX());
  EXPECT_NEAR((augmented.friction - 2.0 * plain.friction).norm(), 0.0, 1e-9 * plain.friction.norm());
  EXPECT_LT(tangent_error(p, f, Vec3::UnitX(), ContactStatus::kStick), 1e-6);
  p.stick_offset = -2.0 * p.allowed_slip * plain.tangential_gap.normalized();  // past the cone: slip on the ellipse
  const ContactResponse slip = response_at(p, f, false, Vec3::UnitX());
  EXPECT_NEAR(slip.friction.norm(), p.mu1 * slip.normal_force, 1e-9 * slip.normal_force);
  EXPECT_LT(tangent_error(p, f, Vec3::UnitX(), ContactStatus::kSlip), 1e-6);
}

// contact.friction_direction: slave_wire. Direction 1 of an orthotropic point is the slave wire's tangent projected
// on the contact plane, whatever the strand axis: at a crossing at 90 degrees the strand axis along the master
// would swap the two directions. The direction moves with the slave wire, and the tangent carries its derivative.
TEST(ContactTangent, OrthotropicDirectionAlongTheSlaveWire) {
  PairFixture f(M_PI / 2, 1.8);
  ContactPoint p = make_point(ContactKind::kPoint);
  p.allowed_slip = 0.05;
  p.mu2 = 5.0 * p.mu1;
  p.direction_along_slave_wire = true;
  const Vec3 master_axis = Vec3::UnitY();  // along wire b: the strand-axis reading would take direction 1 there
  set_stick(p, f, 0.2, 0.1);
  const ContactResponse r = response_at(p, f, false, master_axis);
  ASSERT_EQ(r.status, ContactStatus::kSlip);
  const V3<double> t = centerline_tangent(f.a.x, r.xi);
  Vec3 d1 = Vec3(t[0], t[1], t[2]);
  d1 = (d1 - d1.dot(r.normal) * r.normal).normalized();
  const Vec3 d2 = d1.cross(r.normal);
  EXPECT_NEAR(r.q1, r.friction.dot(d1), 1e-12 * r.normal_force);
  EXPECT_NEAR(r.q2, r.friction.dot(d2), 1e-12 * r.normal_force);
  EXPECT_NEAR(std::hypot(r.q1 / p.mu1, r.q2 / p.mu2), r.normal_force, 1e-9 * r.normal_force);
  EXPECT_LT(tangent_error(p, f, master_axis, ContactStatus::kSlip), 1e-6) << "slip";
  set_stick(p, f, 0.005, 0.002);
  EXPECT_LT(tangent_error(p, f, master_axis, ContactStatus::kStick), 1e-6) << "stick";
  // The same point in the strand-axis reading has its directions swapped (direction 1 along the master).
  p.direction_along_slave_wire = false;
  set_stick(p, f, 0.2, 0.1);
  const ContactResponse along_axis = response_at(p, f, false, master_axis);
  EXPECT_GT(std::abs(along_axis.q1 - r.q1), 0.1 * r.normal_force * p.mu1);
  // An isotropic point ignores the setting (the strand axis is used, and the force is the same either way).
  p.mu2 = p.mu1;
  const ContactResponse isotropic_axis = response_at(p, f, false, master_axis);
  p.direction_along_slave_wire = true;
  const ContactResponse isotropic_wire = response_at(p, f, false, master_axis);
  EXPECT_NEAR((isotropic_axis.friction - isotropic_wire.friction).norm(), 0.0, 1e-12);
}

TEST(ContactTangent, LineContactStickSlipOrthotropic) {
  // Slave a nearly parallel to master b (5 degrees), side by side.
  PairFixture f(0.09, 0.0);
  for (auto& n : f.b.x) n[1] += 1.8;
  const Vec3 axis = Vec3(1.0, 0.1, 0.3).normalized();
  ContactPoint p = make_point(ContactKind::kLine);
  p.xi = 0.33;
  EXPECT_LT(tangent_error(p, f, axis, ContactStatus::kStick), 1e-6);
  set_stick(p, f, 0.004, -0.002);
  EXPECT_LT(tangent_error(p, f, axis, ContactStatus::kStick), 1e-6);
  set_stick(p, f, 0.3, 0.2);
  EXPECT_LT(tangent_error(p, f, axis, ContactStatus::kSlip), 1e-6);
  p.mu2 = 0.05;
  EXPECT_LT(tangent_error(p, f, axis, ContactStatus::kSlip), 1e-6);
}

// The contact stabilization (contact.stabilization): a linear spring -k g on the separation of the surface points
// that touched at the last converged increment (the start points), no cone, acting at the surfaces, beside friction
// if any. With the start points on the stick points it is -k g_T; exact tangent, point and line, frictionless,
// sticking and slipping.
TEST(ContactTangent, StabilizationSpring) {
  const Vec3 axis = Vec3(1.0, 0.3, 0.2).normalized();
  PairFixture crossing(0.5, 1.8);
  PairFixture side_by_side(0.09, 0.0);
  for (auto& n : side_by_side.b.x) n[1] += 1.8;
  for (ContactKind kind : {ContactKind::kPoint, ContactKind::kLine}) {
    const PairFixture& f = kind == ContactKind::kPoint ? crossing : side_by_side;
    ContactPoint p = make_point(kind);
    p.xi = 0.33;
    p.sliding_stabilization = 500.0;
    for (auto [offset, turn, status] : {std::tuple{0.005, 0.002, ContactStatus::kStick}, std::tuple{0.2, 0.1, ContactStatus::kSlip}}) {
      set_stick(p, f, offset, turn);
      p.start_set = true;
      p.start_a = p.history.stick_a;
      p.start_b = p.history.stick_b;
      p.start_direction_a = p.history.stick_direction_a;
      p.start_direction_b = p.history.stick_direction_b;
      const ContactResponse r = response_at(p, f, false, axis);
      ASSERT_GT(r.tangential_gap.norm(), 1e-4);
      EXPECT_LT((r.stabilization + p.sliding_stabilization * r.tangential_gap).norm(), 1e-12 * r.stabilization.norm());
      EXPECT_LT(tangent_error(p, f, axis, status), 1e-6) << to_string(kind) << " with friction, offset " << offset;
      ContactPoint frictionless = p;
      frictionless.mu1 = frictionless.mu2 = 0;
      EXPECT_LT((response_at(frictionless, f, false, axis).stabilization - r.stabilization).norm(), 1e-12 * r.stabilization.norm());
      EXPECT_LT(tangent_error(frictionless, f, axis, ContactStatus::kStick), 1e-6) << to_string(kind) << " frictionless";
    }
    p.sliding_stabilization = 0;  // off: no spring whatever the start points
    EXPECT_EQ(response_at(p, f, false, axis).stabilization.norm(), 0.0);
  }
}

// Held friction states (within an increment, see ContactPoint::friction_mode) are smooth force laws with
// exact tangents too; a held slip keeps the magnitude on the ellipse in its held direction.
TEST(ContactTangent, HeldStickAndHeldSlip) {
  PairFixture f(0.5, 1.8);
    const Vec3 axis = Vec3(1.0, 0.3, 0.2).normalized();
  ContactPoint p = make_point(ContactKind::kPoint);
  p.mu2 = 0.15;
  set_stick(p, f, 0.2);  // far outside the cone
  p.friction_mode = FrictionMode::kHeldStick;
  EXPECT_LT(tangent_error(p, f, axis, ContactStatus::kStick), 1e-6);
  p.friction_mode = FrictionMode::kHeldSlip;
  p.slip_direction = {0.6, 0.8, 0.0};
  EXPECT_LT(tangent_error(p, f, axis, ContactStatus::kSlip), 1e-6);
  const ContactResponse r = response_at(p, f, false, axis);
  EXPECT_NEAR(std::hypot(r.q1 / p.mu1, r.q2 / p.mu2), r.normal_force, 1e-9 * r.normal_force);
  const Vec3 in_plane = (Vec3(0.6, 0.8, 0.0) - r.normal.dot(Vec3(0.6, 0.8, 0.0)) * r.normal).normalized();
  EXPECT_NEAR(r.friction.normalized().dot(in_plane), 1.0, 1e-12);
}

// Under the elastic-slip law a held slip lies along the trial force plus kHeldSlipBlend times the held
// direction on the cone (exact tangent too), so a sliding point resists motion across its slip direction:
// with the held direction alone, an outer wire whose crossings all slide could swing sideways freely within
// a Newton correction (S32 under bending, docs/theory.md).
TEST(ContactForceLaw, HeldSlipTurnsWithSidewaysMotionUnderTheElasticSlipLaw) {
  PairFixture f(0.5, 1.8);
  const Vec3 axis = Vec3(1.0, 0.3, 0.2).normalized();
  ContactPoint p = make_point(ContactKind::kPoint);
  p.mu2 = 0.15;
  p.allowed_slip = 0.02;
  set_stick(p, f, 0.05);
  const ContactResponse plain = response_at(p, f, false, axis);
  ASSERT_EQ(plain.status, ContactStatus::kSlip);
  const Vec3 friction_direction = plain.friction.normalized();
  const Vec3 held_direction = Eigen::AngleAxisd(0.3, plain.normal) * friction_direction;
  p.friction_mode = FrictionMode::kHeldSlip;
  p.slip_direction = {held_direction.x(), held_direction.y(), held_direction.z()};
  EXPECT_LT(tangent_error(p, f, axis, ContactStatus::kSlip), 1e-6);
  const ContactResponse r = response_at(p, f, false, axis);
  EXPECT_NEAR(std::hypot(r.q1 / p.mu1, r.q2 / p.mu2), r.normal_force, 1e-9 * r.normal_force);
  const Vec3 n = r.normal, d1 = (axis - axis.dot(n) * n).normalized(), d2 = d1.cross(n);
  const Vec3 held = held_direction - n.dot(held_direction) * n;
  const double held_on_cone = std::hypot(held.dot(d1) / p.mu1, held.dot(d2) / p.mu2);
  const Vec3 expected = r.trial_friction + kHeldSlipBlend * r.normal_force / held_on_cone * held;
  EXPECT_NEAR(r.friction.normalized().dot(expected.normalized()), 1.0, 1e-12);
  // Held along the force itself, then wire b moved across it by 1e-5 mm: the force turns.
  p.slip_direction = {friction_direction.x(), friction_direction.y(), friction_direction.z()};
  p.mu2 = p.mu1;
  const ContactResponse before = response_at(p, f, false, axis);
  const Vec3 across = before.normal.cross(before.friction).normalized();
  Vector36 motion = Vector36::Zero();
  for (int node = 3; node < 6; ++node)
    for (int c = 0; c < 3; ++c) motion[6 * node + c] = 1e-5 * across[c];
  const ContactResponse after = response_at(p, f, motion, false, axis);
  const double stiffness_across = std::abs((after.friction - before.friction).dot(across)) / 1e-5;
  // The plain return's value is mu P k_t / |trial| with k_t = mu P / allowed_slip; the blend keeps
  // |trial| / (|trial| + 0.5 mu P) of it.
  const double k_t = p.mu1 * before.normal_force / p.allowed_slip;
  const double trial = before.trial_friction.norm(), cone = p.mu1 * before.normal_force;
  const double expected_across = cone * k_t / (trial + kHeldSlipBlend * cone);
  EXPECT_NEAR(stiffness_across, expected_across, 0.05 * expected_across);
}

TEST(ContactForceLaw, SlipForceLiesOnTheFrictionEllipse) {
  PairFixture f(M_PI / 2, 1.8);
    const Vec3 axis = Vec3(1.0, 0.3, 0.2).normalized();
  ContactPoint p = make_point(ContactKind::kPoint);
  p.mu2 = 0.12;
  set_stick(p, f, 0.2);
  const ContactResponse r = response_at(p, f, false, axis);
  ASSERT_EQ(r.status, ContactStatus::kSlip);
  EXPECT_NEAR(std::hypot(r.q1 / p.mu1, r.q2 / p.mu2), r.normal_force, 1e-9 * r.normal_force);
}

// Elastic-slip law with mu2/mu1 = 5: a point reaches the cone at the same elastic slip in either direction, and
// the stick force along the strand axis is that of mu1 alone (a stick stiffness set by max(mu1, mu2) had made the
// axial stick five times stiffer, and a wider cone across then gave a larger loop, not a smaller one).
TEST(ContactForceLaw, OrthotropicElasticSlipReachesTheConeAtTheSameSlipInEveryDirection) {
  FrictionLaw law;
  law.mu1 = 0.2;
  law.mu2 = 1.0;
  law.allowed_slip = 0.05;
  const double pressure = 100;
  const V3<double> normal{1.0, 0.0, 0.0}, along{0.0, 0.0, 1.0}, across{0.0, 1.0, 0.0};  // axis z: direction 1 along z
  const V3<double> axis = along;
  for (const auto& [direction, mu] : {std::make_pair(along, law.mu1), std::make_pair(across, law.mu2)}) {
    const auto half = friction_force(law, normal, scale(0.5 * law.allowed_slip, direction), pressure, axis);
    EXPECT_FALSE(half.slipping);
    EXPECT_NEAR(std::sqrt(dot(half.force, half.force)), 0.5 * mu * pressure, 1e-9 * pressure);  // stick: mu P g / s
    const auto beyond = friction_force(law, normal, scale(1.01 * law.allowed_slip, direction), pressure, axis);
    EXPECT_TRUE(beyond.slipping);
    EXPECT_NEAR(std::sqrt(dot(beyond.force, beyond.force)), mu * pressure, 1e-9 * pressure);
    EXPECT_LT(dot(beyond.force, direction), 0.0);  // opposes the slip
  }
}

}  // namespace
}  // namespace strandfem
