// Centerline kinematics of quadratic beam elements for contact: interpolation and closest-point projections.
#pragma once
#include <array>
#include <cmath>

#include "strandfem/core/dual.hpp"
#include "strandfem/core/rotation.hpp"
#include "strandfem/core/types.hpp"

namespace strandfem {

// Nodal centerline positions of one 3-node element (end, middle, end).
template <class T>
using ElementCenterline = std::array<V3<T>, 3>;
// Nodal section rotations of one element (map the reference section axes to the current ones).
template <class T>
using ElementRotations = std::array<Quat<T>, 3>;

// Centerline and section rotations of one element: what contact needs to place points on the wire surface.
template <class T>
struct ElementPose {
  ElementCenterline<T> x;
  ElementRotations<T> q;
};

// x(xi), x'(xi), x''(xi) of the quadratic Lagrange interpolation; xi may be a dual number.
template <class T, class S>
V3<T> centerline_point(const ElementCenterline<T>& x, const S& xi) {
  const S n0 = 0.5 * xi * (xi - 1.0), n1 = 1.0 - xi * xi, n2 = 0.5 * xi * (xi + 1.0);
  V3<T> r;
  for (int c = 0; c < 3; ++c) r[c] = n0 * x[0][c] + n1 * x[1][c] + n2 * x[2][c];
  return r;
}
template <class T, class S>
V3<T> centerline_tangent(const ElementCenterline<T>& x, const S& xi) {
  const S d0 = xi - 0.5, d1 = -2.0 * xi, d2 = xi + 0.5;
  V3<T> r;
  for (int c = 0; c < 3; ++c) r[c] = d0 * x[0][c] + d1 * x[1][c] + d2 * x[2][c];
  return r;
}
template <class T>
V3<T> centerline_curvature(const ElementCenterline<T>& x) {
  V3<T> r;
  for (int c = 0; c < 3; ++c) r[c] = x[0][c] - 2.0 * x[1][c] + x[2][c];
  return r;
}

// Shape function values at xi (the weights that spread a point force onto the three nodes).
template <class S>
std::array<S, 3> centerline_shape(const S& xi) {
  return {0.5 * xi * (xi - 1.0), 1.0 - xi * xi, 0.5 * xi * (xi + 1.0)};
}

// Section rotation at xi, interpolated as the beam element does (rotation vectors relative to the middle
// node, Crisfield & Jelenic): a rigid rotation of the element rotates it exactly.
template <class T>
Quat<T> section_rotation(const ElementRotations<T>& q, double xi) {
  const auto n = centerline_shape(xi);
  const Quat<T> middle_inverse = conjugate(q[1]);
  const V3<T> psi = add(scale(n[0], rotation_vector_from_quat(multiply(middle_inverse, q[0]))),
                        scale(n[2], rotation_vector_from_quat(multiply(middle_inverse, q[2]))));
  return multiply(q[1], quat_from_rotation_vector(psi));
}

// R(q) v.
template <class T>
V3<T> rotate(const Quat<T>& q, const V3<T>& v) {
  const auto R = rotation_matrix(q);
  return {dot(R[0], v), dot(R[1], v), dot(R[2], v)};
}

// Material point on the wire surface: the centerline point at xi plus radius times the section-fixed unit
// direction `direction` (in the reference section axes) turned by the section rotation there.
template <class T>
V3<T> surface_point(const ElementPose<T>& e, double xi, double radius, const Vec3& direction) {
  const V3<T> m{T(direction[0]), T(direction[1]), T(direction[2])};
  return add(centerline_point(e.x, xi), scale(radius, rotate(section_rotation(e.q, xi), m)));
}

// One Newton step of the orthogonal projection of point p onto the curve b: solves (p - b(eta)).b'(eta) = 0.
// Run in doubles to convergence, then once in dual numbers to get exact derivatives of eta.
template <class T, class S>
S projection_newton_step(const V3<T>& p, const ElementCenterline<T>& b, const S& eta) {
  const V3<T> d = sub(p, centerline_point(b, eta));
  const V3<T> tb = centerline_tangent(b, eta);
  const V3<T> cb = centerline_curvature(b);
  const T residual = dot(d, tb);
  const T slope = dot(d, cb) - dot(tb, tb);
  return eta - residual / slope;
}

// One Newton step for the closest points (xi on a, eta on b) of two curves:
// (a(xi) - b(eta)).a'(xi) = 0 and (a(xi) - b(eta)).b'(eta) = 0.
template <class T, class S>
std::array<S, 2> closest_points_newton_step(const ElementCenterline<T>& a, const ElementCenterline<T>& b, const S& xi,
                                            const S& eta) {
  const V3<T> d = sub(centerline_point(a, xi), centerline_point(b, eta));
  const V3<T> ta = centerline_tangent(a, xi), tb = centerline_tangent(b, eta);
  const V3<T> ca = centerline_curvature(a), cb = centerline_curvature(b);
  const T r1 = dot(d, ta), r2 = dot(d, tb);
  const T j11 = dot(ta, ta) + dot(d, ca), j12 = -dot(ta, tb);
  const T j21 = dot(ta, tb), j22 = dot(d, cb) - dot(tb, tb);
  const T det = j11 * j22 - j12 * j21;
  return {xi - (j22 * r1 - j12 * r2) / det, eta - (-j21 * r1 + j11 * r2) / det};
}

// Converged projection parameter in doubles; returns false if Newton fails (parallel-to-normal geometry).
bool project_point(const V3<double>& p, const ElementCenterline<double>& b, double& eta);
// Converged closest-point parameters in doubles; returns false for parallel centerlines or divergence.
bool closest_points(const ElementCenterline<double>& a, const ElementCenterline<double>& b, double& xi, double& eta);

}  // namespace strandfem
