// Requirement: docs/case-files.md lists exactly the keys the reader accepts (case_key_table), both ways, and writes
// every solver and contact key with the type, range, default and meaning the reader's tables declare.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>

#include "strandfem/io/beam_keys.hpp"
#include "strandfem/io/case_file.hpp"
#include "strandfem/io/case_keys.hpp"
#include "strandfem/io/contact_keys.hpp"
#include "strandfem/io/load_keys.hpp"
#include "strandfem/io/model_keys.hpp"
#include "strandfem/io/output_keys.hpp"
#include "strandfem/io/solver_keys.hpp"

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


// The rows of the page that start with a key's path ("| `solver.force_tolerance` |"), by path.
std::map<std::string, std::string> documented_rows(const std::string& page) {
  std::map<std::string, std::string> rows;
  std::ifstream in(page);
  std::string line;
  const std::regex row("^\\| `([A-Za-z0-9_.<>\\[\\]]+)` \\|");
  std::smatch match;
  while (std::getline(in, line))
    if (std::regex_search(line, match, row)) rows[match[1]] = line;
  return rows;
}

TEST(CaseKeys, ThePageWritesEverySettingKeyAsTheReaderDeclaresIt) {
  const std::map<std::string, std::string> documented = documented_rows(std::string(STRANDFEM_SOURCE_DIR) + "/docs/case-files.md");
  std::size_t compared = 0;
  for (KeySection section : {KeySection::kPhysics, KeySection::kAdvanced})
    for (const std::string& row : setting_key_rows(section)) {
      const std::string path = row.substr(3, row.find('`', 3) - 3);
      const auto page = documented.find(path);
      ASSERT_NE(page, documented.end()) << path << " has no row of its own in docs/case-files.md (`strandfem keys` prints it)";
      EXPECT_EQ(page->second, row) << path << ": docs/case-files.md differs from the reader's table (`strandfem keys` prints it)";
      ++compared;
    }
  EXPECT_EQ(compared, solver_key_table().size() + contact_key_table().size() + output_key_table().size() + material_key_table().size() +
                          plasticity_key_table().size() + friction_pair_key_table().size() + friction_zone_key_table().size() + strand_key_table().size() + layer_key_table().size() + mesh_key_table().size() + step_key_table().size() +
                          strand_end_load_key_table().size() + transverse_force_key_table().size() + beam_key_table().size() +
                          section_key_table().size() + shape_key_table().size() + hub_key_table().size() + support_key_table().size() +
                          force_key_table().size() + motion_key_table().size() + strand_selector_key_table().size() +
                          beam_selector_key_table().size() + case_heading_key_table().size() + monitor_key_table().size());
}

// The defaults the table shows are those a case without the keys runs with.
TEST(CaseKeys, TheTablesDefaultsAreTheOnesACaseTakes) {
  const CaseDefinition c = load_case_text(R"(
materials: {steel: {E: 200000, nu: 0.3}}
strand: {length: 60, layers: [{wires: 1, diameter: 3.0, material: steel}, {wires: 6, diameter: 3.0, material: steel, lay_angle: 10}]}
contact: {}
steps: [{name: pull, increments: 1, axial_strain: 0.001}]
)",
                                          "defaults.yaml");
  for (const auto& key : solver_key_table()) EXPECT_EQ(c.resolved["solver"][key.name], key.value(SolverOptions{})) << key.name;
  for (const auto& key : contact_key_table())
    if (key.default_rule.empty()) EXPECT_EQ(c.resolved["contact"][key.name], key.value(ContactSettings{})) << key.name;
  for (const auto& key : output_key_table())
    if (key.default_rule.empty()) EXPECT_EQ(c.resolved["output"][key.name], key.value(OutputOptions{})) << key.name;
  EXPECT_TRUE(c.resolved["contact"]["enabled"].get<bool>());
  EXPECT_TRUE(c.resolved["contact"]["normal_smoothing"].is_null());
  for (const auto& key : strand_key_table())
    if (!key.required) EXPECT_EQ(c.resolved["strand"][key.name], key.value(StrandSettings{})) << key.name;
  for (const auto& key : layer_key_table())
    if (!key.required && key.default_rule.empty()) EXPECT_EQ(c.resolved["strand"]["layers"][1][key.name], key.value(LayerSpec{})) << key.name;
  // The rule in words: alternating from a right-hand outer layer inward.
  EXPECT_EQ(c.resolved["strand"]["layers"][1]["lay_direction"], "right");
  EXPECT_EQ(c.resolved["strand"]["layers"][0]["lay_direction"], "none");
}

