#include "strandfem/io/case_keys.hpp"

#include "strandfem/io/contact_keys.hpp"
#include "strandfem/io/load_keys.hpp"
#include "strandfem/io/model_keys.hpp"
#include "strandfem/io/output_keys.hpp"
#include "strandfem/io/solver_keys.hpp"

#include <stdexcept>

namespace strandfem {

namespace {
std::vector<const char*> strand_step_keys() {
  std::vector<const char*> names = key_names(step_key_table());
  for (const char* name : key_names(strand_end_load_key_table(), {"transverse_force", "forces", "motions"})) names.push_back(name);
  return names;
}
}  // namespace

const std::vector<CaseKeyGroup>& case_key_table() {
  static const std::vector<CaseKeyGroup> table = {
      {"", {"title", "description", "expected", "materials", "strand", "beams", "mesh", "supports", "hubs", "steps", "solver", "output",
            "contact"}},
      {"materials.<name>", key_names(material_key_table(), {"plasticity"})},
      {"materials.<name>.plasticity", key_names(plasticity_key_table())},
      {"strand", key_names(strand_key_table(), {"layers"})},
      {"strand.layers[i]", key_names(layer_key_table())},
      {"mesh", key_names(mesh_key_table())},
      {"beams[i]", {"name", "material", "section", "shape", "elements"}},
      {"beams[i].section", {"diameter", "area", "inertia_2", "inertia_3", "torsion_constant", "shear_factor"}},
      {"beams[i].shape (straight)", {"type", "start", "end", "normal"}},
      {"beams[i].shape (arc)", {"type", "center", "radius", "start_angle", "end_angle", "axis"}},
      {"beams[i].shape (helix)", {"type", "radius", "lay_angle", "length", "lay_direction", "start_angle"}},
      {"hubs[i]", {"name", "position", "links"}},
      {"selector (strands)", {"core", "core_z"}},
      {"selector (beams)", {"beam", "point", "node", "hub"}},
      {"supports[i]", {"at", "fix"}},
      {"steps[i]", strand_step_keys()},
      {"steps[i] (beams)", key_names(step_key_table(), {"forces", "motions"})},
      {"steps[i].transverse_force", key_names(transverse_force_key_table())},
      {"steps[i].forces[i]", {"at", "force", "moment"}},
      {"steps[i].motions[i]", {"at", "ux", "uy", "uz", "rx", "ry", "rz"}},
      {"output", key_names(output_key_table(), {"monitor"})},
      {"contact", key_names(contact_key_table(), {"friction_pairs", "friction_zones", "axis"})},
      {"contact.friction_pairs[i]", {"materials", "mu", "orthotropy_ratio", "contacts"}},
      {"contact.friction_zones[i]", {"z", "mu", "materials", "contacts"}},
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
  add("materials.<name>", material_key_table());
  add("materials.<name>.plasticity", plasticity_key_table());
  add("strand", strand_key_table());
  add("strand.layers[i]", layer_key_table());
  add("mesh", mesh_key_table());
  add("steps[i]", step_key_table());
  add("steps[i]", strand_end_load_key_table());
  add("steps[i].transverse_force", transverse_force_key_table());
  add("solver", solver_key_table());
  add("contact", contact_key_table());
  add("output", output_key_table());
  return rows;
}

const std::vector<const char*>& allowed_keys(const std::string& mapping) {
  for (const CaseKeyGroup& group : case_key_table())
    if (group.mapping == mapping) return group.keys;
  throw std::logic_error("case_key_table has no mapping '" + mapping + "'");
}

}  // namespace strandfem
