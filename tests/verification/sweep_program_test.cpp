// Requirement (issue 9): `strandfem sweep` runs a family of cases, one key over values, each into its own results
// folder, and puts their curves on one plot; a variant that is bad input stops the sweep before anything runs.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "program_runner.hpp"

namespace strandfem::verification {
namespace {

constexpr const char* kCase = "cases/verification/bending_cycles_sticking.yaml";

double peak_deflection(const std::filesystem::path& results) {
  const auto loops = read_csv(results / "loops.csv");
  return loops.empty() ? std::nan("") : loops[0].at("peak_deflection_mm") - loops[0].at("start_deflection_mm");
}

TEST(Sweep, OneKeyOverValuesRunsEachVariantAndPlotsThemTogether) {
  const auto folder = std::filesystem::path(::testing::TempDir()) / "strandfem_sweep_friction" / "sweep";
  const ProgramRun run = run_program("sweep " + case_path(kCase) + " --key contact.friction --values 0,5 -q -o " +
                                         folder.string(), "sweep_friction");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  const auto table = read_csv(folder / "sweep.csv");
  ASSERT_EQ(table.size(), 2u);
  EXPECT_EQ(table[0].at("value"), 0.0);
  EXPECT_EQ(table[1].at("value"), 5.0);
  EXPECT_EQ(table[1].at("exit_code"), 0.0);
  EXPECT_TRUE(std::filesystem::exists(folder / "sweep.png")) << run.stderr_text;
  // Each variant ran with its own friction: the sticking strand bends far less than the frictionless one.
  const double frictionless = peak_deflection(folder / "contact.friction=0");
  const double sticking = peak_deflection(folder / "contact.friction=5");
  EXPECT_LT(sticking, 0.6 * frictionless);
  std::ifstream variant(folder / "cases" / "contact.friction=5.yaml");
  std::stringstream text;
  text << variant.rdbuf();
  EXPECT_NE(text.str().find("friction: 5"), std::string::npos);
}

TEST(Sweep, BadKeysAndBadValuesStopItBeforeAnythingRuns) {
  const auto folder = std::filesystem::path(::testing::TempDir()) / "strandfem_sweep_bad" / "sweep";
  ProgramRun run = run_program("sweep " + case_path(kCase) + " --key contact.friction --values 0.3,-1 -q -o " +
                                   folder.string(), "sweep_bad");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.stderr_text.find("contact.friction"), std::string::npos) << run.stderr_text;
  EXPECT_FALSE(std::filesystem::exists(folder / "contact.friction=0.3" / "history.csv"));
  run = run_program("sweep " + case_path(kCase) + " --key strand.layers.5.lay_angle --values 12 -q -o " + folder.string(),
                    "sweep_bad");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.stderr_text.find("strand.layers.5.lay_angle"), std::string::npos) << run.stderr_text;
  run = run_program("sweep " + case_path(kCase) + " --values 1,2 -q -o " + folder.string(), "sweep_bad");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.stderr_text.find("--values needs --key"), std::string::npos) << run.stderr_text;
}

}  // namespace
}  // namespace strandfem::verification
