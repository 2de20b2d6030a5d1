// Requirement (issue 7, contact stabilization): summary.json reports the work done on the strand and the energy
// the viscous stabilization dissipated; the work is that of the end reactions (∫ F dΔL), and a weak stabilization
// moves the load-strain curve by no more than its own force, factor · (elastic force change of the increment), while
// dissipating well under 1 % of the work.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <nlohmann/json.hpp>

#include "program_runner.hpp"

namespace strandfem::verification {
namespace {

constexpr const char* kCase = "cases/verification/resume_axial_cycles.yaml";  // 7-wire, plastic, μ 0.3, cycles
constexpr double kLength = 60;
constexpr double kFactor = 0.01;

nlohmann::json summary(const std::filesystem::path& results) {
  std::ifstream in(results / "summary.json");
  return nlohmann::json::parse(in);
}

TEST(Stabilization, WorkIsThatOfTheReactionsAndWeakDampingBarelyMovesTheCurve) {
  const ProgramRun plain = run_case(kCase, "stabilization_plain");
  ASSERT_EQ(plain.exit_code, 0) << plain.stderr_text;
  const auto history = read_csv(plain.output / "results" / "history.csv");
  ASSERT_GT(history.size(), 10u);
  // The work done on the strand by its end reactions, trapezoidal rule over the converged increments.
  double work = 0, force = 0, strain = 0;
  for (const auto& row : history) {
    work += 0.5 * (force + row.at("axial_force_N")) * (row.at("axial_strain") - strain) * kLength;
    force = row.at("axial_force_N"), strain = row.at("axial_strain");
  }
  const nlohmann::json energy = summary(plain.output / "results")["energy"];
  EXPECT_NEAR(energy["external_work_Nmm"].get<double>(), work, 1e-6 * work);
  EXPECT_EQ(energy["stabilization_energy_Nmm"].get<double>(), 0.0);

  // The same case with a stabilization factor of 0.01 (ramped off within each step, the default).
  const auto case_file = std::filesystem::path(::testing::TempDir()) / "stabilized_axial_cycles.yaml";
  {
    std::ifstream in(case_path(kCase));
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string solver = "solver: {";  // the case's own solver block gains the factor
    ASSERT_NE(text.find(solver), std::string::npos);
    std::string damped_text = text;
    damped_text.insert(text.find(solver) + solver.size(), "stabilization: " + std::to_string(kFactor) + ", ");
    std::ofstream(case_file) << damped_text;
  }
  const std::filesystem::path damped_results =
      std::filesystem::path(::testing::TempDir()) / "strandfem_stabilization_damped" / "results";
  const ProgramRun damped = run_program("run " + case_file.string() + " -q -o " + damped_results.string(), "stabilization_damped");
  ASSERT_EQ(damped.exit_code, 0) << damped.stderr_text;
  const nlohmann::json damped_energy = summary(damped_results)["energy"];
  const double fraction = damped_energy["stabilization_fraction"].get<double>();
  EXPECT_GT(fraction, 0.0);
  EXPECT_LT(fraction, 0.01);
  EXPECT_NEAR(damped_energy["stabilization_energy_Nmm"].get<double>() / damped_energy["external_work_Nmm"].get<double>(),
              fraction, 1e-12);

  // At each load level both runs reached, the damped force differs by at most the damping force of the last
  // increment: factor times the elastic force change over it (slope of the first increment), with a margin.
  const double elastic_slope = history.front().at("axial_force_N") / history.front().at("axial_strain");
  const auto damped_history = read_csv(damped_results / "history.csv");
  int compared = 0;
  double previous_strain = 0;
  for (const auto& d : damped_history) {
    const double increment = std::abs(d.at("axial_strain") - previous_strain);
    previous_strain = d.at("axial_strain");
    for (const auto& p : history) {
      if (p.at("step") != d.at("step") || std::abs(p.at("axial_strain") - d.at("axial_strain")) > 1e-12) continue;
      const double bound = 1.5 * kFactor * elastic_slope * increment + 1e-4 * std::abs(p.at("axial_force_N"));
      EXPECT_NEAR(d.at("axial_force_N"), p.at("axial_force_N"), bound) << "step " << d.at("step") << " strain " << d.at("axial_strain");
      ++compared;
    }
  }
  EXPECT_GE(compared, 15);
}

}  // namespace
}  // namespace strandfem::verification
