#include "strandfem/post/wire_results.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace strandfem {

std::vector<ElementResult> element_results(const Model& model, const ModelState& model_state) {
  std::vector<ElementResult> out(model.elements.size());
  for (std::size_t k = 0; k < model.elements.size(); ++k) {
    const BeamElement& e = model.elements[k];
    ElementResult& r = out[k];
    for (const SectionPointState& p : model_state.elements[k].points) {
      const SectionPointSummary s = e.section().summary(p.strain, p.committed);
      r.max_von_mises = std::max(r.max_von_mises, s.max_von_mises);
      r.max_plastic_strain = std::max(r.max_plastic_strain, s.max_plastic_strain);
      r.mean_von_mises += 0.5 * s.mean_von_mises;  // both points carry the same number of fibres
      r.mean_plastic_strain += 0.5 * s.mean_plastic_strain;
    }
  }
  return out;
}

std::vector<WireNodeResult> wire_node_results(const Model& model, const ModelState& model_state) {
  const Mesh& mesh = model.mesh;
  struct Accumulator {
    Vec6 sum = Vec6::Zero();
    int count = 0;
    double max_von_mises = 0, max_plastic_strain = 0;
  };
  std::vector<Accumulator> at(mesh.nodes.size());
  for (std::size_t k = 0; k < model.elements.size(); ++k) {
    const BeamElement& e = model.elements[k];
    const std::array<SectionPointState, 2>& points = model_state.elements[k].points;
    std::array<SectionPointSummary, 2> summary;
    for (int g = 0; g < 2; ++g) summary[g] = e.section().summary(points[g].strain, points[g].committed);
    // (node slot, point) pairs: end nodes take the nearer point, the middle node both.
    const std::array<std::pair<int, int>, 4> links = {{{0, 0}, {1, 0}, {1, 1}, {2, 1}}};
    for (const auto& [slot, g] : links) {
      Accumulator& a = at[e.nodes()[slot]];
      a.sum += points[g].resultants;
      ++a.count;
      a.max_von_mises = std::max(a.max_von_mises, summary[g].max_von_mises);
      a.max_plastic_strain = std::max(a.max_plastic_strain, summary[g].max_plastic_strain);
    }
  }
  std::vector<WireNodeResult> out;
  for (std::size_t w = 0; w < mesh.wires.size(); ++w)
    for (int node : mesh.wires[w].nodes) {
      const Accumulator& a = at[node];
      const Vec3& x = mesh.nodes[node].reference.position;
      WireNodeResult r;
      r.node = node;
      r.wire = static_cast<int>(w);
      r.layer = mesh.wires[w].layer;
      r.z = x.z();
      r.radius = std::hypot(x.x(), x.y());
      r.angle_degrees = std::hypot(x.x(), x.y()) > 1e-9 ? std::atan2(x.y(), x.x()) * 180.0 / std::numbers::pi : 0.0;
      if (a.count > 0) r.resultants = a.sum / a.count;
      r.max_von_mises = a.max_von_mises;
      r.max_plastic_strain = a.max_plastic_strain;
      out.push_back(r);
    }
  return out;
}

}  // namespace strandfem
