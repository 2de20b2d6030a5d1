// Requirement (issue 10, item 8): a step with nothing to do (no action, or every action held at its total)
// converges at once at the tolerances the paper cases ship with, with contact and friction, and leaves the
// state as it was; it was a step that could never converge (the residual floor lay below round-off).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>

#include "program_runner.hpp"

namespace strandfem::verification {
namespace {

TEST(IdleStep, RestAndHoldStepsConvergeAtOnceWithFrictionalContact) {
  std::ifstream in(case_path("cases/paper/seven_wire_fixed.yaml"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string step = "  - {name: axial strain, increments: 8, axial_strain: 0.008}";
  ASSERT_NE(text.find(step), std::string::npos);
  text.replace(text.find(step), step.size(),
               "  - {name: rest, increments: 2}\n"
               "  - {name: zero strain, increments: 2, axial_strain: 0}\n"
               "  - {name: pull, increments: 4, axial_strain: 0.004}\n"
               "  - {name: hold, increments: 3, axial_strain: 0.004}\n"
               "  - {name: no action, increments: 2}");
  const std::string file = ::testing::TempDir() + "/idle_steps.yaml";
  std::ofstream(file) << text;
  const ProgramRun r = run_program("run " + file + " -q -o " + ::testing::TempDir() + "/idle_out", "idle");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const auto rows = read_csv(std::filesystem::path(::testing::TempDir()) / "idle_out" / "history.csv");
  // The idle steps take their nominal increments; the pull may cut its first one (it did at an elastic slip of
  // 0.0005, with 21 Newton iterations at 1/8 of the step).
  std::map<int, int> increments;
  for (const auto& row : rows) ++increments[static_cast<int>(row.at("step"))];
  EXPECT_EQ(increments, (std::map<int, int>{{1, 2}, {2, 2}, {3, increments[3]}, {4, 3}, {5, 2}}));
  EXPECT_GE(increments[3], 4);
  // The first rest increment settles the normal onset's start (touching points press with k_n s / 4, docs/theory.md,
  // "Normal onset"); every idle increment after it converges at once and leaves the converged state untouched.
  double pulled_force = 0, rest_force = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& row = rows[i];
    const int s = static_cast<int>(row.at("step"));
    if (s == 3) {
      pulled_force = row.at("axial_force_N");
      continue;
    }
    if (i == 0) {
      rest_force = row.at("axial_force_N");
      continue;
    }
    EXPECT_EQ(row.at("newton_iterations"), 0) << "step " << s;
    EXPECT_EQ(row.at("axial_force_N"), s <= 2 ? rest_force : pulled_force) << "step " << s;
  }
  EXPECT_GT(pulled_force, 50000.0);
  EXPECT_LT(std::abs(rest_force), 1e-4 * pulled_force);
}

}  // namespace
}  // namespace strandfem::verification
