// Requirement (issue 9, sweep): a case variant sets one key, found by a dot path through maps and lists, and a path
// that leads nowhere is refused naming it.
#include "strandfem/io/case_variant.hpp"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "strandfem/io/yaml_reader.hpp"

namespace strandfem {
namespace {

constexpr const char* kCase = R"(title: t
strand:
  length: 200
  layers:
    - {wires: 1, diameter: 3.94}
    - {wires: 6, diameter: 3.73, lay_angle: 11.8}
contact: {friction: 0.3}
)";

TEST(CaseVariant, SetsKeysThroughMapsAndLists) {
  const YAML::Node friction = YAML::Load(set_case_key(kCase, "contact.friction", "0.7"));
  EXPECT_DOUBLE_EQ(friction["contact"]["friction"].as<double>(), 0.7);
  EXPECT_DOUBLE_EQ(friction["strand"]["length"].as<double>(), 200);  // the rest untouched
  const YAML::Node angle = YAML::Load(set_case_key(kCase, "strand.layers.1.lay_angle", "14"));
  EXPECT_DOUBLE_EQ(angle["strand"]["layers"][1]["lay_angle"].as<double>(), 14);
  EXPECT_DOUBLE_EQ(angle["strand"]["layers"][0]["diameter"].as<double>(), 3.94);
  // A new key in an existing map, and a flow list as the value.
  const YAML::Node added = YAML::Load(set_case_key(kCase, "contact.orthotropy_ratio", "5"));
  EXPECT_DOUBLE_EQ(added["contact"]["orthotropy_ratio"].as<double>(), 5);
  const YAML::Node list = YAML::Load(set_case_key(kCase, "strand.layers.0.start_angles", "[0, 90]"));
  EXPECT_EQ(list["strand"]["layers"][0]["start_angles"].size(), 2u);
}

TEST(CaseVariant, PathsThatLeadNowhereAreRefusedByName) {
  auto message = [](const std::string& path, const std::string& value) {
    try {
      set_case_key(kCase, path, value);
    } catch (const CaseError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("solver.max_iterations", "5").find("no 'solver'"), std::string::npos);
  EXPECT_NE(message("strand.layers.2.lay_angle", "5").find("list of 2 entries"), std::string::npos);
  EXPECT_NE(message("strand.layers.x", "5").find("expected an index"), std::string::npos);
  EXPECT_NE(message("strand.length.x", "5").find("is a value"), std::string::npos);
  EXPECT_NE(message("contact..friction", "5").find("empty part"), std::string::npos);
  EXPECT_NE(message("contact.friction", "").find("expected a value"), std::string::npos);
  EXPECT_EQ(variant_folder_name("contact.friction", "0.5"), "contact.friction=0.5");
  EXPECT_EQ(variant_folder_name("a.b", "[1, 2]"), "a.b=_1__2_");
}

}  // namespace
}  // namespace strandfem
