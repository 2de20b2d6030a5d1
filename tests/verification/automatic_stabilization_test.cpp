// Requirement: an increment that cannot converge after its cut-backs switches the automatic stabilization on for the
// rest of its step, which carries the run to its end at a small cost in work and in the result; switched off, the
// same run stops. Reference: the same strand converged by cut-backs alone (resume_axial_cycles.yaml).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "program_runner.hpp"

namespace strandfem::verification {
namespace {

constexpr const char* kCase = "cases/verification/automatic_stabilization.yaml";

TEST(AutomaticStabilization, CarriesAStepTheCutBacksCannotAndMovesTheResultLittle) {
  const auto results = std::filesystem::path(::testing::TempDir()) / "strandfem_aided" / "results";
  const ProgramRun aided = run_program("run " + case_path(kCase) + " -o " + results.string(), "aided");
  ASSERT_EQ(aided.exit_code, 0) << aided.stderr_text;
  EXPECT_NE(aided.stderr_text.find("1/4 of the nominal increment, stabilized)"), std::string::npos) << aided.stderr_text;
  const nlohmann::json summary = nlohmann::json::parse(std::ifstream(results / "summary.json"));
  EXPECT_EQ(summary["solver_statistics"]["stabilized_steps"], 1);
  const double fraction = summary["energy"]["stabilization_fraction"].get<double>();
  EXPECT_GT(fraction, 0.0);
  EXPECT_LT(fraction, 0.01);  // Abaqus' guideline for its automatic stabilization: a small share of the work

  // The same strand converged by cut-backs alone: the stabilized steps move the force at the end by under 0.5 %.
  const ProgramRun plain = run_case("cases/verification/resume_axial_cycles.yaml", "aided_reference");
  ASSERT_EQ(plain.exit_code, 0) << plain.stderr_text;
  const auto with_aid = read_csv(results / "history.csv");
  const auto reference = read_csv(plain.output / "results" / "history.csv");
  EXPECT_NEAR(with_aid.back().at("axial_force_N"), reference.back().at("axial_force_N"), 0.005 * reference.back().at("axial_force_N"));
  EXPECT_NEAR(with_aid.back().at("axial_strain"), reference.back().at("axial_strain"), 1e-12);
}

// A run stopped inside the stabilized step and resumed goes on stabilized, as the uninterrupted one (exact solves:
// every row the same to round-off).
TEST(AutomaticStabilization, ResumedRunGoesOnStabilized) {
  const ProgramRun full = run_case(kCase, "aided_full");
  ASSERT_EQ(full.exit_code, 0) << full.stderr_text;
  const ProgramRun first = run_case(kCase, "aided_parts", "--stop-after 3");
  ASSERT_EQ(first.exit_code, 5) << first.stderr_text;
  const auto results = first.output / "results";
  const ProgramRun rest = run_program("run " + case_path(kCase) + " -o " + results.string() + " --resume", "aided_rest");
  ASSERT_EQ(rest.exit_code, 0) << rest.stderr_text;
  EXPECT_NE(rest.stderr_text.find("stabilized)"), std::string::npos) << rest.stderr_text;
  const auto a = read_csv(full.output / "results" / "history.csv"), b = read_csv(results / "history.csv");
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    EXPECT_NEAR(a[i].at("axial_force_N"), b[i].at("axial_force_N"), 1e-8 * std::abs(a[i].at("axial_force_N")) + 1e-9) << i;
}

TEST(AutomaticStabilization, SwitchedOffTheSameRunStops) {
  const auto folder = std::filesystem::path(::testing::TempDir()) / "strandfem_unaided_case";
  std::filesystem::create_directories(folder);
  std::ifstream in(case_path(kCase));
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  const std::string solver = "max_cutbacks: 0}";
  yaml.replace(yaml.find(solver), solver.size(), "max_cutbacks: 0, automatic_stabilization: false}");
  std::ofstream(folder / "case.yaml") << yaml;
  const ProgramRun r = run_program("run " + (folder / "case.yaml").string() + " -q -o " + (folder / "results").string(), "unaided");
  EXPECT_EQ(r.exit_code, 3) << r.stderr_text;
  EXPECT_EQ(r.stderr_text.find("then the automatic stabilization"), std::string::npos) << r.stderr_text;
}

}  // namespace
}  // namespace strandfem::verification
