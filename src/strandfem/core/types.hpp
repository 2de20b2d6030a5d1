// Fixed-size Eigen value types used across StrandFEM (units: N, mm, MPa, rad).
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace strandfem {

using Vec3 = Eigen::Vector3d;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat3 = Eigen::Matrix3d;
using Mat6 = Eigen::Matrix<double, 6, 6>;
using Quaternion = Eigen::Quaterniond;

inline Mat3 skew(const Vec3& v) {
  Mat3 m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

// Quaternion of a rotation vector (axis * angle); exact near zero.
inline Quaternion quaternion_from_rotation_vector(const Vec3& theta) {
  const double t = theta.norm();
  if (t < 1e-12) return Quaternion(1.0, 0.5 * theta.x(), 0.5 * theta.y(), 0.5 * theta.z()).normalized();
  return Quaternion(Eigen::AngleAxisd(t, theta / t));
}

// Rotation vector of a quaternion, angle in [0, pi].
inline Vec3 rotation_vector_from_quaternion(const Quaternion& q_in) {
  Quaternion q = q_in;
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  const Vec3 v = q.vec();
  const double s = v.norm();
  if (s < 1e-12) return 2.0 * v / q.w();
  return 2.0 * std::atan2(s, q.w()) / s * v;
}

}  // namespace strandfem
