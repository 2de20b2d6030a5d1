// The case file's `contact:` mapping (friction per pair and zone, penalty factors, search, overlap).
#pragma once
#include <map>
#include <string>

#include "strandfem/beam/section.hpp"
#include "strandfem/contact/contact_settings.hpp"
#include "strandfem/io/yaml_reader.hpp"

namespace strandfem {

// Reads and validates `contact:` (docs/case-files.md); `strand`: the case is a strand (no `axis` key).
// Throws CaseError naming the key.
ContactSettings parse_contact_settings(const YamlReader& reader, const YAML::Node& node,
                                       const std::map<std::string, Material>& materials, bool strand);

}  // namespace strandfem
