// Requirement: docs/case-files.md lists exactly the keys the reader accepts (case_key_table), both ways.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <string>

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

TEST(CaseKeys, EveryMappingOfTheTableIsFoundByName) {
  for (const CaseKeyGroup& group : case_key_table()) EXPECT_EQ(&allowed_keys(group.mapping), &group.keys) << group.mapping;
  EXPECT_THROW(allowed_keys("no such mapping"), std::logic_error);
}

}  // namespace
}  // namespace strandfem
