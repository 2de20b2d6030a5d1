// Requirement: frictional strands pulled and released to zero strain or zero force, cycled between tension and
// release, and bent once under tension reach their end on the default settings at their nominal increments.
#include <gtest/gtest.h>

#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "program_runner.hpp"
#include "test_strands.hpp"

namespace strandfem::verification {
namespace {

std::vector<std::map<std::string, double>> run_inline_case(const std::string& text, const std::string& tag) {
  const std::string file = ::testing::TempDir() + "/" + tag + ".yaml";
  std::ofstream(file) << text;
  const std::string out = ::testing::TempDir() + "/" + tag + "_out";
  const ProgramRun r = run_program("run " + file + " -q -o " + out, tag);
  EXPECT_EQ(r.exit_code, 0) << r.stderr_text;
  return read_csv(std::filesystem::path(out) / "history.csv");
}

std::map<int, int> increments_per_step(const std::vector<std::map<std::string, double>>& rows) {
  std::map<int, int> count;
  for (const auto& row : rows) ++count[static_cast<int>(row.at("step"))];
  return count;
}

// The paper's Table 1 strand, 40 mm, 4 elements per wire, Judge et al.'s mu = 0.115.
const char* kSevenWire = R"(
materials:
  steel: {E: 188000, nu: 0.3, density: 7.85e-9}
strand:
  length: 40
  ends: fixed
  layers:
    - {wires: 1, diameter: 3.94, material: steel}
    - {wires: 6, diameter: 3.73, material: steel, lay_angle: 11.8}
mesh: {elements_per_wire: 4}
contact: {friction: 0.115}
output: {vtu: false}
)";

TEST(LoadReversal, SevenWireStrandReleasedToZeroStrain) {
  const auto rows = run_inline_case(std::string(kSevenWire) + R"(steps:
  - {name: pull, increments: 2, axial_strain: 0.002}
  - {name: release, increments: 2, axial_strain: 0.0}
)", "release_7");
  ASSERT_EQ(rows.size(), 4u);  // nominal increments, no cut-back
  const double peak = rows[1].at("axial_force_N");
  EXPECT_GT(peak, 20000.0);
  // Fixed ends stick and slip little: the release retraces the pull, and zero strain leaves a force of round-off size.
  EXPECT_NEAR(rows[2].at("axial_force_N"), rows[0].at("axial_force_N"), 0.01 * peak);
  EXPECT_NEAR(rows[3].at("axial_force_N"), 0.0, 1e-3 * peak);
}

TEST(LoadReversal, NineteenWireStrandCycledBetweenTensionAndZeroForce) {
  const auto rows = run_inline_case(R"(
materials:
  steel: {E: 188000, nu: 0.3, density: 7.85e-9}
strand:
  length: 60
  ends: fixed
  layers:
    - {wires: 1, diameter: 3.0, material: steel}
    - {wires: 6, diameter: 2.9, material: steel, lay_angle: 12}
    - {wires: 12, diameter: 2.9, material: steel, lay_angle: 13}
mesh: {elements_per_wire: 4}
contact: {friction: 0.2}
output: {vtu: false}
steps:
  - {name: pull, increments: 2, axial_force: 20000}
  - {name: release, increments: 2, axial_force: 0}
  - {name: pull again, increments: 2, axial_force: 25000}
  - {name: release again, increments: 3, axial_force: 0}
)", "cycle_19");
  EXPECT_EQ(increments_per_step(rows), (std::map<int, int>{{1, 2}, {2, 2}, {3, 2}, {4, 3}}));
  ASSERT_EQ(rows.size(), 9u);
  const double loads[] = {10000, 20000, 10000, 0, 12500, 25000, 50000.0 / 3, 25000.0 / 3, 0};
  for (std::size_t i = 0; i < rows.size(); ++i) {
    // Each applied load is met to 0.1 % of its largest value in the step.
    const double largest = i < 2 ? 20000 : (i < 4 ? 20000 : 25000);
    EXPECT_NEAR(rows[i].at("axial_force_N"), loads[i], 1e-3 * largest) << "row " << i;
  }
  // Released to zero force, the strand comes back to its length; the second pull follows the first one's slope.
  const double strain_at_20kN = rows[1].at("axial_strain");
  EXPECT_NEAR(rows[3].at("axial_strain"), 0.0, 1e-3 * strain_at_20kN);
  EXPECT_NEAR(rows[8].at("axial_strain"), 0.0, 1e-3 * strain_at_20kN);
  EXPECT_NEAR(rows[5].at("axial_strain") / 25000, strain_at_20kN / 20000, 0.01 * strain_at_20kN / 20000);
}

// The inner 19 wires of S32, 200 mm, 10 kN, then 1 kN at midspan and back, mu = 0.2, nothing numerical set: the
// peak lies within eq. 3.1's bounds, the strand carries the load asked for, and the run takes at most 1.5 times its
// nominal increments.
TEST(LoadReversal, NineteenWireStrandBentOnceUnderTensionOnTheDefaults) {
  const std::string tag = "bend_19_defaults";
  const auto rows = run_inline_case(nineteen_wire_bent_once(), tag);
  ASSERT_FALSE(rows.empty());
  EXPECT_NEAR(rows.back().at("load_factor"), 3.0, 1e-9);
  EXPECT_LE(rows.size(), 19u);  // 3 + 2 x 5 nominal increments, times 1.5
  const auto out = std::filesystem::path(::testing::TempDir()) / (tag + "_out");
  const nlohmann::json summary = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  const nlohmann::json& loop = summary["bending"]["loops"].at(0);
  EXPECT_TRUE(loop["peak_within_eq31"].get<bool>());
  EXPECT_NEAR(loop["peak_load_N"].get<double>(), 1000.0, 1.0);  // met to 0.1 % of V
  EXPECT_GT(loop["area_Nmm"].get<double>(), 0.0);
}

}  // namespace
}  // namespace strandfem::verification
