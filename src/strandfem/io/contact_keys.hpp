// The case file's `contact:` mapping (friction per pair and zone, penalty factors, search, overlap).
#pragma once
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "strandfem/beam/section.hpp"
#include "strandfem/contact/contact_settings.hpp"
#include "strandfem/io/setting_keys.hpp"
#include "strandfem/io/yaml_reader.hpp"

namespace strandfem {

// The keys of `contact:`, each with its type, range, default and meaning; its two lists have tables of their own.
const std::vector<SettingKey<ContactSettings>>& contact_key_table();

// An entry of `contact.friction_pairs` as the case gives it; the materials must be two of `materials`.
struct FrictionPairKeys {
  YAML::Node materials;
  std::optional<double> mu, orthotropy_ratio;
  std::string contacts;  // lateral | radial; empty: both
};
const std::vector<SettingKey<FrictionPairKeys>>& friction_pair_key_table();

// An entry of `contact.friction_zones`.
struct FrictionZoneKeys {
  double z_min = 0, z_max = 0;  // mm
  double mu = 0;
  YAML::Node materials;  // a list of material pairs, where the entry gives it (else all)
  std::string contacts;  // lateral | radial; empty: both
};
const std::vector<SettingKey<FrictionZoneKeys>>& friction_zone_key_table();

// Reads and validates `contact:` (docs/case-files.md); `strand`: the case is a strand (no `axis` key).
// Throws CaseError naming the key.
ContactSettings parse_contact_settings(const YamlReader& reader, const YAML::Node& node,
                                       const std::map<std::string, Material>& materials, bool strand);

// The settings as the run uses them, for summary.json: every scalar setting and, per material pair entry, the
// coefficient and mu2/mu1 it runs with on each interface it names.
nlohmann::json resolved_contact_settings(const ContactSettings& settings);

}  // namespace strandfem
