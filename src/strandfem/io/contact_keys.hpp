// The case file's `contact:` mapping (friction per pair and zone, penalty factors, search, overlap).
#pragma once
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "strandfem/beam/section.hpp"
#include "strandfem/contact/contact_settings.hpp"
#include "strandfem/io/yaml_reader.hpp"

namespace strandfem {

// Reads and validates `contact:` (docs/case-files.md); `strand`: the case is a strand (no `axis` key).
// Throws CaseError naming the key.
ContactSettings parse_contact_settings(const YamlReader& reader, const YAML::Node& node,
                                       const std::map<std::string, Material>& materials, bool strand);

// The settings as the run uses them, for summary.json: every scalar setting and, per material pair entry, the
// coefficient and mu2/mu1 it runs with on each interface it names.
nlohmann::json resolved_contact_settings(const ContactSettings& settings);

}  // namespace strandfem
