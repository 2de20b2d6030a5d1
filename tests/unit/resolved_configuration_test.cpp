// Requirement: summary.json's configuration records every default a case took (docs/results.md): the strand's lay
// directions and start angles, the mesh, the materials, the steps and the output options.
#include <gtest/gtest.h>

#include "strandfem/io/case_file.hpp"

namespace strandfem {
namespace {

TEST(ResolvedConfiguration, RecordsTheDefaultsACaseTook) {
  const CaseDefinition c = load_case_text(R"(
materials:
  steel: {E: 200000, nu: 0.3}
strand:
  length: 100
  layers:
    - {wires: 1, diameter: 3.0, material: steel}
    - {wires: 6, diameter: 3.0, material: steel, lay_angle: 10}
steps:
  - {name: pull, increments: 2, axial_strain: 0.001}
)",
                                          "defaults.yaml");
  const nlohmann::json& r = c.resolved;
  // One layer around the core: laid right-hand, as the outer layer of a conductor (docs/case-files.md).
  const nlohmann::json& layer = r["strand"]["layers"][1];
  EXPECT_EQ(layer["lay_direction"], "right");
  EXPECT_DOUBLE_EQ(layer["lay_angle"].get<double>(), 10.0);
  EXPECT_DOUBLE_EQ(layer["start_angle"].get<double>(), 0.0);
  EXPECT_EQ(r["strand"]["layers"][0]["lay_direction"], "none");
  EXPECT_EQ(r["strand"]["ends"], "fixed");
  EXPECT_DOUBLE_EQ(r["strand"]["clamp_length"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(r["mesh"]["element_length"].get<double>(), 10.0);
  EXPECT_TRUE(r["mesh"]["elements_per_wire"].is_null());
  EXPECT_DOUBLE_EQ(r["materials"]["steel"]["E"].get<double>(), 200000.0);
  EXPECT_TRUE(r["materials"]["steel"]["plasticity"].is_null());
  ASSERT_EQ(r["steps"].size(), 1u);
  EXPECT_EQ(r["steps"][0]["name"], "pull");
  EXPECT_EQ(r["steps"][0]["increments"], 2);
  EXPECT_EQ(r["steps"][0]["cycles"], 0);
  EXPECT_EQ(r["output"]["vtu"], true);
  EXPECT_EQ(r["output"]["contacts_every"], 1);
  EXPECT_DOUBLE_EQ(r["output"]["steady_tolerance"].get<double>(), 0.02);
}

}  // namespace
}  // namespace strandfem
