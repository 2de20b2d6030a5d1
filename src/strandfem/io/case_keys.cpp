#include "strandfem/io/case_keys.hpp"

#include "strandfem/io/beam_keys.hpp"
#include "strandfem/io/contact_keys.hpp"
#include "strandfem/io/load_keys.hpp"
#include "strandfem/io/model_keys.hpp"
#include "strandfem/io/output_keys.hpp"
#include "strandfem/io/solver_keys.hpp"

#include <stdexcept>

namespace strandfem {

const std::vector<SettingKey<CaseHeading>>& case_heading_key_table() {
  using H = CaseHeading;
  static const std::vector<SettingKey<H>> table = keys_in_section<H>(KeySection::kPhysics, {
        text_key("title", &H::title, "text", "run title, printed and written to summary.json"),
        node_key("description", &H::description, "any", "free-form; the program ignores it").default_is("—"),
        node_key("expected", &H::expected, "any", "free-form reference values kept next to a case; the program ignores them").default_is("—"),
    });
  return table;
}

const std::vector<SettingKey<MonitorKey>>& monitor_key_table() {
  static const std::vector<SettingKey<MonitorKey>> table = keys_in_section<MonitorKey>(KeySection::kPhysics, {
        node_key("monitor", &MonitorKey::monitor, "selector",
                 "node of the history's `monitor_*` columns (`monitor_f*_N`: its internal force, the reaction where it is driven)")
            .default_is("the core node nearest mid-length"),
    });
  return table;
}

namespace {
std::vector<const char*> strand_step_keys() {
  std::vector<const char*> names = key_names(step_key_table());
  for (const char* name : key_names(strand_end_load_key_table(), {"transverse_force", "forces", "motions"})) names.push_back(name);
  return names;
}
}  // namespace

const std::vector<CaseKeyGroup>& case_key_table() {
  static const std::vector<CaseKeyGroup> table = {
      {"", key_names(case_heading_key_table(),
                     {"materials", "strand", "beams", "mesh", "supports", "hubs", "steps", "solver", "output", "contact"})},
      {"materials.<name>", key_names(material_key_table(), {"plasticity"})},
      {"materials.<name>.plasticity", key_names(plasticity_key_table())},
      {"strand", key_names(strand_key_table(), {"layers"})},
      {"strand.layers[i]", key_names(layer_key_table())},
      {"mesh", key_names(mesh_key_table())},
      {"beams[i]", key_names(beam_key_table(), {"section", "shape"})},
      {"beams[i].section", key_names(section_key_table())},
      {"beams[i].shape (straight)", shape_kinds()[0].keys},
      {"beams[i].shape (arc)", shape_kinds()[1].keys},
      {"beams[i].shape (helix)", shape_kinds()[2].keys},
      {"hubs[i]", key_names(hub_key_table())},
      {"selector (strands)", key_names(strand_selector_key_table())},
      {"selector (beams)", key_names(beam_selector_key_table())},
      {"supports[i]", key_names(support_key_table())},
      {"steps[i]", strand_step_keys()},
      {"steps[i] (beams)", key_names(step_key_table(), {"forces", "motions"})},
      {"steps[i].transverse_force", key_names(transverse_force_key_table())},
      {"steps[i].forces[i]", key_names(force_key_table())},
      {"steps[i].motions[i]", key_names(motion_key_table())},
      {"output", key_names(output_key_table(), key_names(monitor_key_table()))},
      {"contact", key_names(contact_key_table(), {"friction_pairs", "friction_zones"})},
      {"contact.friction_pairs[i]", key_names(friction_pair_key_table())},
      {"contact.friction_zones[i]", key_names(friction_zone_key_table())},
      {"solver", key_names(solver_key_table())},
  };
  return table;
}

std::vector<std::string> setting_key_rows(KeySection section) {
  std::vector<std::string> rows;
  const auto add = [&](const char* mapping, const auto& table) {
    for (const auto& key : table)
      if (key.section == section) rows.push_back(key_row(mapping, key));
  };
  add("", case_heading_key_table());
  add("materials.<name>", material_key_table());
  add("materials.<name>.plasticity", plasticity_key_table());
  add("strand", strand_key_table());
  add("strand.layers[i]", layer_key_table());
  add("mesh", mesh_key_table());
  add("beams[i]", beam_key_table());
  add("beams[i].section", section_key_table());
  add("beams[i].shape", shape_key_table());
  add("hubs[i]", hub_key_table());
  add("supports[i]", support_key_table());
  add("steps[i]", step_key_table());
  add("steps[i]", strand_end_load_key_table());
  add("steps[i].transverse_force", transverse_force_key_table());
  add("steps[i].forces[i]", force_key_table());
  add("steps[i].motions[i]", motion_key_table());
  add("solver", solver_key_table());
  add("contact", contact_key_table());
  add("contact.friction_pairs[i]", friction_pair_key_table());
  add("contact.friction_zones[i]", friction_zone_key_table());
  add("output", output_key_table());
  add("output", monitor_key_table());
  add("selector", strand_selector_key_table());
  add("selector", beam_selector_key_table());
  return rows;
}

const std::vector<const char*>& allowed_keys(const std::string& mapping) {
  for (const CaseKeyGroup& group : case_key_table())
    if (group.mapping == mapping) return group.keys;
  throw std::logic_error("case_key_table has no mapping '" + mapping + "'");
}

}  // namespace strandfem
