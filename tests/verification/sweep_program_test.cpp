// Requirement (issue 9): `strandfem sweep` runs a family of cases, one key over values, each into its own results
// folder, and puts their curves on one plot; `--set` fixes other keys in every variant; a variant that is bad input
// stops the sweep before anything runs.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
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
  // sweep.csv gives each variant's results: its last cycle's peak as loops.csv has it.
  for (std::size_t i = 0; i < 2; ++i) {
    const auto loops = read_csv(folder / (i == 0 ? "contact.friction=0" : "contact.friction=5") / "loops.csv");
    ASSERT_EQ(loops.size(), 1u);
    EXPECT_NEAR(table[i].at("peak_deflection_mm"), loops[0].at("peak_deflection_mm"), 1e-6 * loops[0].at("peak_deflection_mm"));
    EXPECT_NEAR(table[i].at("loop_area_Nmm"), loops[0].at("area_Nmm"), 1e-6 * std::abs(loops[0].at("area_Nmm")) + 1e-9);
  }
  EXPECT_EQ(table[1].at("cycles"), 1.0);
  EXPECT_GT(table[1].at("axial_force_N"), 0.0);
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

TEST(Sweep, SetFixesOtherKeysInEveryVariant) {
  const auto folder = std::filesystem::path(::testing::TempDir()) / "strandfem_sweep_set" / "sweep";
  const ProgramRun run = run_program("sweep " + case_path(kCase) +
                                         " --key contact.friction --values 0.4 --set contact.orthotropy_ratio=3"
                                         " --set contact.friction_direction=slave_wire -q -o " + folder.string(),
                                     "sweep_set");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  std::ifstream variant(folder / "cases" / "contact.friction=0.4.yaml");
  std::stringstream text;
  text << variant.rdbuf();
  EXPECT_NE(text.str().find("friction: 0.4"), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("orthotropy_ratio: 3"), std::string::npos) << text.str();
  // What ran, read back from the run's own record of its configuration.
  std::ifstream summary(folder / "contact.friction=0.4" / "summary.json");
  std::stringstream record;
  record << summary.rdbuf();
  EXPECT_NE(record.str().find("\"friction_direction\": \"slave_wire\""), std::string::npos) << record.str().substr(0, 2000);
}

TEST(Sweep, BadSettingsStopItBeforeAnythingRuns) {
  const auto folder = std::filesystem::path(::testing::TempDir()) / "strandfem_sweep_bad_set" / "sweep";
  // A list of cases with a setting: the setting reaches every case, and a wrong value is refused by name.
  ProgramRun run = run_program("sweep " + case_path(kCase) + " --set contact.friction=-1 -q -o " + folder.string(),
                               "sweep_bad_set");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.stderr_text.find("contact.friction"), std::string::npos) << run.stderr_text;
  EXPECT_FALSE(std::filesystem::exists(folder / "bending_cycles_sticking" / "history.csv"));
  for (const std::string& bad : {"contact.friction", "=0.3", "contact.friction="}) {
    run = run_program("sweep " + case_path(kCase) + " --set " + bad + " -q -o " + folder.string(), "sweep_bad_set");
    EXPECT_EQ(run.exit_code, 2) << bad;
    EXPECT_NE(run.stderr_text.find("expected KEY=VALUE"), std::string::npos) << run.stderr_text;
  }
  run = run_program("sweep " + case_path(kCase) + " --key contact.friction --values 0.3 --set contact.friction=0.5 -q -o " +
                        folder.string(), "sweep_bad_set");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.stderr_text.find("already varied by --key"), std::string::npos) << run.stderr_text;
}

TEST(Sweep, TwoProcessesShareTheVariantsAndGiveTheSerialNumbers) {
#ifndef STRANDFEM_MPIEXEC
  GTEST_SKIP() << "built on sequential MUMPS";
#else
  const auto base = std::filesystem::path(::testing::TempDir()) / "strandfem_sweep_processes";
  const std::string variants = " --key contact.friction --values 0,0.3,5 -t 1 -o ";
  const ProgramRun serial = run_program("sweep " + case_path(kCase) + variants + (base / "serial").string() + " -q", "sweep_serial");
  ASSERT_EQ(serial.exit_code, 0) << serial.stderr_text;
  const ProgramRun two = run_program("sweep " + case_path(kCase) + variants + (base / "two").string(), "sweep_two", kTwoProcesses);
  ASSERT_EQ(two.exit_code, 0) << two.stderr_text;
  // Both processes took variants from the one queue, and rank 0 wrote the table and the figure.
  EXPECT_NE(two.stderr_text.find("sweep (process 0): contact.friction="), std::string::npos) << two.stderr_text;
  EXPECT_NE(two.stderr_text.find("sweep (process 1): contact.friction="), std::string::npos) << two.stderr_text;
  EXPECT_TRUE(std::filesystem::exists(base / "two" / "sweep.png")) << two.stderr_text;
  // Each variant ran alone in its process, its factorizations on one BLAS thread (read back from OpenBLAS).
  for (const char* variant : {"contact.friction=0", "contact.friction=0.3", "contact.friction=5"}) {
    const auto statistics = nlohmann::json::parse(std::ifstream(base / "two" / variant / "summary.json")).at("solver_statistics");
    EXPECT_EQ(statistics.at("mumps_processes"), 1) << variant;
    if (statistics.at("blas_kernels") != "not OpenBLAS") EXPECT_EQ(statistics.at("blas_threads"), 1) << variant;
  }
  const auto one_process = read_csv(base / "serial" / "sweep.csv");
  const auto two_processes = read_csv(base / "two" / "sweep.csv");
  ASSERT_EQ(one_process.size(), 3u);
  ASSERT_EQ(two_processes.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(two_processes[i].at("value"), one_process[i].at("value"));
    EXPECT_EQ(two_processes[i].at("exit_code"), 0.0);
    // The same model on one process each: the same path, to the solver's tolerance.
    EXPECT_NEAR(two_processes[i].at("peak_deflection_mm"), one_process[i].at("peak_deflection_mm"),
                1e-6 * one_process[i].at("peak_deflection_mm"));
    EXPECT_NEAR(two_processes[i].at("secant_ei_Nm2"), one_process[i].at("secant_ei_Nm2"), 1e-5 * one_process[i].at("secant_ei_Nm2"));
    EXPECT_NEAR(two_processes[i].at("loop_area_Nmm"), one_process[i].at("loop_area_Nmm"),
                1e-3 * std::abs(one_process[i].at("loop_area_Nmm")) + 1e-6);
  }
  // Bad input stops every process before anything runs, with the input error's code.
  const ProgramRun bad = run_program("sweep " + case_path(kCase) + " --key contact.friction --values 0.3,-1 -q -o " +
                                         (base / "bad").string(), "sweep_two_bad", kTwoProcesses);
  EXPECT_EQ(bad.exit_code, 2) << bad.stderr_text;
  EXPECT_NE(bad.stderr_text.find("contact.friction"), std::string::npos) << bad.stderr_text;
  EXPECT_FALSE(std::filesystem::exists(base / "bad" / "contact.friction=0.3" / "history.csv"));
#endif
}

}  // namespace
}  // namespace strandfem::verification
