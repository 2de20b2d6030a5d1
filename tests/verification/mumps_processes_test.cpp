// A run on two MUMPS processes (the MPI build under mpiexec) gives the one-process run's results to solver
// tolerance, says so in summary.json, and keeps the program's exit codes.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "program_runner.hpp"

using namespace strandfem::verification;

namespace {

nlohmann::json solver_statistics(const ProgramRun& run) {
  return nlohmann::json::parse(std::ifstream(run.output / "results" / "summary.json")).at("solver_statistics");
}

}  // namespace

TEST(MumpsProcesses, TwoProcessBendingRunMatchesTheOneProcessRun) {
#ifndef STRANDFEM_MPIEXEC
  GTEST_SKIP() << "built on sequential MUMPS";
#else
  // 19 wires, friction, one load cycle: slip and stick change over the cycle, so the whole path is compared.
  const std::string case_file = "cases/verification/bending_friction_trends.yaml";
  const ProgramRun one = run_case(case_file, "mumps_one_process", "-t 2");
  ASSERT_EQ(one.exit_code, 0) << one.stderr_text;
  const std::string results = (one.output.parent_path() / "strandfem_mumps_two_processes" / "results").string();
  const ProgramRun two =
      run_program("run " + case_path(case_file) + " -q -t 2 -o " + results, "mumps_two_processes", kTwoProcesses);
  ASSERT_EQ(two.exit_code, 0) << two.stderr_text;
  EXPECT_EQ(solver_statistics(one).at("mumps_processes"), 1);
  EXPECT_EQ(solver_statistics(two).at("mumps_processes"), 2);
  EXPECT_EQ(solver_statistics(two).at("mumps_build").get<std::string>().rfind("MPI", 0), 0u);
  EXPECT_EQ(solver_statistics(two).at("ordering"), solver_statistics(one).at("ordering"));

  const auto history_one = read_csv(one.output / "results" / "history.csv");
  const auto history_two = read_csv(two.output / "results" / "history.csv");
  ASSERT_EQ(history_one.size(), history_two.size());
  ASSERT_GE(history_one.size(), 15u);  // tension, then V up and down
  double largest = 0;
  for (const auto& row : history_one) largest = std::max(largest, std::abs(row.at("midspan_deflection_mm")));
  // Newton stops at a residual tolerance, and the factors differ in round-off: the deflections agree to 1e-4 of
  // the largest, far inside the loop's width (the one-process loop area is 76 N mm at a 0.36 mm peak).
  for (std::size_t i = 0; i < history_one.size(); ++i)
    EXPECT_NEAR(history_two[i].at("midspan_deflection_mm"), history_one[i].at("midspan_deflection_mm"), 1e-4 * largest)
        << "increment " << history_one[i].at("increment");
  const auto loops_one = read_csv(one.output / "results" / "loops.csv");
  const auto loops_two = read_csv(two.output / "results" / "loops.csv");
  ASSERT_EQ(loops_one.size(), 1u);
  ASSERT_EQ(loops_two.size(), 1u);
  EXPECT_GT(loops_one[0].at("area_Nmm"), 10.0);
  EXPECT_NEAR(loops_two[0].at("area_Nmm"), loops_one[0].at("area_Nmm"), 1e-3 * loops_one[0].at("area_Nmm"));
#endif
}

TEST(MumpsProcesses, BadInputOnTwoProcessesExitsWithTheInputErrorCode) {
#ifndef STRANDFEM_MPIEXEC
  GTEST_SKIP() << "built on sequential MUMPS";
#else
  const ProgramRun run = run_program("run " + case_path("cases/verification/no_such_case.yaml") + " -q -o " +
                                         ::testing::TempDir() + "/strandfem_mumps_bad_input_results",
                                     "mumps_bad_input", kTwoProcesses);
  EXPECT_EQ(run.exit_code, 2) << run.stderr_text;
  EXPECT_NE(run.stderr_text.find("no_such_case.yaml"), std::string::npos) << run.stderr_text;
#endif
}
