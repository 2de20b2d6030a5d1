// Requirement (issue 9, sweep): a case variant sets one key, found by a dot path through maps and lists, and a path
// that leads nowhere is refused naming it.
#include "strandfem/io/case_variant.hpp"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <fstream>

#include "strandfem/io/case_file.hpp"
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

// The sweep key contact.orthotropy_ratio reaches the pairs without a ratio of their own (Fig. 19: the steel pairs
// stay isotropic), and the results' configuration says which ratio each pair ran with.
TEST(CaseVariant, OrthotropyRatioReachesPairsWithoutTheirOwn) {
  const std::string text = set_case_key(std::string(kCase) + R"(materials:
  steel: {E: 200000, nu: 0.3}
  aluminum: {E: 65000, nu: 0.33}
steps:
  - {name: pull, increments: 1, axial_strain: 0.001}
)", "contact", "{friction: 0.5, friction_pairs: [{materials: [steel, steel], mu: 0.3, orthotropy_ratio: 1}, {materials: [steel, aluminum], mu: 0.4}]}");
  std::string with_materials = set_case_key(text, "strand.layers.0.material", "steel");
  with_materials = set_case_key(with_materials, "strand.layers.1.material", "aluminum");
  const YAML::Node with_ratio = YAML::Load(set_case_key(with_materials, "contact.orthotropy_ratio", "15"));
  const std::string file = ::testing::TempDir() + "/orthotropy_pairs.yaml";
  std::ofstream(file) << YAML::Dump(with_ratio);
  const CaseDefinition c = load_case(file);
  constexpr ContactInterface radial = ContactInterface::kRadial;
  EXPECT_DOUBLE_EQ(c.model.contact_settings.orthotropy_at("steel", "steel", radial), 1.0);
  EXPECT_DOUBLE_EQ(c.model.contact_settings.orthotropy_at("aluminum", "steel", radial), 15.0);
  EXPECT_DOUBLE_EQ(c.model.contact_settings.orthotropy_at("aluminum", "aluminum", radial), 15.0);
  const nlohmann::json& pairs = c.resolved["contact"]["pairs"];
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_DOUBLE_EQ(pairs[0]["orthotropy_ratio"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(pairs[1]["orthotropy_ratio"].get<double>(), 15.0);
  EXPECT_DOUBLE_EQ(pairs[1]["mu"].get<double>(), 0.4);
  EXPECT_EQ(pairs[1]["contacts"], "all");
}

// A friction_pairs entry limited to lateral contacts that sets only a ratio (Fig. 19 with the orthotropy on the
// radial aluminum contacts alone): the results' configuration gives the coefficient it runs with, the contact's.
TEST(CaseVariant, PairEntryLimitedToLateralContacts) {
  const std::string text = set_case_key(std::string(kCase) + R"(materials:
  steel: {E: 200000, nu: 0.3}
steps:
  - {name: pull, increments: 1, axial_strain: 0.001}
)", "contact", "{friction: 0.7, orthotropy_ratio: 15, friction_pairs: [{materials: [steel, steel], contacts: lateral, orthotropy_ratio: 1}]}");
  const std::string file = ::testing::TempDir() + "/lateral_pair.yaml";
  std::ofstream(file) << set_case_key(set_case_key(text, "strand.layers.0.material", "steel"), "strand.layers.1.material", "steel");
  const CaseDefinition c = load_case(file);
  const nlohmann::json& pair = c.resolved["contact"]["pairs"][0];
  EXPECT_EQ(pair["contacts"], "lateral");
  EXPECT_DOUBLE_EQ(pair["mu"].get<double>(), 0.7);
  EXPECT_DOUBLE_EQ(pair["orthotropy_ratio"].get<double>(), 1.0);
  EXPECT_FALSE(pair.contains("radial"));
  EXPECT_DOUBLE_EQ(c.model.contact_settings.orthotropy_at("steel", "steel", ContactInterface::kRadial), 15.0);
}

}  // namespace
}  // namespace strandfem
