// Requirement: docs/case-files.md lists exactly the keys the reader accepts (case_key_table), both ways, and the
// defaults of the solver and contact keys the reader takes.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>

#include "strandfem/io/case_file.hpp"
#include "strandfem/io/case_keys.hpp"

namespace strandfem {
namespace {

// The table's keys as full paths, in the documentation's form ("strand.layers[i].wires", "selector.core").
std::set<std::string> table_paths() {
  std::set<std::string> paths;
  for (const CaseKeyGroup& group : case_key_table()) {
    std::string mapping = group.mapping.substr(0, group.mapping.find(" ("));
    for (const char* key : group.keys) paths.insert(mapping.empty() ? key : mapping + "." + key);
  }
  return paths;
}

// The key column of every "| key |" table in the page: backticked paths; a bare name (`max_cutbacks`) takes the
// mapping of the cell's first path (`solver.max_iterations`, `max_cutbacks`).
std::set<std::string> documented_paths(const std::string& page) {
  std::set<std::string> paths;
  std::ifstream in(page);
  std::string line;
  bool in_key_table = false;
  const std::regex code("`([^`]+)`");
  while (std::getline(in, line)) {
    if (line.rfind("| key |", 0) == 0) {
      in_key_table = true;
      continue;
    }
    if (line.rfind("|", 0) != 0) {
      in_key_table = false;
      continue;
    }
    if (!in_key_table || line.rfind("|---", 0) == 0) continue;
    const std::string cell = line.substr(1, line.find('|', 1) - 1);
    std::string prefix;
    for (auto it = std::sregex_iterator(cell.begin(), cell.end(), code); it != std::sregex_iterator(); ++it) {
      const std::string path = (*it)[1];
      const auto dot = path.rfind('.');
      if (prefix.empty() && dot != std::string::npos) prefix = path.substr(0, dot + 1);
      paths.insert(dot == std::string::npos && !prefix.empty() ? prefix + path : path);
    }
  }
  return paths;
}

TEST(CaseKeys, TheDocumentationListsExactlyTheKeysTheReaderAccepts) {
  const std::set<std::string> table = table_paths();
  const std::set<std::string> documented = documented_paths(std::string(STRANDFEM_SOURCE_DIR) + "/docs/case-files.md");
  ASSERT_GT(documented.size(), 100u);
  // A key that holds a mapping or a list is documented by its own row or by the rows of what it holds.
  const auto is_documented = [&documented](const std::string& path) {
    for (const std::string& d : documented)
      if (d == path || d.rfind(path + ".", 0) == 0 || d.rfind(path + "[i]", 0) == 0 || d.rfind(path + ".<name>", 0) == 0) return true;
    return false;
  };
  for (const std::string& path : table) EXPECT_TRUE(is_documented(path)) << path << " is read but not in docs/case-files.md";
  for (const std::string& path : documented) EXPECT_TRUE(table.count(path)) << path << " is in docs/case-files.md but not read";
}


// The default each `solver.*` and `contact.*` row of docs/case-files.md states: from the default column, or from
// "default X" in the text ("default 0.005 each", "default 25, 8", "fKn (default 1), ξn (default 10)"), by key.
std::map<std::string, std::string> documented_defaults(const std::string& page) {
  std::map<std::string, std::string> defaults;
  std::ifstream in(page);
  std::string line;
  const std::regex code("`([^`]+)`");
  const std::regex stated("default ([^;:()]+)");
  bool default_column = false;
  while (std::getline(in, line)) {
    if (line.rfind("| key |", 0) == 0) default_column = line.find("| default |") != std::string::npos;
    if (line.rfind("| `solver.", 0) != 0 && line.rfind("| `contact.", 0) != 0) continue;
    std::vector<std::string> cells;
    for (std::size_t at = 1, next; (next = line.find(" |", at)) != std::string::npos; at = next + 2) cells.push_back(line.substr(at, next - at));
    std::vector<std::string> keys;
    std::string prefix;
    for (auto it = std::sregex_iterator(cells[0].begin(), cells[0].end(), code); it != std::sregex_iterator(); ++it) {
      const std::string path = (*it)[1];
      const auto dot = path.rfind('.');
      if (prefix.empty() && dot != std::string::npos) prefix = path.substr(0, dot + 1);
      keys.push_back(dot == std::string::npos ? prefix + path : path);
    }
    std::vector<std::string> values;
    if (default_column) {
      values.push_back(cells.size() > 2 ? cells[2] : "");
    } else {
      const std::string text = line.substr(line.find(" |") + 2);
      for (auto it = std::sregex_iterator(text.begin(), text.end(), stated); it != std::sregex_iterator(); ++it) {
        std::string v = std::regex_replace(std::string((*it)[1]), std::regex(" each$|\\s+$"), "");
        for (std::size_t at = 0, comma; at <= v.size(); at = comma + 2) {
          comma = v.find(", ", at);
          if (comma == std::string::npos) comma = v.size();
          values.push_back(v.substr(at, comma - at));
        }
      }
    }
    const bool each = values.size() == 1;
    for (std::size_t k = 0; k < keys.size() && (each || k < values.size()); ++k) {
      std::string v = each ? values[0] : values[k];
      v = std::regex_replace(v, std::regex("^\\s+|\\s+$|`"), "");
      defaults[keys[k]] = v;
    }
  }
  return defaults;
}

TEST(CaseKeys, TheDocumentedDefaultsAreTheOnesTheReaderTakes) {
  const CaseDefinition c = load_case_text(R"(
materials: {steel: {E: 200000, nu: 0.3}}
strand: {length: 60, layers: [{wires: 1, diameter: 3.0, material: steel}, {wires: 6, diameter: 3.0, material: steel, lay_angle: 10}]}
contact: {enabled: true}
steps: [{name: pull, increments: 1, axial_strain: 0.001}]
)",
                                          "defaults.yaml");
  const std::map<std::string, std::string> documented = documented_defaults(std::string(STRANDFEM_SOURCE_DIR) + "/docs/case-files.md");
  int compared = 0;
  for (const auto& [path, text] : documented) {
    const auto dot = path.find('.');
    const nlohmann::json& section = c.resolved[path.substr(0, dot)];
    const std::string key = path.substr(dot + 1);
    if (!section.contains(key) || text.empty() || text.find(' ') != std::string::npos) continue;
    const nlohmann::json& value = section[key];
    if (value.is_number()) {
      char* end = nullptr;
      const double stated = std::strtod(text.c_str(), &end);
      if (end == text.c_str() || *end != '\0') continue;  // a rule in words, not a number
      EXPECT_NEAR(value.get<double>(), stated, 1e-12 * std::abs(stated)) << path;
    } else if (value.is_boolean()) {
      EXPECT_EQ(value.get<bool>() ? "true" : "false", text) << path;
    } else if (value.is_string()) {
      EXPECT_EQ(value.get<std::string>(), text) << path;
    } else {
      continue;
    }
    ++compared;
  }
  // Every solver and contact setting with a plain default (measured: 33 of them).
  EXPECT_GE(compared, 30);
}

TEST(CaseKeys, EveryMappingOfTheTableIsFoundByName) {
  for (const CaseKeyGroup& group : case_key_table()) EXPECT_EQ(&allowed_keys(group.mapping), &group.keys) << group.mapping;
  EXPECT_THROW(allowed_keys("no such mapping"), std::logic_error);
}

}  // namespace
}  // namespace strandfem
