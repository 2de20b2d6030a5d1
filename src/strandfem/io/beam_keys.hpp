// The case file's free beam lines, hubs and node selectors: `beams[i]`, its `section` and `shape`, `hubs[i]` and
// `selector`, declared with their types, ranges, defaults and meanings.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "strandfem/geometry/beam_line.hpp"
#include "strandfem/io/setting_keys.hpp"

namespace strandfem {

// A beam line's own keys (its section and shape are mappings of their own).
struct BeamKeys {
  std::string name;
  std::string material;
  int elements = 1;
};

// A beam line's section: a circle by its diameter, or the five properties of a general section.
struct SectionKeys {
  std::optional<double> diameter;
  double area = 0, inertia_2 = 0, inertia_3 = 0, torsion_constant = 0, shear_factor = 0;
};

struct HubKeys {
  std::string name;
  Vec3 position = Vec3::Zero();
  YAML::Node links;  // node selectors, resolved once the beam lines are built
};

// A node selector as the case gives it; which keys go together: the reader checks.
struct SelectorKeys {
  std::string core;  // start | end
  std::optional<double> core_z;
  std::string beam, point, hub;
  std::optional<int> node;
};

const std::vector<SettingKey<BeamKeys>>& beam_key_table();        // but `section` and `shape`
const std::vector<SettingKey<SectionKeys>>& section_key_table();  // diameter alone, or the other five: the reader checks
// Every shape's keys; shape_kind_keys names those of one kind, and the keys that kind requires.
const std::vector<SettingKey<BeamLineSpec>>& shape_key_table();
struct ShapeKind {
  const char* type;
  std::vector<const char*> keys;      // allowed, `type` included
  std::vector<const char*> required;
};
const std::vector<ShapeKind>& shape_kinds();
const std::vector<SettingKey<HubKeys>>& hub_key_table();
const std::vector<SettingKey<SelectorKeys>>& strand_selector_key_table();
const std::vector<SettingKey<SelectorKeys>>& beam_selector_key_table();

}  // namespace strandfem
