// Requirement: bending under tension with load cycles runs through the program and writes its loops and
// deflection curves; without friction a strand bends close to EImin (eqs. 1.2, 3.1, 3.2) with no loop.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "program_runner.hpp"
#include "thick_bar.hpp"

namespace strandfem::verification {
namespace {

TEST(BendingProgram, FrictionlessStrandBendsCloseToEIminWithoutLoop) {
  const ProgramRun run = run_case("cases/verification/bending_cycles_frictionless.yaml", "bending_frictionless", "--plots");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  // --plots draws the loop and the deflection curve (scripts/plot_bending.py) into the results folder.
  EXPECT_TRUE(std::filesystem::exists(run.output / "results" / "bending_hysteresis.png")) << run.stderr_text;
  EXPECT_TRUE(std::filesystem::exists(run.output / "results" / "bending_deflection.png")) << run.stderr_text;
  const auto loops = read_csv(run.output / "results" / "loops.csv");
  ASSERT_EQ(loops.size(), 1u);
  const auto& loop = loops[0];
  const double peak = loop.at("peak_deflection_mm") - loop.at("start_deflection_mm");
  const double y_max = loop.at("eq31_ei_max_mm"), y_min = loop.at("eq31_ei_min_mm");
  // Between the closed-form bounds of eq. 3.1 and within 10 % of the full-slip (EImin) value (measured: 4.8 %
  // stiffer, the rigid end planes hold the wires together near the clamps).
  EXPECT_GT(peak, y_max);
  EXPECT_LT(peak, y_min);
  EXPECT_NEAR(peak, y_min, 0.10 * y_min);
  // No hysteresis: the loop's area is next to nothing against V y_peak (frictionless, elastic).
  EXPECT_LT(loop.at("area_Nmm"), 1e-3 * loop.at("peak_load_N") * peak);
  EXPECT_NEAR(loop.at("end_deflection_mm"), loop.at("start_deflection_mm"), 1e-3 * peak);
  // The core's deflection curve at V max follows eq. 3.2 for EImin within 10 % of its peak.
  const auto curve = read_csv(run.output / "results" / "deflection_curves.csv");
  ASSERT_GT(curve.size(), 10u);
  for (const auto& row : curve)
    EXPECT_NEAR(row.at("deflection_mm"), row.at("eq32_ei_min_mm"), 0.10 * y_min) << "z = " << row.at("z_mm");
  // summary.json checks that curve against eq. 3.2's bounds (EImax below, the larger EImin form above), at every
  // interior node and beyond the case's 20 mm clamp-edge offset: recounted here from the file. Measured: near the
  // clamps this short frictionless strand lies above both EImin forms (12.5 % at 5 mm), so not every node is within.
  nlohmann::json summary;
  std::ifstream(run.output / "results" / "summary.json") >> summary;
  const nlohmann::json& checks = summary["bending"]["deflection_curves"];
  ASSERT_EQ(checks.size(), 1u);
  EXPECT_EQ(checks[0]["cycle"], 1);
  EXPECT_TRUE(summary["bending"]["loops"][0]["peak_within_eq31"].get<bool>());
  for (const auto& [key, from_clamp] : {std::pair<std::string, double>{"all_nodes", 0.0}, {"beyond_clamp_edge", 20.0}}) {
    int nodes = 0, within = 0;
    double largest_excess = 0, largest_excess_x = 0;
    for (const auto& row : curve) {
      const double x = std::min(row.at("z_mm"), 200.0 - row.at("z_mm"));
      if (!(x > 0) || x < from_clamp) continue;
      ++nodes;
      const double upper = std::max(row.at("eq32_ei_min_mm"), row.at("eq32_ei_min_shear_mm"));
      const double y = row.at("deflection_mm");
      if (y >= row.at("eq32_ei_max_mm") && y <= upper) ++within;
      if (y - upper > largest_excess) largest_excess = y - upper, largest_excess_x = x;
    }
    const nlohmann::json& check = checks[0][key];
    EXPECT_EQ(check["nodes"].get<int>(), nodes) << key;
    EXPECT_EQ(check["within"].get<int>(), within) << key;
    EXPECT_LT(within, nodes) << key;
    EXPECT_NEAR(check["largest_excess_mm"].get<double>(), largest_excess, 1e-6 * y_min) << key;
    EXPECT_NEAR(check["largest_excess_x_mm"].get<double>(), largest_excess_x, 1e-3) << key;
  }
  EXPECT_LT(checks[0]["beyond_clamp_edge"]["nodes"].get<int>(), checks[0]["all_nodes"]["nodes"].get<int>());
  // From the load point (midspan, z = 100 mm): each node's rise below it, beside eq. 3.2's; summary.json gives the
  // rise 45 and 90 mm either side, the mean of both sides, which the file's columns give again here.
  double load_deflection = 0;
  for (const auto& row : curve)
    if (row.at("z_from_load_mm") == 0) load_deflection = row.at("deflection_mm");
  ASSERT_GT(load_deflection, y_max);
  for (const auto& row : curve) {
    EXPECT_NEAR(row.at("z_from_load_mm"), row.at("z_mm") - 100.0, 1e-9);
    EXPECT_NEAR(row.at("rise_from_load_mm"), load_deflection - row.at("deflection_mm"), 1e-6 * y_min);
    EXPECT_NEAR(row.at("rise_from_load_mm"), row.at("eq32_ei_min_rise_mm"), 0.10 * y_min) << "z = " << row.at("z_mm");
  }
  const nlohmann::json& rises = checks[0]["from_load_point"];
  ASSERT_EQ(rises.size(), 3u);
  for (const nlohmann::json& r : rises) {
    const double d = r["distance_mm"].get<double>();
    if (d > 100) continue;  // beyond this 200 mm strand's clamps
    double sides = 0;
    for (const auto& row : curve)
      if (std::abs(std::abs(row.at("z_from_load_mm")) - d) < 1e-6) sides += 0.5 * row.at("rise_from_load_mm");
    if (std::fmod(d, 5.0) == 0) EXPECT_NEAR(r["rise_mm"].get<double>(), sides, 1e-6 * y_min) << d;
    EXPECT_GT(r["rise_mm"].get<double>(), r["eq32_ei_max_mm"].get<double>()) << d;
    EXPECT_NEAR(r["rise_mm"].get<double>(), r["eq32_ei_min_mm"].get<double>(), 0.10 * y_min) << d;
  }
  // history.csv: the cyclic step's two halves are cycle 1, out then back.
  const auto history = read_csv(run.output / "results" / "history.csv");
  int out = 0, back = 0;
  for (const auto& row : history)
    if (row.at("cycle") == 1) (row.at("returning") == 1 ? back : out)++;
  EXPECT_EQ(out, 4);
  EXPECT_EQ(back, 4);
}

// With friction too high for any contact point to slide the wires stick: no loop, and a strand far stiffer than
// EImin that approaches EImax as the stick stiffness grows (default elastic slip 0.5 % of the element length, then
// ten times stiffer). Measured: secant EI 29.7 and 56.8 N m² against EImax 97.7 and EImin 12.7 N m².
TEST(BendingProgram, StickingStrandHasNoLoopAndApproachesEImax) {
  double previous_peak = 0;
  for (const std::string slip : {"0.005", "0.0005"}) {
    const auto case_file = std::filesystem::path(::testing::TempDir()) / ("bending_sticking_" + slip + ".yaml");
    {
      std::ifstream in(case_path("cases/verification/bending_cycles_sticking.yaml"));
      std::stringstream text;
      text << in.rdbuf();
      std::string yaml = text.str();
      const std::string key = "friction: 5";
      yaml.replace(yaml.find(key), key.size(), key + ", elastic_slip: " + slip);
      std::ofstream(case_file) << yaml;
    }
    const auto results = std::filesystem::path(::testing::TempDir()) / ("strandfem_sticking_" + slip) / "results";
    const ProgramRun run = run_program("run " + case_file.string() + " -q -o " + results.string(), "sticking_" + slip);
    ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
    const auto loops = read_csv(results / "loops.csv");
    ASSERT_EQ(loops.size(), 1u);
    const auto& loop = loops[0];
    const double peak = loop.at("peak_deflection_mm") - loop.at("start_deflection_mm");
    const double y_max = loop.at("eq31_ei_max_mm"), y_min = loop.at("eq31_ei_min_mm");
    EXPECT_GT(peak, y_max) << "elastic slip " << slip;
    EXPECT_LT(peak, 0.6 * y_min) << "elastic slip " << slip;  // far from the full-slip value
    // Sticking, elastic: no dissipation and no ratchet.
    EXPECT_LT(loop.at("area_Nmm"), 1e-3 * loop.at("peak_load_N") * peak) << "elastic slip " << slip;
    EXPECT_NEAR(loop.at("end_deflection_mm"), loop.at("start_deflection_mm"), 1e-3 * peak) << "elastic slip " << slip;
    // The core's whole curve lies between eq. 3.2's bounds (summary.json's check; measured: all 39 nodes).
    nlohmann::json summary;
    std::ifstream(results / "summary.json") >> summary;
    const nlohmann::json& check = summary["bending"]["deflection_curves"][0]["all_nodes"];
    EXPECT_EQ(check["nodes"].get<int>(), 39) << "elastic slip " << slip;
    EXPECT_EQ(check["within"].get<int>(), 39) << "elastic slip " << slip;
    // Stiffer stick, stiffer strand: the deflection moves toward the EImax bound.
    if (previous_peak > 0) EXPECT_LT(peak, 0.7 * previous_peak);
    previous_peak = peak;
  }
}

// A strand of its core alone is the tensioned thick bar of BeamBenchmarks: the core's deflection curve in
// deflection_curves.csv and the shear form written beside it both follow the tensioned Timoshenko beam on the
// span stretched by eps = T/(EA), EI and S times 1 + eps (the sections' laws are per reference length). Measured:
// both within 3e-7 of the midspan deflection; the shear form on the unstretched span is off by 0.44 % of it.
TEST(BendingProgram, CoreAloneFollowsTheShearFormOnTheStretchedSpan) {
  const ProgramRun run = run_case("cases/verification/tensioned_core_bending.yaml", "tensioned_core");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  const ThickBar bar;
  const double midspan = bar.deflection(0.5 * bar.L);
  const auto curve = read_csv(run.output / "results" / "deflection_curves.csv");
  ASSERT_EQ(curve.size(), 81u);
  for (const auto& row : curve) {
    const double expected = bar.deflection(row.at("z_mm"));
    EXPECT_NEAR(row.at("deflection_mm"), expected, 1e-5 * midspan) << "z = " << row.at("z_mm");
    EXPECT_NEAR(row.at("eq32_ei_min_shear_mm"), expected, 1e-5 * midspan) << "z = " << row.at("z_mm");
  }
}

// Clamps and a saddle are rigid over their lengths: the bar bends only between their edges, as the same tensioned
// Timoshenko beam on the 120 mm (stretched) between them, and the saddle's nodes all move with the load point;
// deflection_curves.csv's references are eq. 3.2 on that span.
TEST(BendingProgram, ClampsAndSaddleHoldTheirLengthsRigid) {
  const ProgramRun run = run_case("cases/verification/tensioned_core_saddle.yaml", "tensioned_core_saddle");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  const ThickBar bar;
  const double clamp = 20, saddle = 40, span = bar.L - 2 * clamp - saddle, s = bar.stretch();
  auto expected = [&](double z) {
    const double x = std::clamp(std::min(z, bar.L - z) - clamp, 0.0, 0.5 * span);
    return tensioned_timoshenko_deflection(bar.V, bar.T, bar.E * bar.inertia() * s, bar.shear_stiffness() * s, span * s, x * s);
  };
  const double midspan = expected(0.5 * bar.L);
  EXPECT_LT(midspan, 0.5 * bar.deflection(0.5 * bar.L));  // far stiffer than the bar loaded at its core node
  const auto curve = read_csv(run.output / "results" / "deflection_curves.csv");
  ASSERT_EQ(curve.size(), 81u);
  for (const auto& row : curve) {
    EXPECT_NEAR(row.at("deflection_mm"), expected(row.at("z_mm")), 1e-5 * midspan) << "z = " << row.at("z_mm");
    // eq. 3.2's references take the same span: the bent one, between the clamps' and the saddle's edges.
    EXPECT_NEAR(row.at("eq32_ei_min_shear_mm"), expected(row.at("z_mm")), 1e-5 * midspan) << "z = " << row.at("z_mm");
    if (std::abs(row.at("z_from_load_mm")) <= 0.5 * saddle) EXPECT_NEAR(row.at("rise_from_load_mm"), 0.0, 1e-9 * midspan);
  }
}

}  // namespace
}  // namespace strandfem::verification
