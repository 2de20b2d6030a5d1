// Requirement (issue 9): the trends of the paper's friction studies hold on a shortened strand (the inner 19 wires
// of S32 over 200 mm, T = 10 kN, V = 1 kN out and back): raising mu raises the bending stiffness and shrinks the
// loop (section 5.1); mu2/mu1 > 1 shrinks the loop (section 5.3). Every peak lies between eq. 3.1's bounds, and
// most of every loop is friction's work.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "program_runner.hpp"

namespace strandfem::verification {
namespace {

constexpr const char* kCase = "cases/verification/bending_friction_trends.yaml";

std::map<std::string, double> first_loop(const std::filesystem::path& results) {
  const auto loops = read_csv(results / "loops.csv");
  return loops.empty() ? std::map<std::string, double>{} : loops[0];
}

std::filesystem::path sweep(const std::string& key, const std::string& values, const std::string& tag) {
  const auto folder = std::filesystem::path(::testing::TempDir()) / ("strandfem_" + tag);
  const ProgramRun run = run_program("sweep " + case_path(kCase) + " --key " + key + " --values " + values + " -q -o " + folder.string(), tag);
  EXPECT_EQ(run.exit_code, 0) << run.stderr_text;
  return folder;
}

// kCase with each `from` text replaced by its `to`, written to the test's temporary folder as `name`.yaml.
std::string case_variant(const std::vector<std::pair<std::string, std::string>>& replacements, const std::string& name) {
  std::ifstream in(case_path(kCase));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const auto& [from, to] : replacements) {
    EXPECT_NE(text.find(from), std::string::npos) << from;
    if (text.find(from) != std::string::npos) text.replace(text.find(from), from.size(), to);
  }
  const std::string path = ::testing::TempDir() + "/" + name + ".yaml";
  std::ofstream(path) << text;
  return path;
}

void expect_between_bounds(const std::map<std::string, double>& loop, const std::string& name) {
  ASSERT_FALSE(loop.empty()) << name;
  const double peak = loop.at("peak_deflection_mm") - loop.at("start_deflection_mm");
  EXPECT_GT(peak, loop.at("eq31_ei_max_mm")) << name;
  EXPECT_LT(peak, loop.at("eq31_ei_min_mm")) << name;
}

// Most of the loop is friction's work (the rest is the set the cycle leaves locked in).
void expect_friction_loop(const std::map<std::string, double>& loop, const std::string& name) {
  ASSERT_FALSE(loop.empty()) << name;
  EXPECT_GT(loop.at("friction_dissipation_Nmm"), 0.5 * loop.at("area_Nmm")) << name;
  EXPECT_LE(loop.at("friction_dissipation_Nmm"), loop.at("area_Nmm")) << name;
}

// Measured: secant EI 105.9, 154.8, 206.5 N m^2, loop areas 75.9, 34.3, 13.8 N mm and friction
// dissipation 61.4, 25.2, 10.4 N mm for mu 0.2, 0.4, 0.8.
TEST(FrictionTrends, HigherFrictionStiffensTheStrandAndShrinksTheLoop) {
  const auto folder = sweep("contact.friction", "0.2,0.4,0.8", "trend_friction");
  const auto low = first_loop(folder / "contact.friction=0.2"), mid = first_loop(folder / "contact.friction=0.4"),
             high = first_loop(folder / "contact.friction=0.8");
  for (const auto& [loop, name] : {std::make_pair(low, "0.2"), std::make_pair(mid, "0.4"), std::make_pair(high, "0.8")}) {
    expect_between_bounds(loop, name);
    expect_friction_loop(loop, name);
  }
  ASSERT_FALSE(low.empty() || mid.empty() || high.empty());
  EXPECT_GT(mid.at("secant_ei_Nm2"), 1.2 * low.at("secant_ei_Nm2"));
  EXPECT_GT(high.at("secant_ei_Nm2"), 1.2 * mid.at("secant_ei_Nm2"));
  EXPECT_LT(mid.at("area_Nmm"), 0.6 * low.at("area_Nmm"));
  EXPECT_LT(high.at("area_Nmm"), 0.6 * mid.at("area_Nmm"));
  EXPECT_GT(high.at("area_Nmm"), 2e-2 * high.at("peak_load_N") * (high.at("peak_deflection_mm") - high.at("start_deflection_mm")))
      << "a loop (7 % of V y_peak), not an elastic response";
}

// Measured: mu2/mu1 = 5 at mu1 = 0.2 gives a loop of 67.1 N mm against 75.9 and secant EI 111.5 against 105.9 N m^2.
TEST(FrictionTrends, OrthotropicFrictionShrinksTheLoop) {
  const auto folder = sweep("contact.orthotropy_ratio", "1,5", "trend_orthotropy");
  const auto isotropic = first_loop(folder / "contact.orthotropy_ratio=1"), orthotropic = first_loop(folder / "contact.orthotropy_ratio=5");
  expect_between_bounds(isotropic, "ratio 1");
  expect_between_bounds(orthotropic, "ratio 5");
  ASSERT_FALSE(isotropic.empty() || orthotropic.empty());
  EXPECT_LT(orthotropic.at("area_Nmm"), 0.95 * isotropic.at("area_Nmm"));
  EXPECT_GT(orthotropic.at("secant_ei_Nm2"), 1.02 * isotropic.at("secant_ei_Nm2"));
}

// contact.friction_direction: at mu2/mu1 = 5 (mu1 0.2, every contact orthotropic), direction 1 along the slave wire
// instead of the strand axis. Measured: loops 72.81 against 67.16 N mm (75.9 isotropic), friction's
// work 59.02 against 54.47, secant EI 111.8 against 111.5 N m^2: the reading changes the loop by 8 %, and both
// still bend between eq. 3.1's bounds. The summary says which reading ran.
TEST(FrictionTrends, FrictionDirectionAlongTheSlaveWireIsAnotherReading) {
  const std::string orthotropic_case =
      case_variant({{"elastic_slip: 0.0005}", "elastic_slip: 0.0005, orthotropy_ratio: 5}"}}, "friction_trends_orthotropic");
  const auto folder = std::filesystem::path(::testing::TempDir()) / "strandfem_trend_direction";
  const ProgramRun run = run_program("sweep " + orthotropic_case + " --key contact.friction_direction --values strand_axis,slave_wire -q -o " +
                                         folder.string(),
                                     "trend_direction");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  std::map<std::string, std::map<std::string, double>> loops;
  for (const std::string direction : {"strand_axis", "slave_wire"}) {
    const auto results = folder / ("contact.friction_direction=" + direction);
    loops[direction] = first_loop(results);
    expect_between_bounds(loops[direction], direction);
    expect_friction_loop(loops[direction], direction);
    const nlohmann::json summary = nlohmann::json::parse(std::ifstream(results / "summary.json"));
    EXPECT_EQ(summary["configuration"]["contact"]["friction_direction"], direction);
  }
  ASSERT_FALSE(loops["strand_axis"].empty() || loops["slave_wire"].empty());
  EXPECT_GT(std::abs(loops["slave_wire"].at("area_Nmm") / loops["strand_axis"].at("area_Nmm") - 1.0), 0.04);
}

// Three cycles of mu 0.2: the first loop also locks in a set, the repeated ones are friction's work and repeat
// each other (the paper: steady from the second cycle). On this 5-increment segment cycle 3 still differs from
// cycle 2 by about 6 % in area (it shakes down slowly), so the case asks output.steady_tolerance 0.1: cycle 3
// is steady by it, cycle 2 is not; at the default 0.02 neither would be.
TEST(FrictionTrends, RepeatedCyclesAreFrictionsWorkAndSteady) {
  const std::string three_cycles = case_variant({{"cycles: 1,", "cycles: 3,"},
                                                 {"output: {vtu: false}", "output: {vtu: false, steady_tolerance: 0.1}"}},
                                                "friction_trends_three_cycles");
  const auto results = std::filesystem::path(::testing::TempDir()) / "strandfem_friction_three_cycles" / "results";
  const ProgramRun run = run_program("run " + three_cycles + " -q -o " + results.string(), "friction_three_cycles");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  const auto loops = read_csv(results / "loops.csv");
  ASSERT_EQ(loops.size(), 3u);
  EXPECT_LT(loops[1].at("area_Nmm"), 0.5 * loops[0].at("area_Nmm"));
  for (int c : {1, 2}) {
    EXPECT_NEAR(loops[c].at("area_Nmm"), loops[c].at("friction_dissipation_Nmm"), 0.05 * loops[c].at("area_Nmm")) << c;
    expect_between_bounds(loops[c], "cycle " + std::to_string(c + 1));
    // The paper's presentation (the previous return half and this loading half, peak to peak) carries no set of
    // the first loading either. It is friction's work between the peaks plus the change of the energy stored
    // between them, which fades as the cycles shake down: 17.26 against 19.31 N mm from peak 1 to 2, 17.66
    // against 18.49 from peak 2 to 3.
    EXPECT_LT(loops[c].at("return_loop_area_Nmm"), 0.5 * loops[0].at("area_Nmm")) << c;
  }
  auto stored_change = [&](int c) {
    return std::abs(loops[c].at("return_loop_area_Nmm") - loops[c].at("return_loop_friction_dissipation_Nmm"));
  };
  EXPECT_LT(stored_change(2), stored_change(1));
  EXPECT_LT(stored_change(2), 0.1 * loops[2].at("return_loop_area_Nmm"));
  EXPECT_LT(loops[1].at("area_change"), -0.5);
  EXPECT_EQ(loops[1].at("steady"), 0.0);
  EXPECT_LT(std::abs(loops[2].at("area_change")), 0.1);
  EXPECT_LT(std::abs(loops[2].at("peak_deflection_change")), 0.01);
  EXPECT_EQ(loops[2].at("steady"), 1.0);
  const nlohmann::json bending = nlohmann::json::parse(std::ifstream(results / "summary.json"))["bending"];
  EXPECT_EQ(bending["steady_tolerance"], 0.1);
  EXPECT_EQ(bending["loops"][2]["steady"], true);
  EXPECT_FALSE(bending["loops"][0].contains("return_loop"));
  EXPECT_NEAR(bending["loops"][1]["return_loop"]["area_Nmm"].get<double>(), loops[1].at("return_loop_area_Nmm"),
              1e-6 * loops[1].at("return_loop_area_Nmm"));  // the CSV keeps 8 digits
}

}  // namespace
}  // namespace strandfem::verification