// A value outside a key's range is refused with the key, its place in the file and the range.
TEST(CaseKeys, AValueOutsideItsRangeNamesTheKeyAndTheRange) {
  const auto error_of = [](const std::string& settings) {
    try {
      load_case_text("materials: {steel: {E: 200000, nu: 0.3}}\nstrand: {length: 60, layers: [{wires: 1, diameter: 3.0, material: steel}]}\n"
                     "steps: [{name: pull, increments: 1, axial_strain: 0.001}]\n" + settings + "\n",
                     "range.yaml");
    } catch (const CaseError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(error_of("solver: {newton_forcing: 1.5}"), "range.yaml:4:26: solver.newton_forcing: expected a value in [0, 1], got 1.5");
  EXPECT_EQ(error_of("contact: {line_contact_angle: 90}"), "range.yaml:4:31: contact.line_contact_angle: expected a value in (0, 90), got 90");
  EXPECT_EQ(error_of("contact: {friction: 10}"), "range.yaml:4:21: contact.friction: expected a value in [0, 10), got 10");
  EXPECT_NE(error_of("solver: {max_cutbacks: 31}").find("solver.max_cutbacks: expected an integer in 0..30"), std::string::npos);
  EXPECT_NE(error_of("contact: {tangential_penalty: soft}").find("contact.tangential_penalty: expected one of: elastic_slip, paper"),
            std::string::npos);
  EXPECT_EQ(error_of("contact: {stick_tolerance: 0.5}"), "accepted");
  // Angles are read in degrees and checked in degrees.
  const auto layer_error = [](const std::string& outer_layer) {
    try {
      load_case_text("materials: {steel: {E: 200000, nu: 0.3}}\nstrand: {length: 60, layers: [{wires: 1, diameter: 3.0, material: steel}, " +
                         outer_layer + "]}\nsteps: [{name: pull, increments: 1, axial_strain: 0.001}]\n",
                     "layer.yaml");
    } catch (const CaseError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(layer_error("{wires: 6, diameter: 3.0, material: steel, lay_angle: 90}"),
            "layer.yaml:2:129: strand.layers[1].lay_angle: expected an angle in (0, 90) degrees, got 90");
  EXPECT_NE(layer_error("{wires: 6, diameter: 3.0, material: steel}").find("layer.yaml:2:75: strand.layers[1].lay_angle: missing required key"), std::string::npos);
  EXPECT_EQ(layer_error("{wires: 6, diameter: 3.0, material: steel, lay_angle: 10, lay_direction: left}"), "accepted");
}

TEST(SettingKeys, NumbersAndRangesAreWrittenAsThePageWritesThem) {
  EXPECT_EQ(number_text(1e-8), "1e-8");
  EXPECT_EQ(number_text(0.0005), "0.0005");
  EXPECT_EQ(number_text(25), "25");
  EXPECT_EQ(number_text(3.75), "3.75");
  EXPECT_EQ(number_text(1e15), "1e15");
  EXPECT_EQ(NumberRange::positive().text(), "> 0");
  EXPECT_EQ(NumberRange::non_negative().text(), "≥ 0");
  EXPECT_EQ(NumberRange::half_open(0, 0.5).text(), "in [0, 0.5)");
  EXPECT_TRUE(NumberRange::half_open(0, 1).contains(0));
  EXPECT_FALSE(NumberRange::half_open(0, 1).contains(1));
  EXPECT_FALSE(NumberRange::open(0, 90).contains(0));
  EXPECT_TRUE(NumberRange::closed(0, 1).contains(1));
}

TEST(CaseKeys, EveryMappingOfTheTableIsFoundByName) {
  for (const CaseKeyGroup& group : case_key_table()) EXPECT_EQ(&allowed_keys(group.mapping), &group.keys) << group.mapping;
  EXPECT_THROW(allowed_keys("no such mapping"), std::logic_error);
}

}  // namespace
}  // namespace strandfem
