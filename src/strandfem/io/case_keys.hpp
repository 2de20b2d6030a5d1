// The keys a case file may hold, mapping by mapping: the one table the reader checks every mapping against and
// docs/case-files.md lists (a test compares the two).
#pragma once
#include <string>
#include <vector>

#include "strandfem/io/setting_keys.hpp"

namespace strandfem {

// A mapping of a case file and the keys it may hold. Mappings are named as the documentation writes paths:
// "strand.layers[i]", "materials.<name>.plasticity", "steps[i].transverse_force"; a mapping whose keys depend on
// the case's kind or on a `type` adds it in parentheses ("steps[i] (beams)", "beams[i].shape (arc)"), and
// "selector (strands)" / "selector (beams)" are the node selectors of `at`, hub `links` and `output.monitor`.
struct CaseKeyGroup {
  std::string mapping;
  std::vector<const char*> keys;
};

const std::vector<CaseKeyGroup>& case_key_table();

// The top level's own values (its other keys are the mappings of the table).
struct CaseHeading {
  std::string title = "untitled";
  YAML::Node description, expected;  // free-form; the program ignores them
};
const std::vector<SettingKey<CaseHeading>>& case_heading_key_table();

// `output.monitor`: a node selector, resolved with the case's nodes.
struct MonitorKey {
  YAML::Node monitor;
};
const std::vector<SettingKey<MonitorKey>>& monitor_key_table();

// The keys of one mapping of the table; std::logic_error for a mapping the table does not have (a bug).
const std::vector<const char*>& allowed_keys(const std::string& mapping);

// The rows of docs/case-files.md in one section of the page: every key declared with its type, range and default,
// in the tables' order.
std::vector<std::string> setting_key_rows(KeySection section);

}  // namespace strandfem
