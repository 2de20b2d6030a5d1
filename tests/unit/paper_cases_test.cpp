// Requirement: the paper's case files hold physics only: no solver key, and of the contact keys only friction's
// (coefficients, pairs, zones, orthotropy, direction), so that every paper case runs on the defaults.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <set>
#include <string>

namespace {

TEST(PaperCases, SetNoNumericalKey) {
  const std::set<std::string> friction_keys = {"friction", "friction_pairs", "friction_zones", "orthotropy_ratio",
                                               "friction_direction"};
  int files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(std::string(STRANDFEM_SOURCE_DIR) + "/cases/paper")) {
    if (entry.path().extension() != ".yaml") continue;
    ++files;
    const YAML::Node node = YAML::LoadFile(entry.path().string());
    EXPECT_FALSE(node["solver"]) << entry.path() << " sets solver keys";
    if (!node["contact"]) continue;
    for (const auto& key : node["contact"])
      EXPECT_TRUE(friction_keys.count(key.first.as<std::string>())) << entry.path() << " sets contact." << key.first.as<std::string>();
  }
  EXPECT_GE(files, 27);  // the paper's cases are all there
}

}  // namespace
