// Contact search: element bounding boxes inflated by radius and margin, binned in a uniform cell grid.
#pragma once
#include <utility>
#include <vector>

#include "strandfem/mesh/mesh.hpp"

namespace strandfem {

struct BoundingBox {
  Vec3 lower = Vec3::Constant(1e300), upper = Vec3::Constant(-1e300);
  void include(const Vec3& p) { lower = lower.cwiseMin(p); upper = upper.cwiseMax(p); }
  bool overlaps(const BoundingBox& o) const {
    return (lower.array() <= o.upper.array()).all() && (o.lower.array() <= upper.array()).all();
  }
};

// Box of the quadratic centerline of an element: it lies in the hull of its end nodes and its Bezier
// control point 2 x1 - (x0 + x2) / 2, so that box bounds the whole curve; then inflated by `inflation`.
BoundingBox element_box(const std::array<Vec3, 3>& nodes, double inflation);

// Lower bound of the distance between the quadratic centerlines of two elements: the distance of their
// two-chord polylines less each curve's largest deviation from its polyline (|x0 - 2 x1 + x2| / 4).
double centerline_distance_bound(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b);

// Pairs (i < j) of mesh elements on different wires whose boxes overlap and whose centerlines may come
// closer than the sum of their inflations (boxes of inclined helical elements overlap far more often). `inflation[e]` < 0 leaves
// element e out. The grid's cell is the largest box extent, so each box touches at most 8 cells.
std::vector<std::pair<int, int>> find_candidate_pairs(const Mesh& mesh, const std::vector<NodeState>& state,
                                                      const std::vector<double>& inflation);

}  // namespace strandfem
