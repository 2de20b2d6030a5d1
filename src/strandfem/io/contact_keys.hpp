// The case file's `contact:` mapping (friction per pair and zone, penalty factors, search, overlap).
#pragma once
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "strandfem/beam/section.hpp"
#include "strandfem/contact/contact_settings.hpp"
#include "strandfem/io/setting_keys.hpp"
#include "strandfem/io/yaml_reader.hpp"

namespace strandfem {

// The scalar keys of `contact:`, each with its type, range, default and meaning; `friction_pairs`,
// `friction_zones` and `axis` are read by parse_contact_settings itself.
const std::vector<SettingKey<ContactSettings>>& contact_key_table();

// Reads and validates `contact:` (docs/case-files.md); `strand`: the case is a strand (no `axis` key).
// Throws CaseError naming the key.
ContactSettings parse_contact_settings(const YamlReader& reader, const YAML::Node& node,
                                       const std::map<std::string, Material>& materials, bool strand);

// The settings as the run uses them, for summary.json: every scalar setting and, per material pair entry, the
// coefficient and mu2/mu1 it runs with on each interface it names.
nlohmann::json resolved_contact_settings(const ContactSettings& settings);

}  // namespace strandfem
