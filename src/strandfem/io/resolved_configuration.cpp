#include "strandfem/io/resolved_configuration.hpp"

#include "strandfem/io/model_keys.hpp"
#include "strandfem/io/output_keys.hpp"

#include <numbers>

namespace strandfem {

namespace {
constexpr double kDegree = std::numbers::pi / 180.0;

nlohmann::json resolved_strand(const CaseDefinition& c) {
  const StrandSpec& strand = *c.strand;
  nlohmann::json layers = nlohmann::json::array();
  for (std::size_t i = 0; i < strand.layers.size(); ++i) {
    const LayerSpec& l = strand.layers[i];
    nlohmann::json layer = {{"wires", l.wires},
                            {"diameter", l.wire_diameter},
                            {"material", l.material},
                            {"lay_angle", l.lay_angle / kDegree},
                            {"lay_direction", i == 0 ? "none" : l.lay_direction > 0 ? "right" : "left"},
                            {"start_angle", l.start_angle / kDegree}};
    if (!l.wire_start_angles.empty()) {
      nlohmann::json angles = nlohmann::json::array();
      for (double a : l.wire_start_angles) angles.push_back(a / kDegree);
      layer["wire_start_angles"] = angles;
    }
    layers.push_back(layer);
  }
  return {{"length", strand.length}, {"ends", c.end_type}, {"clamp_length", c.clamp_length}, {"layers", layers}};
}

nlohmann::json resolved_materials(const StrandSpec& strand) {
  nlohmann::json materials = nlohmann::json::object();
  for (const auto& [name, m] : strand.materials) {
    nlohmann::json j = resolved_setting_keys(material_key_table(), m);
    j["plasticity"] = m.plasticity ? resolved_setting_keys(plasticity_key_table(), *m.plasticity) : nlohmann::json(nullptr);
    materials[name] = j;
  }
  return materials;
}
}  // namespace

void add_resolved_model(const CaseDefinition& c, nlohmann::json& resolved) {
  if (c.strand) {
    resolved["strand"] = resolved_strand(c);
    resolved["materials"] = resolved_materials(*c.strand);
  }
  resolved["mesh"] = {{"element_length", c.mesh_spec.elements_per_wire > 0 ? nlohmann::json(nullptr) : nlohmann::json(c.mesh_spec.element_length)},
                      {"elements_per_wire", c.mesh_spec.elements_per_wire > 0 ? nlohmann::json(c.mesh_spec.elements_per_wire) : nlohmann::json(nullptr)}};
  nlohmann::json steps = nlohmann::json::array();
  for (const LoadStep& s : c.model.steps) steps.push_back({{"name", s.name}, {"increments", s.increments}, {"cycles", s.cycles}});
  resolved["steps"] = steps;
  resolved["output"] = resolved_setting_keys(output_key_table(), c.output);
}

}  // namespace strandfem
