// The case file's `materials.<name>`, `materials.<name>.plasticity` and `mesh` keys, declared with their types,
// ranges, defaults and meanings.
#pragma once
#include <vector>

#include "strandfem/beam/material.hpp"
#include "strandfem/io/setting_keys.hpp"
#include "strandfem/mesh/mesh.hpp"

namespace strandfem {

const std::vector<SettingKey<Material>>& material_key_table();           // but `plasticity`, a mapping of its own
const std::vector<SettingKey<BilinearHardening>>& plasticity_key_table();  // tangent_modulus < E: the reader checks
const std::vector<SettingKey<MeshSpec>>& mesh_key_table();                 // one of the two: the reader checks

}  // namespace strandfem
