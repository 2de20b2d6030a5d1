#include "strandfem/post/model_report.hpp"

#include <cmath>
#include <numbers>

#include "strandfem/geometry/lay_ratio.hpp"
#include "strandfem/post/analytic.hpp"

namespace strandfem {

nlohmann::json model_report(const CaseDefinition& c) {
  const Mesh& mesh = c.model.mesh;
  nlohmann::json j;
  j["title"] = c.title;
  j["nodes"] = mesh.nodes.size();
  j["elements"] = mesh.elements.size();
  j["wires"] = mesh.wires.size();
  const DofMap dofs = build_dof_map(c.model);
  j["dofs"] = dofs.equation_count;
  j["dofs_before_constraints"] = 6 * mesh.nodes.size();
  j["rigid_ties"] = c.model.ties.size();
  j["warnings"] = c.warnings;
  if (!c.strand) return j;
  const StrandSpec& s = *c.strand;
  j["strand_length_mm"] = s.length;
  j["conductor"] = c.conductor.empty() ? nlohmann::json(nullptr) : nlohmann::json(c.conductor);
  j["end_type"] = c.end_type;
  nlohmann::json layers = nlohmann::json::array();
  for (std::size_t i = 0; i < s.layers.size(); ++i) {
    const LayerSpec& l = s.layers[i];
    const double clearance = lateral_clearance(s, static_cast<int>(i));
    const MeshWire* first = nullptr;
    for (const MeshWire& w : mesh.wires)
      if (w.layer == static_cast<int>(i)) { first = &w; break; }
    layers.push_back({{"layer", i},
                      {"wires", l.wires},
                      {"wire_diameter_mm", l.wire_diameter},
                      {"material", l.material},
                      {"lay_angle_deg", l.lay_angle * 180.0 / std::numbers::pi},
                      {"lay_direction", i == 0 ? "none" : (l.lay_direction > 0 ? "right" : "left")},
                      {"lay_ratio", i == 0 ? nlohmann::json(nullptr)
                                           : nlohmann::json(lay_ratio_from_angle(layer_radius(s, static_cast<int>(i)), l.wire_diameter, l.lay_angle))},
                      {"layer_radius_mm", layer_radius(s, static_cast<int>(i))},
                      {"lateral_clearance_mm", std::isnan(clearance) ? nlohmann::json(nullptr) : nlohmann::json(clearance)},
                      {"radial_overlap_mm", std::isnan(clearance) ? nlohmann::json(nullptr)
                                                                  : nlohmann::json(touching_layer_radius(s, static_cast<int>(i)) -
                                                                                   layer_radius(s, static_cast<int>(i)))},
                      {"elements_per_wire", first ? first->elements.size() : 0}});
  }
  j["layers"] = layers;
  const BendingStiffnessBounds ei = bending_stiffness_bounds(s);
  j["EI_max_Nm2"] = ei.ei_max * 1e-6;
  j["EI_min_Nm2"] = ei.ei_min * 1e-6;
  const LinearStrandStiffness k = linear_strand_stiffness(s);
  j["axial_stiffness_N"] = {{"theory", "linearised Costello thin-rod theory, fixed layer radii (docs/theory.md)"},
                            {"fixed_ends", k.axial_fixed()},
                            {"free_ends", k.axial_free()},
                            {"free_end_twist_rad_per_mm_per_strain", k.twist_per_strain_free()},
                            {"C11_N", k.c11},
                            {"C12_Nmm", k.c12},
                            {"C21_Nmm", k.c21},
                            {"C22_Nmm2", k.c22}};
  const StrandProperties p = strand_properties(s);
  j["metallic_area_mm2"] = p.metallic_area;
  j["mass_per_length_kg_per_m"] = p.mass_per_length;
  j["sum_EA_N"] = p.axial_stiffness_sum;
  return j;
}

nlohmann::json poffenberger_swart_report(const StrandSpec& strand, double tension, double yb) {
  const LayerSpec& outer = strand.layers.back();
  const double modulus = strand.materials.at(outer.material).youngs_modulus;
  const double ei_min = bending_stiffness_bounds(strand).ei_min;
  const double xb = kPoffenbergerSwartDistance;
  const double stress = poffenberger_swart_stress(yb, tension, ei_min, modulus, outer.wire_diameter, xb);
  return {{"formula", "sigma_a = K yb, K = E d p^2 / (4 (exp(-p xb) - 1 + p xb)), p = sqrt(T / EImin) (Poffenberger and Swart 1965)"},
          {"tension_N", tension},
          {"yb_mm", yb},
          {"xb_mm", xb},
          {"EI_min_Nm2", ei_min * 1e-6},
          {"outer_wire_E_MPa", modulus},
          {"outer_wire_diameter_mm", outer.wire_diameter},
          {"p_per_mm", std::sqrt(tension / ei_min)},
          {"K_MPa_per_mm", stress / yb},
          {"stress_amplitude_MPa", stress}};
}

}  // namespace strandfem
