#include "strandfem/contact/wire_geometry.hpp"

#include <algorithm>
#include <cmath>

#include "strandfem/core/quadrature.hpp"

namespace strandfem::wire_geometry {
namespace {
constexpr double kRangeTolerance = 1e-9;
// A crossing this close to an element end (in the element parameter) is located among the neighbouring elements too.
constexpr double kCrossingEndZone = 0.1;

int element_count(const Mesh& mesh, int wire) { return static_cast<int>(mesh.wires[wire].elements.size()); }
}  // namespace

ElementCenterline<double> centerline(const Mesh& mesh, const std::vector<NodeState>& state, int element) {
  ElementCenterline<double> x;
  for (int i = 0; i < 3; ++i) {
    const Vec3& p = state[mesh.elements[element].nodes[i]].position;
    x[i] = {p[0], p[1], p[2]};
  }
  return x;
}

Vec3 to_vec(const V3<double>& v) { return Vec3(v[0], v[1], v[2]); }

ElementPose<double> pose(const Mesh& mesh, const std::vector<NodeState>& state, int element) {
  ElementPose<double> e;
  e.x = centerline(mesh, state, element);
  for (int i = 0; i < 3; ++i) {
    const Quaternion& q = state[mesh.elements[element].nodes[i]].rotation;
    e.q[i] = {q.w(), q.x(), q.y(), q.z()};
  }
  return e;
}

int local_index(const Mesh& mesh, int element) {
  return element - mesh.wires[mesh.elements[element].wire].elements.front();
}

bool in_range(double parameter, int local) {
  const bool above_start = parameter > -1.0 + kRangeTolerance || (local == 0 && parameter >= -1.0 - kRangeTolerance);
  return above_start && parameter <= 1.0 + kRangeTolerance;
}

double arc_length(const ElementCenterline<double>& x) {
  std::vector<double> gp, gw;
  gauss_legendre(4, gp, gw);
  double length = 0;
  for (int i = 0; i < 4; ++i) {
    const V3<double> t = centerline_tangent(x, gp[i]);
    length += gw[i] * std::sqrt(dot(t, t));
  }
  return length;
}

FootPoint project_onto_wire(const Mesh& mesh, const std::vector<NodeState>& state, int wire,
                            const std::vector<int>& candidates, const V3<double>& x, int guess_element, double guess_eta) {
  FootPoint best;
  for (int k : candidates) {
    const auto b = centerline(mesh, state, mesh.wires[wire].elements[k]);
    double eta = k == guess_element ? guess_eta : 0.0;
    if (!project_point(x, b, eta) || !in_range(eta, k)) continue;
    const V3<double> d = sub(x, centerline_point(b, eta));
    const double distance = std::sqrt(dot(d, d));
    if (distance < best.distance) best = {k, eta, distance};
  }
  return best;
}

CrossingLocation locate_crossing(const Mesh& mesh, const std::vector<NodeState>& state, const ContactPoint& p) {
  const int count_a = element_count(mesh, p.wire_a), count_b = element_count(mesh, p.wire_b);
  auto line = [&](int wire, int local) { return centerline(mesh, state, mesh.wires[wire].elements[local]); };
  auto inside = [](double parameter) { return std::abs(parameter) <= 1.0 + kRangeTolerance; };
  {
    double xi = p.xi, eta = p.eta;
    if (closest_points(line(p.wire_a, p.element_a), line(p.wire_b, p.element_b), xi, eta) &&
        std::abs(xi) <= 1.0 - kCrossingEndZone && std::abs(eta) <= 1.0 - kCrossingEndZone)
      return {p.element_a, p.element_b, xi, eta, PinnedParameter::kNone, 0.0};
  }
  CrossingLocation best;
  bool beyond_wire_end = false;  // the nearest pair of points lies past a wire's first or last node
  auto consider = [&](int ea, int eb, double xi, double eta, PinnedParameter pinned, const V3<double>& xa, const V3<double>& xb,
                      bool past_end = false) {
    const V3<double> d = sub(xa, xb);
    const double distance = std::sqrt(dot(d, d));
    if (distance < best.distance) {
      best = {ea, eb, xi, eta, pinned, distance};
      beyond_wire_end = past_end;
    }
  };
  auto past_wire_end = [&](int local, double parameter, int count) {
    return (local == 0 && parameter < -1.0 - kRangeTolerance) || (local == count - 1 && parameter > 1.0 + kRangeTolerance);
  };
  const int first_a = std::max(0, p.element_a - 1), last_a = std::min(count_a - 1, p.element_a + 1);
  const int first_b = std::max(0, p.element_b - 1), last_b = std::min(count_b - 1, p.element_b + 1);
  for (int ea = first_a; ea <= last_a; ++ea) {
    const auto a = line(p.wire_a, ea);
    for (int eb = first_b; eb <= last_b; ++eb) {
      const auto b = line(p.wire_b, eb);
      double xi = std::clamp(p.xi - 2.0 * (ea - p.element_a), -1.0, 1.0), eta = std::clamp(p.eta - 2.0 * (eb - p.element_b), -1.0, 1.0);
      if (closest_points(a, b, xi, eta)) {
        const bool past_end = past_wire_end(ea, xi, count_a) || past_wire_end(eb, eta, count_b);
        // Past a wire's end there is no wire to touch: the crossing is open there if that is where it lies.
        if ((inside(xi) && inside(eta)) || (past_end && std::abs(xi) < 1.5 && std::abs(eta) < 1.5))
          consider(ea, eb, xi, eta, PinnedParameter::kNone, centerline_point(a, xi), centerline_point(b, eta), past_end);
      }
      // Shared nodes: the end (parameter 1) of each element of the neighbourhood but its last.
      if (ea < last_a) {
        const V3<double> node = centerline_point(a, 1.0);
        double projected = eta;
        if (project_point(node, b, projected) && inside(projected))
          consider(ea, eb, 1.0, projected, PinnedParameter::kSlave, node, centerline_point(b, projected));
        if (eb < last_b) consider(ea, eb, 1.0, 1.0, PinnedParameter::kBoth, node, centerline_point(b, 1.0));
      }
      if (eb < last_b) {
        const V3<double> node = centerline_point(b, 1.0);
        double projected = xi;
        if (project_point(node, a, projected) && inside(projected))
          consider(ea, eb, projected, 1.0, PinnedParameter::kMaster, centerline_point(a, projected), node);
      }
    }
  }
  if (beyond_wire_end) return CrossingLocation{};
  return best;
}

}  // namespace strandfem::wire_geometry
