#include "strandfem/geometry/beam_line.hpp"

#include <cmath>
#include <utility>

#include "strandfem/geometry/strand.hpp"

namespace strandfem {
namespace {

// An orthonormal frame with e1 = tangent and e2 as close as possible to `preferred`.
Mat3 frame_from(const Vec3& tangent, Vec3 preferred) {
  const Vec3 e1 = tangent.normalized();
  preferred -= preferred.dot(e1) * e1;
  if (preferred.norm() < 1e-9) {
    // Any axis not parallel to the tangent.
    Eigen::Index k;
    e1.cwiseAbs().minCoeff(&k);
    preferred = Vec3::Unit(k) - e1[k] * e1;
  }
  const Vec3 e2 = preferred.normalized();
  Mat3 f;
  f.col(0) = e1;
  f.col(1) = e2;
  f.col(2) = e1.cross(e2);
  return f;
}

}  // namespace

int add_beam_line(Mesh& mesh, const BeamLineSpec& spec, int section) {
  switch (spec.shape) {
    case BeamLineSpec::kStraight: {
      const Mat3 frame = frame_from(spec.end - spec.start, spec.normal);
      return mesh.add_line(spec.name, -1, 0, section, spec.elements, [&](double t) {
        return std::make_pair(Vec3(spec.start + t * (spec.end - spec.start)), frame);
      });
    }
    case BeamLineSpec::kArc: {
      const Vec3 w = spec.axis.normalized();
      const Mat3 basis = frame_from(w, Vec3::UnitX());  // columns: w, u (toward angle 0), v
      const Vec3 u = basis.col(1), v = w.cross(u);
      const double sense = spec.end_angle > spec.start_angle ? 1.0 : -1.0;
      return mesh.add_line(spec.name, -1, 0, section, spec.elements, [&](double t) {
        const double phi = spec.start_angle + t * (spec.end_angle - spec.start_angle);
        const Vec3 radial = std::cos(phi) * u + std::sin(phi) * v;
        const Vec3 tangent = sense * (-std::sin(phi) * u + std::cos(phi) * v);
        return std::make_pair(Vec3(spec.center + spec.radius * radial), frame_from(tangent, -radial));
      });
    }
    case BeamLineSpec::kHelix:
      return mesh.add_line(spec.name, -1, 0, section, spec.elements, [&](double t) {
        const CenterlinePoint p = helix_point(spec.radius, spec.lay_angle, spec.lay_direction, spec.start_angle, t * spec.length);
        return std::make_pair(p.position, p.frame);
      });
  }
  return -1;
}

}  // namespace strandfem
