#include "strandfem/mesh/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace strandfem {

int element_count_for(double arc_length, const MeshSpec& spec) {
  if (spec.elements_per_wire > 0) return spec.elements_per_wire;
  return std::max(1, static_cast<int>(std::lround(arc_length / spec.element_length)));
}

Mesh mesh_strand(const StrandSpec& strand, const MeshSpec& spec) {
  Mesh mesh;
  for (std::size_t i = 0; i < strand.layers.size(); ++i) {
    const LayerSpec& layer = strand.layers[i];
    const Material& material = strand.materials.at(layer.material);
    mesh.sections.push_back(make_section(SectionGeometry::circle(layer.wire_diameter, material.poisson_ratio), material));
    const int section = static_cast<int>(mesh.sections.size()) - 1;
    const double arc_length = strand.length / std::cos(layer.lay_angle);
    const int count = element_count_for(arc_length, spec);
    for (int j = 0; j < layer.wires; ++j) {
      const int layer_index = static_cast<int>(i);
      mesh.add_line("L" + std::to_string(i) + "W" + std::to_string(j), layer_index, j, section, count,
                    [&](double t) {
                      const CenterlinePoint p = wire_centerline(strand, layer_index, j, t * strand.length);
                      return std::make_pair(p.position, p.frame);
                    });
    }
  }
  return mesh;
}

}  // namespace strandfem
