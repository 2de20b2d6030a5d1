// One beam-to-beam contact point (a slave Gauss point in line contact, or a crossing in point contact):
// its fixed data, its committed history, and the penalty/Coulomb force law with its exact linearization.
#pragma once
#include <algorithm>
#include <array>

#include <Eigen/Core>

#include "strandfem/contact/contact_kinematics.hpp"
#include "strandfem/contact/contact_settings.hpp"
#include "strandfem/contact/friction.hpp"
#include "strandfem/core/types.hpp"
#include "strandfem/interaction/interaction.hpp"

namespace strandfem {

enum class ContactKind { kLine, kPoint };
using ContactVector = PairVector;
using ContactMatrix = PairMatrix;
constexpr double kContactActivation = 1e-9;  // closed when gap <= this x (r_a + r_b)
constexpr double kActiveSeparationLimit = 0.05;  // an active point beyond this gap x (r_a + r_b) opens at once
// Step control (ContactSet::admissible_fraction): the closing depth of a point is the normal onset width, and at
// least this fraction of r_a + r_b (9e-4 mm for S32's 3.5-mm wires: 6 kN at a crossing, 1.6 kN/mm along a line
// contact, above what S32 carries under bending); a correction that closes a point deeper than kDeepClosing
// closing depths is shortened.
constexpr double kClosingDepthFraction = 2.5e-4;
constexpr double kDeepClosing = 10.0;
inline double closing_depth(double smoothing, double radius_sum) { return std::max(smoothing, kClosingDepthFraction * radius_sum); }
const char* to_string(ContactKind kind);
const char* to_string(ContactStatus status);

// Wire material coordinate: element index within the wire plus (xi + 1) / 2, so it runs 0..elements.
inline double wire_coordinate(int element_in_wire, double xi) { return element_in_wire + 0.5 * (xi + 1.0); }
inline double element_parameter(double coordinate, int element_in_wire) { return 2.0 * (coordinate - element_in_wire) - 1.0; }

// History of a contact point; written only when an increment converges.
struct ContactHistory {
  bool closed = false;             // in contact at the last converged state
  double stick_a = 0, stick_b = 0; // wire coordinates of the stick points on the slave (a) and master (b)
  // The stick points are on the wire surfaces: unit directions from the centerline to the surface point,
  // fixed in each wire's section (reference section axes), so that a wire rolling or turning about its
  // own axis slides its surface over the neighbour's.
  Vec3 stick_direction_a = Vec3::Zero(), stick_direction_b = Vec3::Zero();
  double slip = 0;                 // accumulated slip, mm
  double slip_since_reversal = 0;  // slip since the slip direction last reversed, mm
  double dissipated_energy = 0;    // work of friction over the slip, N mm (a line point: over its weight's length)
  Vec3 slip_direction = Vec3::Zero();
  bool anchored = false;           // stick points set (also while open: where the wires face each other)
  bool slipping = false;           // slipping at the last converged state (friction along -slip_direction):
                                   // the next increment starts by holding that slip
  // Augmented stick: the elastic slip that carries the stick force with the stick points in place; the trial
  // force is -k_t (g_T - stick_offset), g_T the stick points' separation. Zero without augmentation.
  Vec3 stick_offset = Vec3::Zero();
};

// Fixed data of a contact point plus its committed history. Line points keep xi (their Gauss point) and
// pick their master element per evaluation among the group's candidates; point contacts are located at each
// evaluation around the element pair of their last converged location (ContactSet).
struct ContactPoint {
  ContactKind kind = ContactKind::kPoint;
  int wire_a = -1, wire_b = -1;    // slave, master
  int element_a = -1;              // index within wire a
  int element_b = -1;              // index within wire b (point contacts; line: last converged master element)
  int group = -1;                  // line contacts: index of the (slave element, master wire) group
  double xi = 0, eta = 0;          // last converged parameters (line: xi is the Gauss point)
  double weight = 1;               // line: Gauss weight x reference half length (mm); point: 1
  double radius_a = 0, radius_b = 0;
  double gap_offset = 0;           // subtracted from the gap: the reference overlap (<= 0) or 0
  PenaltyStiffness stiffness;
  double mu1 = 0, mu2 = 0;         // along friction direction 1 and across
  // Direction 1 of an orthotropic point (mu2 != mu1) is the slave wire's tangent at the point projected on the
  // contact plane (contact.friction_direction: slave_wire) instead of the strand axis: it turns with the wire.
  bool direction_along_slave_wire = false;
  double allowed_slip = 0;         // elastic-slip law: slip (mm) at which the stick force reaches the cone; 0: eq. 2.6
  // contact.stabilization: stiffness (units of the normal penalty) of the tangential spring on the motion since
  // the last converged increment; 0: none.
  double sliding_stabilization = 0;
  // Where the point was at the last converged increment (the spring's anchors): wire coordinates and
  // section-fixed surface directions, as the stick points. Rewritten at every commit (and on restore), never by
  // a cut-back. Not history: friction's stick points are.
  bool start_set = false;
  double start_a = 0, start_b = 0;
  Vec3 start_direction_a = Vec3::Zero(), start_direction_b = Vec3::Zero();
  ContactHistory history;
  // Working active set of the current increment (not history). An active point keeps its penalty force
  // P = -k_n g even when the gap opens (tension) until Newton has converged; only then are tensile points
  // released. Without it, wires lifted off by an iteration's second-order motion fall through in the next.
  bool active = false;
  int normal_switches = 0;         // releases and re-activations in this increment; past a few, the point
                                   // keeps its state (a zero-pressure point would chatter about g = 0)
  // Same for friction: after the first iterate of an increment each closed point is held in the state the
  // plain law gives it (stick, or slip in a fixed direction) while Newton converges; then ContactSet
  // switches the points whose trial force disagrees and Newton goes on. Stops stick/slip cycling.
  FrictionMode friction_mode = FrictionMode::kFree;
  Vec3 stick_offset = Vec3::Zero();  // working value of history.stick_offset: augmentation rounds change it
  Vec3 last_augmented_slip = Vec3::Zero();  // the elastic slip the last augmentation round of this increment took
  int friction_switches = 0;       // switches in this increment; past kMaxFrictionSwitches the plain law
  V3<double> slip_direction{0.0, 0.0, 0.0};  // held slip: unit direction of the friction force on the slave
};

// Whether a point carries a tangential force: friction (from its stick points) or the stabilization (from its
// start points). Both act at the wire surfaces, so rotations enter.
inline bool frictional(const ContactPoint& p) { return p.history.anchored && p.mu1 > 0; }
inline bool stabilized(const ContactPoint& p) { return p.start_set && p.sliding_stabilization > 0; }
inline bool carries_tangential_force(const ContactPoint& p) { return frictional(p) || stabilized(p); }

// Result of evaluating one contact point at a given state.
struct ContactResponse {
  ContactStatus status = ContactStatus::kOpen;
  int element_a = -1;              // slave element (index within wire a) used
  int element_b = -1;              // master element (index within wire b) used
  double xi = 0, eta = 0;
  double gap = 0;                  // mm, after the overlap offset
  double normal_force = 0;         // P: N (point) or N/mm (line)
  Vec3 normal = Vec3::Zero();      // from master to slave
  Vec3 position = Vec3::Zero();    // contact point on the master surface
  double q1 = 0, q2 = 0;           // friction on the slave along directions 1 and 2: N or N/mm
  Vec3 tangential_gap = Vec3::Zero();  // elastic + trial slip vector of the slave relative to the master, mm
                                       // (less the stick offset of an augmented stick)
  double slip_ratio = 1;           // P / ||Q_trial||_mu (> 1: the trial lies inside the friction cone)
  Vec3 friction = Vec3::Zero();        // friction force on the slave: N or N/mm
  Vec3 trial_friction = Vec3::Zero();  // the elastic trial -k_t g_T
  Vec3 stabilization = Vec3::Zero();   // the stabilization's spring force on the slave (N or N/mm)
  // Internal nodal forces and moments of the six nodes a0, a1, a2, b0, b1, b2 (6 per node: force, moment)
  // and their exact derivative with respect to (displacement, spin) increments of those nodes.
  ContactVector force = ContactVector::Zero();
  ContactMatrix tangent = ContactMatrix::Zero();
};

// Stick anchors of a contact point in the parameters of the elements evaluated now: material points on
// the two wire surfaces (parameter along the element, section-fixed direction).
struct StickAnchor {
  double xi = 0, eta = 0;
  Vec3 direction_a = Vec3::Zero(), direction_b = Vec3::Zero();
  // The start points of the stabilization's spring (ContactPoint::start_a...), likewise.
  double start_xi = 0, start_eta = 0;
  Vec3 start_direction_a = Vec3::Zero(), start_direction_b = Vec3::Zero();
};

// Normal force for gap g: the penalty law -k_n g, or with smoothing s > 0 the C1 law that sets in
// quadratically, k_n (g - s)^2 / (4 s) for |g| < s, zero beyond s (never a tension).
template <class T>
T normal_force(double stiffness, double smoothing, const T& gap) {
  if (smoothing <= 0.0 || value_of(gap) <= -smoothing) return -stiffness * gap;
  if (value_of(gap) >= smoothing) return T(0.0);
  const T opening = gap - smoothing;
  return stiffness / (4.0 * smoothing) * opening * opening;
}

// Internal nodal forces and moments (a0, a1, a2, b0, b1, b2; entry 2k force, 2k+1 moment of node k) of a
// contact point for the given element poses and converged parameters xi, eta (doubles). T = double for the
// value, a dual number for the tangent (the parameters then get one Newton step in T, which gives their
// exact derivatives).
// Which closest-point parameter of a crossing stays where it was given: at a node where a wire's two elements
// meet at an angle, the closest point of each element lies past its end, and the crossing sits on the node.
enum class PinnedParameter { kNone, kSlave, kMaster, kBoth };

template <class T>
struct ContactForces {
  std::array<V3<T>, 12> nodal;
  T gap{}, normal_force{}, q1{}, q2{};
  V3<T> normal{}, tangential_gap{}, trial_friction{}, friction{}, stabilization{};
  ContactStatus status = ContactStatus::kOpen;
  double slip_ratio = 1;
};

template <class T>
ContactForces<T> contact_forces(const ContactPoint& point, const ElementPose<T>& a, const ElementPose<T>& b, double xi0,
                                double eta0, const StickAnchor& anchor, const Vec3& axis,
                                PinnedParameter pinned = PinnedParameter::kNone) {
  ContactForces<T> out;
  for (auto& f : out.nodal) f = {T(0.0), T(0.0), T(0.0)};
  T xi(xi0), eta(eta0);
  if (point.kind == ContactKind::kPoint && pinned == PinnedParameter::kNone) {
    const auto next = closest_points_newton_step(a.x, b.x, xi, eta);
    xi = next[0];
    eta = next[1];
  } else if (point.kind == ContactKind::kLine || pinned == PinnedParameter::kSlave) {
    eta = projection_newton_step(centerline_point(a.x, xi), b.x, eta);
    xi = T(xi0);
  } else if (pinned == PinnedParameter::kMaster) {
    xi = projection_newton_step(centerline_point(b.x, eta), a.x, xi);
    eta = T(eta0);
  }
  const V3<T> xa = centerline_point(a.x, xi), xb = centerline_point(b.x, eta);
  const V3<T> d = sub(xa, xb);
  const T distance = sqrt(dot(d, d));
  out.normal = scale(1.0 / distance, d);
  out.gap = distance - (point.radius_a + point.radius_b) - point.gap_offset;
  // Touching (gap 0 to round-off, as every offset point is at the start) counts as closed: the first
  // Newton iteration then sees the contact stiffness instead of letting wires fly through each other.
  const double smoothing = point.stiffness.smoothing;
  const double activation = std::max(kContactActivation * (point.radius_a + point.radius_b), smoothing);
  // An active point holds its force in tension only across an iterate's wobble: wires apart by a tenth of their mean
  // radius have separated (or the crossing has left its wires), and -k_n g there would be mega-newtons.
  const bool held_closed = point.active && value_of(out.gap) < kActiveSeparationLimit * (point.radius_a + point.radius_b);
  if (!held_closed && value_of(out.gap) > activation) return out;
  const V3<T>& n = out.normal;
  out.status = ContactStatus::kStick;
  out.normal_force = normal_force(point.stiffness.normal, smoothing, out.gap);
  V3<T> total = scale(out.normal_force, n);
  if (stabilized(point)) {
    // A linear spring, no cone, on the separation of the surface points that touched at the last converged
    // increment: it resists only the motion within an increment (a damper in load time).
    const V3<T> moved = sub(surface_point(a, anchor.start_xi, point.radius_a, anchor.start_direction_a),
                            surface_point(b, anchor.start_eta, point.radius_b, anchor.start_direction_b));
    out.stabilization = scale(-point.sliding_stabilization, sub(moved, scale(dot(n, moved), n)));
    total = add(total, out.stabilization);
  }
  if (frictional(point)) {
    // Tangential gap: the separation of the two surface stick points, projected on the contact plane.
    const V3<T> separation = sub(surface_point(a, anchor.xi, point.radius_a, anchor.direction_a),
                                 surface_point(b, anchor.eta, point.radius_b, anchor.direction_b));
    out.tangential_gap = sub(separation, scale(dot(n, separation), n));
    if (!point.stick_offset.isZero()) {
      const V3<T> offset{T(point.stick_offset.x()), T(point.stick_offset.y()), T(point.stick_offset.z())};
      out.tangential_gap = sub(out.tangential_gap, sub(offset, scale(dot(n, offset), n)));
    }
    const FrictionLaw law{point.mu1, point.mu2, point.stiffness.tangential, point.allowed_slip, point.friction_mode,
                          point.slip_direction};
    const V3<T> reference = point.direction_along_slave_wire && point.mu2 != point.mu1
                                ? centerline_tangent(a.x, xi)
                                : V3<T>{T(axis[0]), T(axis[1]), T(axis[2])};
    const FrictionForce<T> f = friction_force(law, n, out.tangential_gap, out.normal_force, reference);
    out.friction = f.force;
    out.trial_friction = f.trial;
    out.q1 = f.q1;
    out.q2 = f.q2;
    out.slip_ratio = f.slip_ratio;
    if (f.slipping) out.status = ContactStatus::kSlip;
    total = add(total, f.force);
  }
  // Internal force = minus the contact force acting on the node; weight turns per-length into force. The
  // force acts at the surface points x_a - r_a n and x_b + r_b n, so friction also twists both wires:
  // internal moments w N r (n x F) on each (the normal force has no arm).
  const auto na = centerline_shape(xi), nb = centerline_shape(eta);
  const bool tangential = carries_tangential_force(point);
  const V3<T> twist = tangential ? cross(n, add(out.friction, out.stabilization)) : V3<T>{T(0.0), T(0.0), T(0.0)};
  for (int i = 0; i < 3; ++i) {
    out.nodal[2 * i] = scale(-point.weight * na[i], total);
    out.nodal[6 + 2 * i] = scale(point.weight * nb[i], total);
    if (!tangential) continue;
    out.nodal[2 * i + 1] = scale(point.weight * point.radius_a * na[i], twist);
    out.nodal[6 + 2 * i + 1] = scale(point.weight * point.radius_b * nb[i], twist);
  }
  return out;
}

// Value, outputs and (if with_tangent) exact tangent of a contact point.
ContactResponse evaluate_contact(const ContactPoint& point, const ElementPose<double>& a, const ElementPose<double>& b,
                                 int element_a, int element_b, double xi, double eta, const Vec3& axis, bool with_tangent,
                                 PinnedParameter pinned = PinnedParameter::kNone);

// The same into an existing response: every field is rewritten except the tangent, which is written only when
// with_tangent and the point is closed (left as it was otherwise: a strand's responses hold some 30 000 tangents
// of 10 kB, and zeroing and copying them at each evaluation cost more than the contact forces).
void evaluate_contact_into(const ContactPoint& point, const ElementPose<double>& a, const ElementPose<double>& b,
                           int element_a, int element_b, double xi, double eta, const Vec3& axis, bool with_tangent,
                           PinnedParameter pinned, ContactResponse& r);

// An open response at the given parameters: every field but the tangent reset.
void reset_response(ContactResponse& r, int element_a, int element_b, double xi, double eta);

// Section-fixed unit direction from the centerline at xi to the surface point along `outward` (a unit
// vector in space): the stick direction of a point that closes or slides there.
Vec3 section_direction(const ElementPose<double>& e, double xi, const Vec3& outward);

}  // namespace strandfem
