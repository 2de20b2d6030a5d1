#include "strandfem/contact/contact_point.hpp"

namespace strandfem {

const char* to_string(ContactKind kind) { return kind == ContactKind::kLine ? "line" : "point"; }
const char* to_string(ContactStatus status) {
  switch (status) {
    case ContactStatus::kOpen: return "open";
    case ContactStatus::kStick: return "stick";
    case ContactStatus::kSlip: return "slip";
  }
  return "?";
}

bool project_point(const V3<double>& p, const ElementCenterline<double>& b, double& eta) {
  for (int k = 0; k < 30; ++k) {
    const double next = projection_newton_step(p, b, eta);
    if (!std::isfinite(next) || std::abs(next) > 10.0) return false;
    const double step = next - eta;
    eta = next;
    if (std::abs(step) < 1e-13) return true;
  }
  return false;
}

bool closest_points(const ElementCenterline<double>& a, const ElementCenterline<double>& b, double& xi, double& eta) {
  for (int k = 0; k < 40; ++k) {
    const auto next = closest_points_newton_step(a, b, xi, eta);
    if (!std::isfinite(next[0]) || !std::isfinite(next[1]) || std::abs(next[0]) > 10.0 || std::abs(next[1]) > 10.0)
      return false;
    const double step = std::abs(next[0] - xi) + std::abs(next[1] - eta);
    xi = next[0];
    eta = next[1];
    if (step < 1e-13) return true;
  }
  return false;
}

namespace {

// The poses with dual numbers: positions x + du and rotations exp(dtheta^) q, with (du, dtheta) of node k
// (a0..b2) as variables 6k..6k+5, or only du as variables 3k..3k+2 when rotations do not enter.
template <int N>
std::array<ElementPose<Dual<double, N>>, 2> lift_poses(const ElementPose<double>& a, const ElementPose<double>& b) {
  using D = Dual<double, N>;
  constexpr bool spins = N == 36;
  std::array<ElementPose<D>, 2> out;
  for (int e = 0; e < 2; ++e) {
    const ElementPose<double>& source = e == 0 ? a : b;
    for (int i = 0; i < 3; ++i) {
      const int node = 3 * e + i;
      V3<D> spin{D(0.0), D(0.0), D(0.0)};
      for (int c = 0; c < 3; ++c) {
        out[e].x[i][c] = D::variable(source.x[i][c], spins ? 6 * node + c : 3 * node + c);
        if (spins) spin[c] = D::variable(0.0, 6 * node + 3 + c);
      }
      const Quat<double>& q = source.q[i];
      out[e].q[i] = multiply(quat_from_rotation_vector(spin), Quat<D>{D(q.w), D(q.x), D(q.y), D(q.z)});
    }
  }
  return out;
}

template <int N>
void fill_tangent(const ContactForces<Dual<double, N>>& f, ContactMatrix& tangent) {
  constexpr bool spins = N == 36;
  for (int row = 0; row < 36; ++row) {
    const auto& entry = f.nodal[row / 3][row % 3];
    for (int k = 0; k < N; ++k) tangent(row, spins ? k : 6 * (k / 3) + k % 3) = entry.grad[k];
  }
}

}  // namespace

Vec3 section_direction(const ElementPose<double>& e, double xi, const Vec3& outward) {
  const V3<double> m = transpose_times(rotation_matrix(section_rotation(e.q, xi)), V3<double>{outward.x(), outward.y(), outward.z()});
  return Vec3(m[0], m[1], m[2]).normalized();
}

void reset_response(ContactResponse& r, int element_a, int element_b, double xi, double eta) {
  r.status = ContactStatus::kOpen;
  r.element_a = element_a;
  r.element_b = element_b;
  r.xi = xi;
  r.eta = eta;
  r.gap = 0;
  r.normal_force = 0;
  r.normal.setZero();
  r.position.setZero();
  r.q1 = r.q2 = 0;
  r.tangential_gap.setZero();
  r.slip_ratio = 1;
  r.friction.setZero();
  r.trial_friction.setZero();
  r.stabilization.setZero();
  r.force.setZero();
}

ContactResponse evaluate_contact(const ContactPoint& point, const ElementPose<double>& a, const ElementPose<double>& b,
                                 int element_a, int element_b, double xi, double eta, const Vec3& axis, bool with_tangent,
                                 PinnedParameter pinned) {
  ContactResponse r;
  evaluate_contact_into(point, a, b, element_a, element_b, xi, eta, axis, with_tangent, pinned, r);
  return r;
}

void evaluate_contact_into(const ContactPoint& point, const ElementPose<double>& a, const ElementPose<double>& b,
                           int element_a, int element_b, double xi, double eta, const Vec3& axis, bool with_tangent,
                           PinnedParameter pinned, ContactResponse& r) {
  reset_response(r, element_a, element_b, xi, eta);
  // Stick points in the parameters of the elements evaluated now (may lie slightly outside [-1, 1]).
  StickAnchor anchor;
  anchor.xi = point.kind == ContactKind::kLine ? xi : element_parameter(point.history.stick_a, element_a);
  anchor.eta = element_parameter(point.history.stick_b, element_b);
  anchor.direction_a = point.history.stick_direction_a;
  anchor.direction_b = point.history.stick_direction_b;
  anchor.start_xi = point.kind == ContactKind::kLine ? xi : element_parameter(point.start_a, element_a);
  anchor.start_eta = element_parameter(point.start_b, element_b);
  anchor.start_direction_a = point.start_direction_a;
  anchor.start_direction_b = point.start_direction_b;
  const ContactForces<double> f = contact_forces<double>(point, a, b, xi, eta, anchor, axis, pinned);
  r.status = f.status;
  r.gap = f.gap;
  r.normal = Vec3(f.normal[0], f.normal[1], f.normal[2]);
  const V3<double> xb = centerline_point(b.x, eta);
  r.position = Vec3(xb[0], xb[1], xb[2]) + point.radius_b * r.normal;
  if (f.status == ContactStatus::kOpen) return;
  r.normal_force = f.normal_force;
  r.q1 = f.q1;
  r.q2 = f.q2;
  r.tangential_gap = Vec3(f.tangential_gap[0], f.tangential_gap[1], f.tangential_gap[2]);
  r.slip_ratio = f.slip_ratio;
  r.friction = Vec3(f.friction[0], f.friction[1], f.friction[2]);
  r.trial_friction = Vec3(f.trial_friction[0], f.trial_friction[1], f.trial_friction[2]);
  r.stabilization = Vec3(f.stabilization[0], f.stabilization[1], f.stabilization[2]);
  for (int i = 0; i < 12; ++i)
    for (int c = 0; c < 3; ++c) r.force[3 * i + c] = f.nodal[i][c];
  if (!with_tangent) return;
  // Rotations enter only through friction or the stabilization (surface points, moment arms): without them,
  // translations suffice.
  if (carries_tangential_force(point)) {
    const auto poses = lift_poses<36>(a, b);
    fill_tangent<36>(contact_forces(point, poses[0], poses[1], xi, eta, anchor, axis, pinned), r.tangent);
  } else {
    r.tangent.setZero();  // the spin columns stay zero
    const auto poses = lift_poses<18>(a, b);
    fill_tangent<18>(contact_forces(point, poses[0], poses[1], xi, eta, anchor, axis, pinned), r.tangent);
  }
}

}  // namespace strandfem
