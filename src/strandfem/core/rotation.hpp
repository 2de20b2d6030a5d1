// Rotation algebra on SO(3) (unit quaternions, rotation vectors, right Jacobian), generic in the scalar type.
#pragma once
#include <array>
#include <cmath>

#include "strandfem/core/dual.hpp"

namespace strandfem {

template <class T>
using V3 = std::array<T, 3>;

// Unit quaternion (w, x, y, z): rotates vectors by v' = q v q*.
template <class T>
struct Quat {
  T w{1.0}, x{}, y{}, z{};
};

template <class T>
V3<T> add(const V3<T>& a, const V3<T>& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
template <class T>
V3<T> sub(const V3<T>& a, const V3<T>& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
template <class T, class S>
V3<T> scale(const S& s, const V3<T>& a) { return {s * a[0], s * a[1], s * a[2]}; }
template <class T>
T dot(const V3<T>& a, const V3<T>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
template <class T>
V3<T> cross(const V3<T>& a, const V3<T>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// a b; either may be a constant (Quat<double>), whose parts then multiply as plain numbers.
template <class A, class B>
auto multiply(const Quat<A>& a, const Quat<B>& b) -> Quat<decltype(a.w * b.w)> {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
template <class T>
Quat<T> conjugate(const Quat<T>& q) { return {q.w, -q.x, -q.y, -q.z}; }

// Quaternion of the rotation vector theta (axis times angle). A Taylor series near zero keeps the
// derivatives exact at theta = 0, where the closed form divides by zero.
template <class T>
Quat<T> quat_from_rotation_vector(const V3<T>& theta) {
  const T t2 = dot(theta, theta);
  T w, s;  // w = cos(t/2), s = sin(t/2)/t
  if (value_of(t2) < 1e-10) {
    w = 1.0 - t2 / 8.0 + t2 * t2 / 384.0;
    s = 0.5 - t2 / 48.0 + t2 * t2 / 3840.0;
  } else {
    const T t = sqrt(t2);
    w = cos(0.5 * t);
    s = sin(0.5 * t) / t;
  }
  return {w, s * theta[0], s * theta[1], s * theta[2]};
}

// Rotation vector of a unit quaternion, angle in [0, pi].
template <class T>
V3<T> rotation_vector_from_quat(Quat<T> q) {
  if (value_of(q.w) < 0.0) q = {-q.w, -q.x, -q.y, -q.z};
  const V3<T> v{q.x, q.y, q.z};
  const T s2 = dot(v, v);
  T factor;  // 2 atan2(|v|, w) / |v|
  if (value_of(s2) < 1e-12) {
    const T w2 = q.w * q.w;
    factor = 2.0 / q.w * (1.0 - s2 / (3.0 * w2) + s2 * s2 / (5.0 * w2 * w2));
  } else {
    const T s = sqrt(s2);
    factor = 2.0 * atan2(s, q.w) / s;
  }
  return scale(factor, v);
}

// Rotation matrix columns: R = [e1 e2 e3], stored row-major as m[row][col].
template <class T>
std::array<V3<T>, 3> rotation_matrix(const Quat<T>& q) {
  const T xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
  const T xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
  const T wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
  return {V3<T>{1.0 - 2.0 * (yy + zz), 2.0 * (xy - wz), 2.0 * (xz + wy)},
          V3<T>{2.0 * (xy + wz), 1.0 - 2.0 * (xx + zz), 2.0 * (yz - wx)},
          V3<T>{2.0 * (xz - wy), 2.0 * (yz + wx), 1.0 - 2.0 * (xx + yy)}};
}

// R^T a
template <class T>
V3<T> transpose_times(const std::array<V3<T>, 3>& R, const V3<T>& a) {
  return {R[0][0] * a[0] + R[1][0] * a[1] + R[2][0] * a[2], R[0][1] * a[0] + R[1][1] * a[1] + R[2][1] * a[2],
          R[0][2] * a[0] + R[1][2] * a[1] + R[2][2] * a[2]};
}

// Right Jacobian of SO(3) applied to a vector: exp(-psi^) d exp(psi^) = (J_r(psi) dpsi)^.
// J_r = I - a psi^ + b psi^2, a = (1 - cos t)/t^2, b = (t - sin t)/t^3.
template <class T>
V3<T> right_jacobian_times(const V3<T>& psi, const V3<T>& v) {
  const T t2 = dot(psi, psi);
  T a, b;
  if (value_of(t2) < 1e-8) {
    a = 0.5 - t2 / 24.0 + t2 * t2 / 720.0;
    b = 1.0 / 6.0 - t2 / 120.0 + t2 * t2 / 5040.0;
  } else {
    const T t = sqrt(t2);
    a = (1.0 - cos(t)) / t2;
    b = (t - sin(t)) / (t2 * t);
  }
  const V3<T> pv = cross(psi, v);
  const V3<T> ppv = cross(psi, pv);
  return {v[0] - a * pv[0] + b * ppv[0], v[1] - a * pv[1] + b * ppv[1], v[2] - a * pv[2] + b * ppv[2]};
}

}  // namespace strandfem
