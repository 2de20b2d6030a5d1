// Finite-element mesh of beam lines: nodes with reference frames, 3-node elements, wires, sections.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "strandfem/beam/beam_element.hpp"
#include "strandfem/beam/section.hpp"
#include "strandfem/geometry/strand.hpp"

namespace strandfem {

struct MeshNode {
  NodeState reference;  // position and section frame of the stress-free configuration
  int wire = -1;
  int layer = -1;       // strand layer (0 = core), -1 for free beam lines
};

struct MeshElement {
  std::array<int, 3> nodes{};
  int section = 0;
  int wire = -1;
};

// A line of elements: a strand wire or a free beam line. Nodes are ordered along the line.
struct MeshWire {
  std::string name;
  int layer = -1;
  int index_in_layer = 0;
  int section = 0;
  std::vector<int> nodes;
  std::vector<int> elements;
};

struct Mesh {
  std::vector<MeshNode> nodes;
  std::vector<MeshElement> elements;
  std::vector<MeshWire> wires;
  std::vector<std::unique_ptr<Section>> sections;

  // Appends a line of `element_count` quadratic elements sampled from a parametric centerline:
  // point(t) for t in [0, 1] gives the position and section frame.
  template <class PointFn>
  int add_line(const std::string& name, int layer, int index_in_layer, int section, int element_count,
               PointFn point);
};

// How to divide a wire into elements: a target element length along the wire, or a fixed count.
struct MeshSpec {
  double element_length = 10.0;  // mm
  int elements_per_wire = 0;     // overrides element_length when > 0
};

// Meshes every wire of the strand; wire 0 is the core.
Mesh mesh_strand(const StrandSpec& strand, const MeshSpec& spec);

// Elements for a wire of the given arc length under the mesh spec.
int element_count_for(double arc_length, const MeshSpec& spec);

template <class PointFn>
int Mesh::add_line(const std::string& name, int layer, int index_in_layer, int section, int element_count,
                   PointFn point) {
  MeshWire wire;
  wire.name = name;
  wire.layer = layer;
  wire.index_in_layer = index_in_layer;
  wire.section = section;
  const int wire_id = static_cast<int>(wires.size());
  const int node_count = 2 * element_count + 1;
  for (int k = 0; k < node_count; ++k) {
    const auto [position, frame] = point(static_cast<double>(k) / (node_count - 1));
    MeshNode n;
    n.reference.position = position;
    n.reference.rotation = Quaternion(frame).normalized();
    n.wire = wire_id;
    n.layer = layer;
    wire.nodes.push_back(static_cast<int>(nodes.size()));
    nodes.push_back(n);
  }
  for (int e = 0; e < element_count; ++e) {
    MeshElement el;
    el.nodes = {wire.nodes[2 * e], wire.nodes[2 * e + 1], wire.nodes[2 * e + 2]};
    el.section = section;
    el.wire = wire_id;
    wire.elements.push_back(static_cast<int>(elements.size()));
    elements.push_back(el);
  }
  wires.push_back(std::move(wire));
  return wire_id;
}

}  // namespace strandfem
