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

ContactResponse evaluate_contact(const ContactPoint& point, const ElementCenterline<double>& a,
                                 const ElementCenterline<double>& b, int element_b, double xi, double eta,
                                 const Vec3& axis, bool with_tangent) {
  ContactResponse r;
  r.element_b = element_b;
  r.xi = xi;
  r.eta = eta;
  // Stick points in the parameters of the elements evaluated now (may lie slightly outside [-1, 1]).
  const double stick_xi = point.kind == ContactKind::kLine ? xi : element_parameter(point.history.stick_a, point.element_a);
  const double stick_eta = element_parameter(point.history.stick_b, element_b);
  const ContactForces<double> f = contact_forces<double>(point, a, b, xi, eta, stick_xi, stick_eta, axis);
  r.status = f.status;
  r.gap = f.gap;
  r.normal = Vec3(f.normal[0], f.normal[1], f.normal[2]);
  const V3<double> xb = centerline_point(b, eta);
  r.position = Vec3(xb[0], xb[1], xb[2]) + point.radius_b * r.normal;
  if (f.status == ContactStatus::kOpen) return r;
  r.normal_force = f.normal_force;
  r.q1 = f.q1;
  r.q2 = f.q2;
  r.tangential_gap = Vec3(f.tangential_gap[0], f.tangential_gap[1], f.tangential_gap[2]);
  r.slip_ratio = f.slip_ratio;
  r.friction = Vec3(f.friction[0], f.friction[1], f.friction[2]);
  r.trial_friction = Vec3(f.trial_friction[0], f.trial_friction[1], f.trial_friction[2]);
  for (int i = 0; i < 6; ++i)
    for (int c = 0; c < 3; ++c) r.force[3 * i + c] = f.nodal[i][c];
  if (!with_tangent) return r;
  using D = Dual<double, 18>;
  ElementCenterline<D> ad, bd;
  for (int i = 0; i < 3; ++i)
    for (int c = 0; c < 3; ++c) {
      ad[i][c] = D::variable(a[i][c], 3 * i + c);
      bd[i][c] = D::variable(b[i][c], 9 + 3 * i + c);
    }
  const ContactForces<D> fd = contact_forces<D>(point, ad, bd, xi, eta, stick_xi, stick_eta, axis);
  for (int i = 0; i < 6; ++i)
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 18; ++k) r.tangent(3 * i + c, k) = fd.nodal[i][c].grad[k];
  return r;
}

}  // namespace strandfem
