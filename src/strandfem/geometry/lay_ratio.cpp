#include "strandfem/geometry/lay_ratio.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace strandfem {

std::optional<WireKind> wire_kind_from_name(const std::string& name) {
  if (name == "steel") return WireKind::kSteel;
  if (name == "aluminium") return WireKind::kAluminium;
  if (name == "alloy") return WireKind::kAlloy;
  return std::nullopt;
}

const char* wire_kind_name(WireKind kind) {
  switch (kind) {
    case WireKind::kSteel: return "steel";
    case WireKind::kAluminium: return "aluminium";
    case WireKind::kAlloy: return "alloy";
  }
  return "";
}

std::optional<LayRatioRange> en50182_lay_ratio_range(const std::vector<LayerKind>& layers, int layer) {
  if (layer <= 0 || layer >= static_cast<int>(layers.size())) return std::nullopt;
  const bool conductor = std::any_of(layers.begin(), layers.end(), [](const LayerKind& k) { return k.kind != WireKind::kSteel; });
  if (!conductor) return std::nullopt;  // EN 50182 covers conductors, not steel strands
  const LayerKind& l = layers[layer];
  if (l.kind != WireKind::kSteel) return layer + 1 == static_cast<int>(layers.size()) ? LayRatioRange{10, 14} : LayRatioRange{10, 16};
  int core_wires = 0;  // the steel core: the steel layers from the centre out
  for (const LayerKind& k : layers) {
    if (k.kind != WireKind::kSteel) break;
    core_wires += k.wires;
  }
  if ((core_wires == 7 || core_wires == 19) && l.wires == 6) return LayRatioRange{16, 26};
  if (core_wires == 19 && l.wires == 12) return LayRatioRange{14, 22};
  if (core_wires == 37 && l.wires == 6) return LayRatioRange{17, 25};
  if (core_wires == 37 && l.wires == 12) return LayRatioRange{16, 22};
  if (core_wires == 37 && l.wires == 18) return LayRatioRange{14, 18};
  return std::nullopt;
}

double lay_angle_from_ratio(double layer_radius, double wire_diameter, double lay_ratio) {
  const double lay_length = lay_ratio * (2.0 * layer_radius + wire_diameter);
  return std::atan(2.0 * std::numbers::pi * layer_radius / lay_length);
}

double lay_ratio_from_angle(double layer_radius, double wire_diameter, double lay_angle) {
  const double lay_length = 2.0 * std::numbers::pi * layer_radius / std::tan(lay_angle);
  return lay_length / (2.0 * layer_radius + wire_diameter);
}

}  // namespace strandfem
