#include "strandfem/post/analytic.hpp"

#include "strandfem/beam/section.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace strandfem {
namespace {
const Material& material_of(const StrandSpec& strand, const LayerSpec& layer) {
  return strand.materials.at(layer.material);
}
}  // namespace

BendingStiffnessBounds bending_stiffness_bounds(const StrandSpec& strand) {
  BendingStiffnessBounds b;
  for (std::size_t i = 0; i < strand.layers.size(); ++i) {
    const LayerSpec& layer = strand.layers[i];
    const Material& m = material_of(strand, layer);
    const double E = m.youngs_modulus;
    const SectionGeometry section = SectionGeometry::circle(layer.wire_diameter, m.poisson_ratio);
    const double area = section.area, inertia = section.inertia_2;
    const double c = std::cos(layer.lay_angle), R = layer_radius(strand, static_cast<int>(i));
    b.ei_min += layer.wires * E * inertia * c;
    b.wire_shear_stiffness += layer.wires * section.shear_factor * m.shear_modulus() * area * c;
    b.ei_max += layer.wires * (E * inertia * c + 0.5 * E * area * R * R * c * c * c);
  }
  return b;
}

LinearStrandStiffness linear_strand_stiffness(const StrandSpec& strand) {
  LinearStrandStiffness k;
  // Positive twist: the lay direction of the outer layer.
  const int reference_direction = strand.layers.back().lay_direction;
  for (std::size_t i = 0; i < strand.layers.size(); ++i) {
    const LayerSpec& layer = strand.layers[i];
    const Material& m = material_of(strand, layer);
    const double r = 0.5 * layer.wire_diameter;
    const double EA = m.youngs_modulus * std::numbers::pi * r * r;
    const double EI = m.youngs_modulus * std::numbers::pi * std::pow(r, 4) / 4.0;
    const double GJ = m.shear_modulus() * std::numbers::pi * std::pow(r, 4) / 2.0;
    if (i == 0) {
      k.c11 += layer.wires * EA;
      k.c22 += layer.wires * GJ;
      continue;
    }
    // Costello's helix angle is measured from the cross-section plane: alpha_c = pi/2 - lay angle.
    const double s = std::cos(layer.lay_angle), c = std::sin(layer.lay_angle);
    const double cos2 = c * c - s * s;
    const double R = layer_radius(strand, static_cast<int>(i));
    const double n = layer.wires;
    // A layer laid against the reference direction couples twist and extension with the opposite sign.
    const double sign = layer.lay_direction == reference_direction ? 1.0 : -1.0;
    k.c11 += n * (EA * s * s * s + 2.0 * EI * s * s * s * std::pow(c, 4) / (R * R) +
                  GJ * s * std::pow(c, 4) * cos2 / (R * R));
    k.c12 += sign * n * s * s * c * (EA * R - 2.0 * EI * s * s * c * c / R - GJ * c * c * cos2 / R);
    k.c21 += sign * n * s * s * c * (EA * R - 2.0 * EI * c * c * (1.0 + s * s) / R + GJ * s * s * cos2 / R);
    k.c22 += n * (EA * R * R * s * c * c + 2.0 * EI * s * s * s * c * c * (1.0 + s * s) - GJ * std::pow(s, 5) * cos2);
  }
  return k;
}

StrandProperties strand_properties(const StrandSpec& strand) {
  StrandProperties p;
  for (const LayerSpec& layer : strand.layers) {
    const Material& m = material_of(strand, layer);
    const double area = std::numbers::pi * 0.25 * layer.wire_diameter * layer.wire_diameter;
    p.metallic_area += layer.wires * area;
    // density in t/mm^3 times mm^2 gives t/mm = 1e6 kg/m.
    p.mass_per_length += layer.wires * m.density * area / std::cos(layer.lay_angle) * 1e6;
    p.axial_stiffness_sum += layer.wires * m.youngs_modulus * area;
  }
  return p;
}

double radial_contact_count_eq24(const StrandSpec& strand, int layer) {
  if (layer < 2 || layer >= static_cast<int>(strand.layers.size()))
    throw std::invalid_argument("radial_contact_count_eq24: layer must be in 2.." + std::to_string(strand.layers.size() - 1));
  const LayerSpec &outer = strand.layers[layer], &inner = strand.layers[layer - 1];
  const double contact_radius = layer_radius(strand, layer) - 0.5 * outer.wire_diameter;
  const double spacing = 2.0 * M_PI * contact_radius * std::cos(inner.lay_angle) /
                         (inner.wires * std::sin(outer.lay_angle + inner.lay_angle));
  return outer.wires * strand.length / (spacing * std::cos(outer.lay_angle));
}

double radial_contact_count_helix(const StrandSpec& strand, int layer) {
  if (layer < 2 || layer >= static_cast<int>(strand.layers.size()))
    throw std::invalid_argument("radial_contact_count_helix: layer must be in 2.." + std::to_string(strand.layers.size() - 1));
  const LayerSpec &outer = strand.layers[layer], &inner = strand.layers[layer - 1];
  const double rate_outer = outer.lay_direction * std::tan(outer.lay_angle) / layer_radius(strand, layer);
  const double rate_inner = inner.lay_direction * std::tan(inner.lay_angle) / layer_radius(strand, layer - 1);
  return outer.wires * inner.wires * strand.length * std::abs(rate_outer - rate_inner) / (2.0 * M_PI);
}

double poffenberger_swart_stress(double yb, double tension, double ei_min, double wire_modulus, double wire_diameter, double xb) {
  const double px = std::sqrt(tension / ei_min) * xb;
  // e^(-px) - 1 + px loses its digits for small px: its series, (px)²/2 - (px)³/6 + (px)⁴/24, below 1e-3.
  const double shape = px < 1e-3 ? px * px * (0.5 - px / 6.0 + px * px / 24.0) : std::expm1(-px) + px;
  return yb * wire_modulus * wire_diameter * px * px / (4.0 * xb * xb * shape);
}

}  // namespace strandfem
