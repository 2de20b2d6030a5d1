#include "strandfem/geometry/strand.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace strandfem {

std::vector<int> default_lay_directions(int layer_count) {
  std::vector<int> directions(layer_count, 1);
  for (int i = layer_count - 1, d = 1; i >= 1; --i, d = -d) directions[i] = d;
  return directions;
}

double layer_radius(const StrandSpec& strand, int layer) {
  if (layer == 0) return 0.0;
  double r = 0.5 * strand.layers[0].wire_diameter;
  for (int k = 1; k < layer; ++k) r += strand.layers[k].wire_diameter;
  return r + 0.5 * strand.layers[layer].wire_diameter;
}

CenterlinePoint wire_centerline(const StrandSpec& strand, int layer, int wire_in_layer, double z) {
  CenterlinePoint p;
  if (layer == 0) {
    p.position = Vec3(0, 0, z);
    p.frame.col(0) = Vec3::UnitZ();
    p.frame.col(1) = Vec3::UnitX();
    p.frame.col(2) = Vec3::UnitY();
    return p;
  }
  const LayerSpec& spec = strand.layers[layer];
  const double start = spec.wire_start_angles.empty()
                            ? spec.start_angle + 2.0 * std::numbers::pi * wire_in_layer / spec.wires
                            : spec.wire_start_angles[wire_in_layer];
  return helix_point(layer_radius(strand, layer), spec.lay_angle, spec.lay_direction, start, z);
}

CenterlinePoint helix_point(double radius, double lay_angle, int direction, double start_angle, double z) {
  // Angle rate along z: theta_i / L with theta_i = tan(alpha) L / R (eq. 2.2).
  const double R = radius, rate = direction * std::tan(lay_angle) / R;
  const double phi = start_angle + rate * z;
  CenterlinePoint p;
  p.position = Vec3(R * std::cos(phi), R * std::sin(phi), z);
  const Vec3 tangent = Vec3(-R * rate * std::sin(phi), R * rate * std::cos(phi), 1.0).normalized();
  const Vec3 inward(-std::cos(phi), -std::sin(phi), 0.0);
  p.frame.col(0) = tangent;
  p.frame.col(1) = inward;
  p.frame.col(2) = tangent.cross(inward);
  return p;
}

namespace {

// Smallest angular separation at z = 0 between two wires of the layer: 2 pi / n when evenly spaced, otherwise
// the smallest gap between neighbours of the sorted start angles (wires of a layer are parallel helices, so their
// separation stays the same along z).
double smallest_angular_spacing(const LayerSpec& spec) {
  const double turn = 2.0 * std::numbers::pi;
  if (spec.wire_start_angles.empty()) return turn / spec.wires;
  std::vector<double> angles;
  for (const double a : spec.wire_start_angles) angles.push_back(a - turn * std::floor(a / turn));
  std::sort(angles.begin(), angles.end());
  double smallest = angles.front() + turn - angles.back();
  for (std::size_t i = 1; i < angles.size(); ++i) smallest = std::min(smallest, angles[i] - angles[i - 1]);
  return smallest;
}

// Smallest centerline distance between neighbouring wires of a layer laid at radius R, minus a diameter.
double clearance_at_radius(const LayerSpec& spec, double R) {
  const double k = spec.lay_direction * std::tan(spec.lay_angle) / R;
  const double phi0 = smallest_angular_spacing(spec);
  // Squared distance from wire 0 at z = 0 to wire 1 at height z.
  auto distance2 = [&](double z) { return 2.0 * R * R * (1.0 - std::cos(phi0 + k * z)) + z * z; };
  // The minimum lies between z = 0 and the height where wire 1 passes over wire 0's start angle, and within
  // |z| <= the distance at z = 0 (the distance is at least |z|): nearly straight wires would otherwise send the
  // search to heights where z^2 overflows.
  const double reach = std::sqrt(distance2(0.0));
  const double z_end = std::abs(k) > 1e-12 ? std::clamp(-phi0 / k, -reach, reach) : 0.0;
  double a = std::min(0.0, z_end), b = std::max(0.0, z_end);
  double best = a, best_value = distance2(a);
  const int samples = 400;
  for (int s = 1; s <= samples; ++s) {
    const double z = a + (b - a) * s / samples;
    const double v = distance2(z);
    if (v < best_value) best = z, best_value = v;
  }
  double lo = best - (b - a) / samples, hi = best + (b - a) / samples;
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 100; ++it) {
    const double z1 = hi - golden * (hi - lo), z2 = lo + golden * (hi - lo);
    if (distance2(z1) < distance2(z2)) hi = z2; else lo = z1;
  }
  return std::sqrt(distance2(0.5 * (lo + hi))) - spec.wire_diameter;
}

}  // namespace

double lateral_clearance(const StrandSpec& strand, int layer) {
  const LayerSpec& spec = strand.layers[layer];
  if (layer == 0 || spec.wires < 2) return std::numeric_limits<double>::quiet_NaN();
  return clearance_at_radius(spec, layer_radius(strand, layer));
}

double touching_layer_radius(const StrandSpec& strand, int layer) {
  const LayerSpec& spec = strand.layers[layer];
  if (layer == 0 || spec.wires < 2) return std::numeric_limits<double>::quiet_NaN();
  // Clearance grows with the radius: bisect between a radius with overlap and one with a gap.
  // Wires at the same start angle overlap at any radius.
  if (!(smallest_angular_spacing(spec) > 0)) return std::numeric_limits<double>::quiet_NaN();
  double lo = 0.5 * spec.wire_diameter, hi = layer_radius(strand, layer);
  for (int grow = 0; clearance_at_radius(spec, hi) < 0; ++grow) {
    if (grow == 200) return std::numeric_limits<double>::quiet_NaN();
    hi *= 1.5;
  }
  for (int it = 0; it < 80; ++it) {
    const double mid = 0.5 * (lo + hi);
    (clearance_at_radius(spec, mid) < 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace strandfem
