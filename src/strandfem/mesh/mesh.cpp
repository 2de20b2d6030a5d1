#include "strandfem/mesh/mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace strandfem {

std::int64_t element_count_for(double arc_length, const MeshSpec& spec) {
  if (spec.elements_per_wire > 0) return spec.elements_per_wire;
  // In floating point first: a tiny element length must not overflow an integer (1e-300 gave one element).
  const double count = std::round(arc_length / spec.element_length);
  if (!(count < kMaxModelNodes)) return kMaxModelNodes;
  return std::max<std::int64_t>(1, static_cast<std::int64_t>(count));
}

std::int64_t strand_node_count(const StrandSpec& strand, const MeshSpec& spec) {
  std::int64_t nodes = 0;
  for (const LayerSpec& layer : strand.layers) {
    const std::int64_t per_wire = 2 * element_count_for(strand.length / std::cos(layer.lay_angle), spec) + 1;
    nodes += static_cast<std::int64_t>(layer.wires) * per_wire;  // wires and counts are bounded: no overflow
  }
  return nodes;
}

Mesh mesh_strand(const StrandSpec& strand, const MeshSpec& spec) {
  const std::int64_t node_count = strand_node_count(strand, spec);
  if (node_count > kMaxModelNodes)
    throw ModelSizeError("the strand mesh would have " + std::to_string(node_count) + " nodes, beyond the limit of " +
                         std::to_string(kMaxModelNodes));
  Mesh mesh;
  mesh.nodes.reserve(static_cast<std::size_t>(node_count));
  for (std::size_t i = 0; i < strand.layers.size(); ++i) {
    const LayerSpec& layer = strand.layers[i];
    const Material& material = strand.materials.at(layer.material);
    mesh.sections.push_back(make_section(SectionGeometry::circle(layer.wire_diameter, material.poisson_ratio), material));
    const int section = static_cast<int>(mesh.sections.size()) - 1;
    const double arc_length = strand.length / std::cos(layer.lay_angle);
    const int count = static_cast<int>(element_count_for(arc_length, spec));
    for (int j = 0; j < layer.wires; ++j) {
      const int layer_index = static_cast<int>(i);
      const std::string name = fmt::format("L{}W{}", i, j);
      mesh.add_line(name, layer_index, j, section, count,
                    [&](double t) {
                      const CenterlinePoint p = wire_centerline(strand, layer_index, j, t * strand.length);
                      return std::make_pair(p.position, p.frame);
                    });
    }
  }
  return mesh;
}

ElementResolution element_resolution(const Mesh& mesh, std::size_t first_element) {
  ElementResolution r;
  r.shortest = std::numeric_limits<double>::infinity();
  for (std::size_t e = first_element; e < mesh.elements.size(); ++e) {
    const auto& n = mesh.elements[e].nodes;
    const Vec3 &a = mesh.nodes[n[0]].reference.position, &b = mesh.nodes[n[1]].reference.position,
               &c = mesh.nodes[n[2]].reference.position;
    r.shortest = std::min(r.shortest, (b - a).norm() + (c - b).norm());
    r.coordinate_scale = std::max({r.coordinate_scale, a.cwiseAbs().maxCoeff(), c.cwiseAbs().maxCoeff()});
  }
  return r;
}

}  // namespace strandfem
