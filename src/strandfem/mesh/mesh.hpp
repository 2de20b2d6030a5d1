// Finite-element mesh of beam lines: nodes with reference frames, 3-node elements, wires, sections.
#pragma once
#include <algorithm>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "strandfem/beam/beam_element.hpp"
#include "strandfem/beam/section.hpp"
#include "strandfem/geometry/strand.hpp"

namespace strandfem {

// Model-size limit, checked before anything is allocated: 250,000 nodes (1,500,000 DOFs). The largest paper
// case (S32, 1 m) has 12,621 nodes; a model at the limit already takes seconds and gigabytes just to be built
// (a run of elastoplastic wires keeps the fibre states of every element: 2.7 GB at the limit, measured).
constexpr int kMaxModelNodes = 250000;
constexpr int kMaxElementsPerLine = (kMaxModelNodes - 1) / 2;  // 3-node elements within the model-size limit
// Elements shorter than this fraction of the coordinates' magnitude (or than kMinElementLength) would lose
// their geometry to round-off: positions carry 16 digits, an element's strains are differences of them.
constexpr double kMinElementLengthRatio = 1e-6;
constexpr double kMinElementLength = 1e-6;  // mm

// A mesh beyond kMaxModelNodes (thrown by the mesher; case files check first and name the key).
struct ModelSizeError : std::length_error {
  using std::length_error::length_error;
};

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

// Meshes every wire of the strand; wire 0 is the core. Throws ModelSizeError beyond kMaxModelNodes.
Mesh mesh_strand(const StrandSpec& strand, const MeshSpec& spec);

// Elements for a wire of the given arc length under the mesh spec, computed in floating point and saturated at
// kMaxModelNodes (any count that large is beyond the model-size limit anyway), so that it never overflows.
std::int64_t element_count_for(double arc_length, const MeshSpec& spec);

// Nodes the strand's mesh would have (64-bit, no allocation).
std::int64_t strand_node_count(const StrandSpec& strand, const MeshSpec& spec);

// The shortest element from `first_element` on (length along its two node-to-node chords) and the largest
// coordinate magnitude of their nodes; resolvable when shortest >= max(kMinElementLength, ratio * scale).
struct ElementResolution {
  double shortest = 0;
  double coordinate_scale = 0;
  bool resolvable() const { return shortest >= std::max(kMinElementLength, kMinElementLengthRatio * coordinate_scale); }
};
ElementResolution element_resolution(const Mesh& mesh, std::size_t first_element);

template <class PointFn>
int Mesh::add_line(const std::string& name, int layer, int index_in_layer, int section, int element_count,
                   PointFn point) {
  MeshWire wire;
  wire.name = name;
  wire.layer = layer;
  wire.index_in_layer = index_in_layer;
  wire.section = section;
  const int wire_id = static_cast<int>(wires.size());
  const std::int64_t nodes_after = static_cast<std::int64_t>(nodes.size()) + 2 * static_cast<std::int64_t>(element_count) + 1;
  if (element_count < 1 || nodes_after > kMaxModelNodes)
    throw ModelSizeError("line '" + name + "': " + std::to_string(element_count) + " elements would take the model to " +
                         std::to_string(nodes_after) + " nodes, beyond the limit of " + std::to_string(kMaxModelNodes));
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
