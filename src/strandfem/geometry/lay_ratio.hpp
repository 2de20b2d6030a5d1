// Lay ratios of conductor layers (lay length over the layer's outer diameter) and EN 50182's ranges for them.
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace strandfem {

// What a conductor layer's wires are made of, as far as EN 50182's lay-ratio ranges tell them apart.
enum class WireKind { kSteel, kAluminium, kAlloy };
std::optional<WireKind> wire_kind_from_name(const std::string& name);  // steel | aluminium | alloy
const char* wire_kind_name(WireKind kind);

struct LayRatioRange {
  double lowest = 0, highest = 0;
  double middle() const { return 0.5 * (lowest + highest); }
  bool contains(double ratio) const { return ratio >= lowest && ratio <= highest; }
};

// One layer of a conductor as its lay-ratio range depends on it: its kind and wire count.
struct LayerKind {
  WireKind kind = WireKind::kAluminium;
  int wires = 1;
};

// EN 50182's range for layer `layer` (1 = the first layer around the core) of a conductor whose layers, core first,
// are `layers`: the outer aluminium or alloy layer 10-14, inner ones 10-16; steel layers by their core's size, a 7-
// or 19-wire core's 6-wire layer 16-26 and its 12-wire layer 14-22, a 37-wire core's 6-, 12- and 18-wire layers
// 17-25, 16-22 and 14-18. None for the core, a steel layer of another construction, or a strand of steel alone.
std::optional<LayRatioRange> en50182_lay_ratio_range(const std::vector<LayerKind>& layers, int layer);

// A helical layer of wires of diameter `wire_diameter` (mm) whose centres lie at `layer_radius` (mm): its lay angle
// (rad, from the strand axis) for a lay ratio, and back. The layer's outer diameter is 2 layer_radius + wire_diameter.
double lay_angle_from_ratio(double layer_radius, double wire_diameter, double lay_ratio);
double lay_ratio_from_angle(double layer_radius, double wire_diameter, double lay_angle);

}  // namespace strandfem
