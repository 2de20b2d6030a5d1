#include "strandfem/contact/contact_search.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace strandfem {

BoundingBox element_box(const std::array<Vec3, 3>& x, double inflation) {
  BoundingBox box;
  box.include(x[0]);
  box.include(x[2]);
  box.include(x[1]);
  box.include(2.0 * x[1] - 0.5 * (x[0] + x[2]));
  box.lower.array() -= inflation;
  box.upper.array() += inflation;
  return box;
}

namespace {
// Shortest distance between segments p0-p1 and q0-q1 (clamped closest points).
double segment_distance(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  const Vec3 u = p1 - p0, v = q1 - q0, w = p0 - q0;
  const double a = u.dot(u), b = u.dot(v), c = v.dot(v), d = u.dot(w), e = v.dot(w);
  const double denominator = a * c - b * b;
  double s = denominator > 1e-14 * a * c ? std::clamp((b * e - c * d) / denominator, 0.0, 1.0) : 0.0;
  double t = c > 0 ? (b * s + e) / c : 0.0;
  if (t < 0 || t > 1) {
    t = std::clamp(t, 0.0, 1.0);
    s = a > 0 ? std::clamp((b * t - d) / a, 0.0, 1.0) : 0.0;
  }
  return (w + s * u - t * v).norm();
}
}  // namespace

double centerline_distance_bound(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b) {
  double distance = 1e300;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) distance = std::min(distance, segment_distance(a[i], a[i + 1], b[j], b[j + 1]));
  return distance - 0.25 * (a[0] - 2.0 * a[1] + a[2]).norm() - 0.25 * (b[0] - 2.0 * b[1] + b[2]).norm();
}

std::vector<std::pair<int, int>> find_candidate_pairs(const Mesh& mesh, const std::vector<NodeState>& state,
                                                      const std::vector<double>& inflation) {
  const int count = static_cast<int>(mesh.elements.size());
  std::vector<BoundingBox> boxes(count);
  double cell = 0;
  Vec3 origin = Vec3::Constant(1e300);
  for (int e = 0; e < count; ++e) {
    if (inflation[e] < 0) continue;
    const auto& nodes = mesh.elements[e].nodes;
    boxes[e] = element_box({state[nodes[0]].position, state[nodes[1]].position, state[nodes[2]].position}, inflation[e]);
    cell = std::max(cell, (boxes[e].upper - boxes[e].lower).maxCoeff());
    origin = origin.cwiseMin(boxes[e].lower);
  }
  if (cell <= 0) return {};
  auto key = [](std::int64_t i, std::int64_t j, std::int64_t k) { return (i * 73856093) ^ (j * 19349663) ^ (k * 83492791); };
  std::unordered_map<std::int64_t, std::vector<int>> grid;
  std::vector<std::array<int, 6>> ranges(count);
  for (int e = 0; e < count; ++e) {
    if (inflation[e] < 0) continue;
    auto& r = ranges[e];
    for (int c = 0; c < 3; ++c) {
      r[c] = static_cast<int>(std::floor((boxes[e].lower[c] - origin[c]) / cell));
      r[3 + c] = static_cast<int>(std::floor((boxes[e].upper[c] - origin[c]) / cell));
    }
    for (int i = r[0]; i <= r[3]; ++i)
      for (int j = r[1]; j <= r[4]; ++j)
        for (int k = r[2]; k <= r[5]; ++k) grid[key(i, j, k)].push_back(e);
  }
  std::vector<std::pair<int, int>> pairs;
  for (int e = 0; e < count; ++e) {
    if (inflation[e] < 0) continue;
    const auto& r = ranges[e];
    for (int i = r[0]; i <= r[3]; ++i)
      for (int j = r[1]; j <= r[4]; ++j)
        for (int k = r[2]; k <= r[5]; ++k) {
          const auto it = grid.find(key(i, j, k));
          if (it == grid.end()) continue;
          for (int other : it->second)
            if (other > e && mesh.elements[other].wire != mesh.elements[e].wire && boxes[e].overlaps(boxes[other]))
              pairs.emplace_back(e, other);
        }
  }
  // A pair sharing several cells (or a hash collision) appears more than once.
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  auto nodes_of = [&](int e) {
    const auto& n = mesh.elements[e].nodes;
    return std::array<Vec3, 3>{state[n[0]].position, state[n[1]].position, state[n[2]].position};
  };
  std::erase_if(pairs, [&](const std::pair<int, int>& p) {
    return centerline_distance_bound(nodes_of(p.first), nodes_of(p.second)) > inflation[p.first] + inflation[p.second];
  });
  return pairs;
}

}  // namespace strandfem
