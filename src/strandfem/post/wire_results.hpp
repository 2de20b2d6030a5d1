// Results reduced from the section points of a converged state: per element and along each wire's nodes.
#pragma once
#include <vector>

#include "strandfem/solver/model_state.hpp"

namespace strandfem {

// Von Mises stress (MPa) and equivalent plastic strain over all fibres of an element's two section points.
struct ElementResult {
  double max_von_mises = 0, mean_von_mises = 0;
  double max_plastic_strain = 0, mean_plastic_strain = 0;
};

std::vector<ElementResult> element_results(const Model& model, const ModelState& model_state);

// Section results at a wire node: resultants [N, Q2, Q3, T, M2, M3] (section axes; N and N mm) averaged over
// the section points next to the node (end nodes: the nearer point of each adjacent element; middle nodes:
// both points of their element), and the largest von Mises stress and plastic strain among those points.
struct WireNodeResult {
  int node = -1, wire = -1, layer = -1;
  double z = 0;              // reference axial position, mm
  double angle_degrees = 0;  // reference angular position about the strand axis (z)
  double radius = 0;         // reference distance from the strand axis, mm
  Vec6 resultants = Vec6::Zero();
  double max_von_mises = 0, max_plastic_strain = 0;
};

// Along every wire, node by node in wire order.
std::vector<WireNodeResult> wire_node_results(const Model& model, const ModelState& model_state);

}  // namespace strandfem
