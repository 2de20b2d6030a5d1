// Helical strand geometry: layers, layer radii (paper eq. 2.1) and wire centerline helices (eq. 2.2).
#pragma once
#include <map>
#include <string>
#include <vector>

#include "strandfem/beam/section.hpp"
#include "strandfem/core/types.hpp"

namespace strandfem {

// One layer of the strand; layer 0 is the straight core (one wire, no lay angle).
struct LayerSpec {
  int wires = 1;
  double wire_diameter = 0;   // mm
  std::string material;       // key into StrandSpec::materials
  double lay_angle = 0;       // rad, between the wire tangent and the strand axis
  int lay_direction = 1;      // +1 right-hand lay, -1 left-hand lay
  double start_angle = 0;     // rad, angular position gamma of the layer's first wire at z = 0
  // Optional per-wire angular positions at z = 0 (rad); when empty, wires are evenly spaced from start_angle.
  std::vector<double> wire_start_angles;
};

struct StrandSpec {
  double length = 0;  // mm
  std::vector<LayerSpec> layers;
  std::map<std::string, Material> materials;
};

// Lay directions alternating from a right-hand outer layer inward (the usual conductor practice).
std::vector<int> default_lay_directions(int layer_count);

// Layer radius R_i of eq. 2.1 (R_0 = 0 for the core).
double layer_radius(const StrandSpec& strand, int layer);

// Point and section frame of a wire centerline at axial position z (0 <= z <= length). The frame has
// e1 = unit tangent, e2 = unit normal toward the strand axis (x axis for the core), e3 = e1 x e2.
struct CenterlinePoint {
  Vec3 position;
  Mat3 frame;  // columns e1, e2, e3
};
CenterlinePoint wire_centerline(const StrandSpec& strand, int layer, int wire_in_layer, double z);

// Point and frame of a helix about the z axis: radius, lay angle (rad), direction (+1 right-hand),
// angular position at z = 0 (rad).
CenterlinePoint helix_point(double radius, double lay_angle, int direction, double start_angle, double z);

// Smallest distance between the centerlines of two neighbouring wires of a layer minus one wire diameter:
// negative values are overlaps of the nominal geometry. Neighbours are those closest in start angle (evenly
// spaced, or per-wire start_angles). NaN for the core and single-wire layers.
double lateral_clearance(const StrandSpec& strand, int layer);

// Layer radius at which neighbouring wires of the layer would just touch (exact helix distance). Its
// excess over layer_radius() is the overlap "in radius" that strand data sheets quote (120-wire strand,
// layer 2: about 0.19 mm). NaN for the core and single-wire layers.
double touching_layer_radius(const StrandSpec& strand, int layer);

}  // namespace strandfem
