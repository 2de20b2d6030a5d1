#include "strandfem/io/resolved_configuration.hpp"

#include "strandfem/geometry/lay_ratio.hpp"
#include "strandfem/io/load_keys.hpp"
#include "strandfem/io/model_keys.hpp"
#include "strandfem/io/output_keys.hpp"

namespace strandfem {

namespace {
nlohmann::json resolved_strand(const CaseDefinition& c) {
  const StrandSpec& strand = *c.strand;
  nlohmann::json layers = nlohmann::json::array();
  for (std::size_t i = 0; i < strand.layers.size(); ++i) {
    nlohmann::json layer = resolved_setting_keys(layer_key_table(), strand.layers[i]);
    if (i == 0) layer["lay_direction"] = "none";  // the core is straight
    layers.push_back(layer);
  }
  StrandSettings settings{strand.length, c.end_type, c.clamp_length, c.conductor, {}, {}};
  if (!c.conductor.empty())
    for (std::size_t i = 1; i < strand.layers.size(); ++i) {
      settings.lay_ratios.push_back(lay_ratio_from_angle(layer_radius(strand, static_cast<int>(i)), strand.layers[i].wire_diameter, strand.layers[i].lay_angle));
      settings.lay_angles.push_back(strand.layers[i].lay_angle);
    }
  nlohmann::json resolved = resolved_setting_keys(strand_key_table(), settings);
  if (!c.conductor.empty()) resolved["conductor_source"] = c.conductor_origin;  // the catalogue row it starts at
  resolved["layers"] = layers;
  return resolved;
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
  for (const LoadStep& s : c.model.steps) steps.push_back(resolved_setting_keys(step_key_table(), s));
  resolved["steps"] = steps;
  resolved["output"] = resolved_setting_keys(output_key_table(), c.output);
}

}  // namespace strandfem
