// The case file's `materials.<name>`, `materials.<name>.plasticity`, `strand`, `strand.layers[i]` and `mesh` keys,
// declared with their types, ranges, defaults and meanings.
#pragma once
#include <string>
#include <vector>

#include "strandfem/beam/material.hpp"
#include "strandfem/geometry/strand.hpp"
#include "strandfem/io/setting_keys.hpp"
#include "strandfem/mesh/mesh.hpp"

namespace strandfem {

constexpr int kMaxWiresPerLayer = 1000;  // a layer of real strands has a few dozen wires

// The `strand` mapping's own values (its layers are a list of their own).
struct StrandSettings {
  double length = 0;          // mm
  std::string ends = "fixed"; // fixed | free
  double clamp_length = 0;    // mm held rigid at each end
  std::string conductor;      // a catalogue conductor instead of `layers` (empty: none)
  std::vector<double> lay_ratios;  // conductor: per layer around the core (empty: the catalogue's or EN 50182's)
  std::vector<double> lay_angles;  // conductor: rad, per layer around the core, instead of lay_ratios
};

const std::vector<SettingKey<Material>>& material_key_table();           // but `plasticity`, a mapping of its own
const std::vector<SettingKey<BilinearHardening>>& plasticity_key_table();  // tangent_modulus < E: the reader checks
// But `layers`; clamp_length < length / 2, `conductor` or `layers`, and the lay lists' lengths: the reader checks.
const std::vector<SettingKey<StrandSettings>>& strand_key_table();
// A layer's keys; the core takes neither lay_angle nor lay_direction, start_angle and start_angles exclude each other,
// and the material must be one of `materials`: the reader checks.
const std::vector<SettingKey<LayerSpec>>& layer_key_table();
const std::vector<SettingKey<MeshSpec>>& mesh_key_table();                 // one of the two: the reader checks

}  // namespace strandfem
