// Requirement (issue 9): a run stopped part-way continues from its last converged increment with --resume and
// gives the uninterrupted run's numbers; a checkpoint that is missing or belongs to another case is refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "program_runner.hpp"

namespace strandfem::verification {
namespace {

constexpr const char* kCase = "cases/verification/resume_axial_cycles.yaml";

void expect_same_rows(const std::filesystem::path& a, const std::filesystem::path& b) {
  const auto rows_a = read_csv(a), rows_b = read_csv(b);
  ASSERT_EQ(rows_a.size(), rows_b.size()) << a << " against " << b;
  ASSERT_FALSE(rows_a.empty()) << a;
  for (std::size_t i = 0; i < rows_a.size(); ++i)
    for (const auto& [column, value] : rows_a[i]) {
      if (std::isnan(value)) continue;  // text fields
      if (std::isinf(value)) {  // an axial cycle's bending stiffness (no transverse load)
        EXPECT_EQ(rows_b[i].at(column), value) << a.filename() << " row " << i + 1 << " " << column;
        continue;
      }
      // The case factors every tangent afresh (krylov_iterations: 0), so a resumed run repeats the uninterrupted
      // one's arithmetic; measured identical to the last digit written.
      EXPECT_NEAR(rows_b[i].at(column), value, 1e-7 * std::abs(value) + 1e-9) << a.filename() << " row " << i + 1 << " " << column;
    }
}

TEST(Resume, StoppedAndResumedRunMatchesUninterruptedOne) {
  const ProgramRun full = run_case(kCase, "resume_full");
  ASSERT_EQ(full.exit_code, 0) << full.stderr_text;
  // Stopped inside the first cycle after a pull whose increments were cut back, resumed and stopped again inside
  // its return half, resumed to the end.
  const ProgramRun first = run_case(kCase, "resume_parts", "--stop-after 12");
  ASSERT_EQ(first.exit_code, 5) << first.stderr_text;
  const std::filesystem::path results = first.output / "results";
  EXPECT_EQ(read_csv(results / "history.csv").size(), 12u);
  ASSERT_TRUE(std::filesystem::exists(results / "checkpoint.bin"));
  const std::string resume = "run " + case_path(kCase) + " -q -o " + results.string() + " --resume";
  const ProgramRun second = run_program(resume + " --stop-after 3", "resume_second");
  ASSERT_EQ(second.exit_code, 5) << second.stderr_text;
  const ProgramRun third = run_program(resume, "resume_third");
  ASSERT_EQ(third.exit_code, 0) << third.stderr_text;
  for (const char* file : {"history.csv", "contacts.csv", "wires.csv", "deflection_curves.csv", "loops.csv", "wire_profiles.csv",
                           "contact_profiles.csv"})
    expect_same_rows(full.output / "results" / file, results / file);
  // The status maps need what each loading half saw before the stop (kept in the checkpoint).
  EXPECT_EQ(read_csv_text(full.output / "results" / "contact_profiles.csv", "map_status"),
            read_csv_text(results / "contact_profiles.csv", "map_status"));
  auto profiles = [](const std::filesystem::path& dir) {
    return nlohmann::json::parse(std::ifstream(dir / "summary.json"))["bending"]["profiles"].dump();
  };
  EXPECT_EQ(profiles(full.output / "results"), profiles(results));
}

// With the default inexact Newton (newton_forcing 0.2) a resumed run refactors where the uninterrupted one
// reused older factors for loose solves near convergence, so the two agree to the Newton tolerance, not to the
// last digit: the axial force and torque at every increment within 1e-4 of their largest values (the force
// tolerance is 5e-3; measured 3e-6).
TEST(Resume, ResumedRunWithInexactNewtonMatchesWithinTheNewtonTolerance) {
  std::ifstream in(case_path(kCase));
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string exact = "solver: {newton_forcing: 0, krylov_iterations: 0}\n";
  ASSERT_NE(text.find(exact), std::string::npos);
  std::string inexact = text;
  inexact.erase(inexact.find(exact), exact.size());
  const std::string file = ::testing::TempDir() + "/resume_inexact.yaml";
  std::ofstream(file) << inexact;
  const auto folder = [](const char* tag) { return (std::filesystem::path(::testing::TempDir()) / tag / "results").string(); };
  const ProgramRun full = run_program("run " + file + " -q -o " + folder("strandfem_resume_inexact_full"), "resume_inexact_full");
  ASSERT_EQ(full.exit_code, 0) << full.stderr_text;
  const std::string parts = folder("strandfem_resume_inexact_first");  // emptied by run_program below
  const ProgramRun first = run_program("run " + file + " -q -o " + parts + " --stop-after 12", "resume_inexact_first");
  ASSERT_EQ(first.exit_code, 5) << first.stderr_text;
  const ProgramRun second = run_program("run " + file + " -q -o " + parts + " --resume", "resume_inexact_second");
  ASSERT_EQ(second.exit_code, 0) << second.stderr_text;
  const auto a = read_csv(full.output / "results" / "history.csv"), b = read_csv(std::filesystem::path(parts) / "history.csv");
  ASSERT_EQ(a.size(), b.size());
  for (const char* column : {"axial_force_N", "torque_Nmm"}) {
    double largest = 0;
    for (const auto& row : a) largest = std::max(largest, std::abs(row.at(column)));
    ASSERT_GT(largest, 0.0) << column;
    for (std::size_t i = 0; i < a.size(); ++i)
      EXPECT_NEAR(b[i].at(column), a[i].at(column), 1e-4 * largest) << "row " << i + 1 << " " << column;
  }
}

// With the contact stabilization the springs' start points are not in the checkpoint: a restored run sets them
// from its converged state, as the commit did, so it matches the uninterrupted run as without stabilization, and
// the stabilization energy (which the checkpoint carries) too.
TEST(Resume, ResumedRunWithContactStabilizationMatches) {
  std::ifstream in(case_path(kCase));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string contact = "contact: {friction: 0.3}";
  ASSERT_NE(text.find(contact), std::string::npos);
  text.replace(text.find(contact), contact.size(), "contact: {friction: 0.3, stabilization: 1.0e-4}");
  const std::string file = ::testing::TempDir() + "/resume_stabilized.yaml";
  std::ofstream(file) << text;
  const auto folder = [](const char* tag) { return (std::filesystem::path(::testing::TempDir()) / tag / "results").string(); };
  const ProgramRun full = run_program("run " + file + " -q -o " + folder("strandfem_resume_stabilized_full"), "resume_stabilized_full");
  ASSERT_EQ(full.exit_code, 0) << full.stderr_text;
  const std::string parts = folder("strandfem_resume_stabilized_first");
  const ProgramRun first = run_program("run " + file + " -q -o " + parts + " --stop-after 12", "resume_stabilized_first");
  ASSERT_EQ(first.exit_code, 5) << first.stderr_text;
  const ProgramRun second = run_program("run " + file + " -q -o " + parts + " --resume", "resume_stabilized_second");
  ASSERT_EQ(second.exit_code, 0) << second.stderr_text;
  for (const char* name : {"history.csv", "contacts.csv"}) expect_same_rows(full.output / "results" / name, std::filesystem::path(parts) / name);
  const auto energy = [](const std::filesystem::path& dir) {
    return nlohmann::json::parse(std::ifstream(dir / "summary.json"))["energy"]["stabilization_energy_Nmm"].get<double>();
  };
  const double uninterrupted = energy(full.output / "results");
  EXPECT_GT(uninterrupted, 0.0);
  EXPECT_NEAR(energy(parts), uninterrupted, 1e-7 * uninterrupted);
}

// A finished run can be given more cycles: resumed with the last step's cycle count raised, it continues into
// the new cycles and matches a run made with that count from the start. Fewer cycles, or a change to an
// earlier step, is refused.
TEST(Resume, AddsCyclesToTheLastStepOnly) {
  const ProgramRun full = run_case(kCase, "resume_more_full");
  ASSERT_EQ(full.exit_code, 0) << full.stderr_text;
  {
    // Each cycle after the first says how it differs from the one before, and whether it is steady by the default
    // tolerance (FrictionTrends.RepeatedCyclesAreFrictionsWorkAndSteady sets another).
    const auto loops = read_csv(full.output / "results" / "loops.csv");
    ASSERT_EQ(loops.size(), 2u);
    EXPECT_TRUE(std::isnan(loops[0].at("area_change")));
    // This axial case has no transverse load: its areas are 0 (change 0), its peaks the deflection's round-off.
    auto change = [&](const char* column) {
      const double before = loops[0].at(column), now = loops[1].at(column);
      const double scale = std::max(std::abs(before), std::abs(now));
      return scale > 0 ? (now - before) / scale : 0.0;
    };
    EXPECT_NEAR(loops[1].at("area_change"), change("area_Nmm"), 1e-6);
    EXPECT_NEAR(loops[1].at("friction_dissipation_change"), change("friction_dissipation_Nmm"), 1e-6);
    const nlohmann::json bending = nlohmann::json::parse(std::ifstream(full.output / "results" / "summary.json"))["bending"];
    EXPECT_EQ(bending["steady_tolerance"], 0.02);
    const bool steady = std::abs(loops[1].at("area_change")) <= 0.02 && std::abs(loops[1].at("peak_deflection_change")) <= 0.02;
    EXPECT_EQ(loops[1].at("steady"), steady ? 1.0 : 0.0);
    EXPECT_EQ(bending["loops"][1]["steady"], steady);
    EXPECT_NEAR(bending["loops"][1]["change"]["area"].get<double>(), loops[1].at("area_change"), 1e-6);
  }
  std::ifstream in(case_path(kCase));
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string two = "cycles: 2,";
  ASSERT_NE(text.find(two), std::string::npos);
  std::string one_cycle = text;
  one_cycle.replace(one_cycle.find(two), two.size(), "cycles: 1,");
  const std::string short_case = ::testing::TempDir() + "/resume_one_cycle.yaml";
  std::ofstream(short_case) << one_cycle;
  const auto results = std::filesystem::path(::testing::TempDir()) / "strandfem_resume_more" / "results";
  const ProgramRun first = run_program("run " + short_case + " -q -o " + results.string(), "resume_more");
  ASSERT_EQ(first.exit_code, 0) << first.stderr_text;
  EXPECT_LT(read_csv(results / "history.csv").size(), read_csv(full.output / "results" / "history.csv").size());
  const ProgramRun more = run_program("run " + case_path(kCase) + " -q -o " + results.string() + " --resume", "resume_more_cycles");
  ASSERT_EQ(more.exit_code, 0) << more.stderr_text;
  for (const char* file : {"history.csv", "loops.csv", "wires.csv"}) expect_same_rows(full.output / "results" / file, results / file);
  // The first cycle's check of its peak curve came through the checkpoint, the second's was made after it.
  auto curve_checks = [](const std::filesystem::path& dir) {
    return nlohmann::json::parse(std::ifstream(dir / "summary.json"))["bending"]["deflection_curves"];
  };
  const nlohmann::json checks = curve_checks(results);
  ASSERT_EQ(checks.size(), 2u);
  EXPECT_EQ(checks[0]["cycle"], 1);
  EXPECT_EQ(checks[1]["cycle"], 2);
  EXPECT_EQ(checks.dump(), curve_checks(full.output / "results").dump());
  const ProgramRun fewer = run_program("run " + short_case + " -q -o " + results.string() + " --resume", "resume_fewer_cycles");
  EXPECT_EQ(fewer.exit_code, 2);
  EXPECT_NE(fewer.stderr_text.find("steps[1].cycles is 1"), std::string::npos) << fewer.stderr_text;
  EXPECT_NE(fewer.stderr_text.find("only add cycles to the last step"), std::string::npos) << fewer.stderr_text;
}

// A run stopped after a cycle closed already has that cycle's loop in loops.csv (rewritten as each cycle
// closes, not only when the run ends).
TEST(Resume, LoopsOfClosedCyclesAreWrittenBeforeTheRunEnds) {
  const ProgramRun stopped = run_case(kCase, "resume_loops", "--stop-after 14");
  ASSERT_EQ(stopped.exit_code, 5) << stopped.stderr_text;
  int closed = 0;  // rows that end a returning half: a whole load fraction
  for (const auto& r : read_csv(stopped.output / "results" / "history.csv"))
    closed += r.at("returning") == 1 && std::abs(r.at("load_factor") - std::round(r.at("load_factor"))) < 1e-9;
  ASSERT_EQ(closed, 1) << "the stop must fall after the first cycle and before the second closes";
  EXPECT_EQ(read_csv(stopped.output / "results" / "loops.csv").size(), 1u);
  // summary.json says it stopped, with its 14 increments and the solver's counts so far (for partial benchmarks).
  const nlohmann::json summary = nlohmann::json::parse(std::ifstream(stopped.output / "results" / "summary.json"));
  EXPECT_EQ(summary["status"], "stopped");
  EXPECT_EQ(summary["converged_increments"], 14);
  EXPECT_GE(summary["solver_statistics"]["newton_iterations"].get<int>(), 14);
  EXPECT_GT(summary["solver_statistics"]["factorizations"].get<int>(), 0);
  EXPECT_GT(summary["wall_time_s"].get<double>(), 0.0);
  // ... and the results so far: the closed loop, the check of each peak's curve reached, the energies.
  EXPECT_EQ(summary["bending"]["loops"].size(), 1u);
  EXPECT_GE(summary["bending"]["deflection_curves"].size(), 1u);
  EXPECT_EQ(summary["bending"]["deflection_curves"][0]["cycle"], 1);
  EXPECT_GT(summary["energy"]["external_work_Nmm"].get<double>(), 0.0);
}

TEST(Resume, RefusesAFolderWithoutCheckpoint) {
  const ProgramRun run = run_case(kCase, "resume_nothing", "--resume");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.stderr_text.find("nothing to resume"), std::string::npos) << run.stderr_text;
}

TEST(Resume, RefusesTheCheckpointOfAnotherCase) {
  const ProgramRun first = run_case(kCase, "resume_other", "--stop-after 2");
  ASSERT_EQ(first.exit_code, 5) << first.stderr_text;
  const std::filesystem::path results = first.output / "results";
  const ProgramRun other = run_program("run " + case_path("cases/verification/bending_cycles_frictionless.yaml") + " -q -o " +
                                           results.string() + " --resume",
                                       "resume_other_case");
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.stderr_text.find("another case"), std::string::npos) << other.stderr_text;
  // The refused resume left the stopped run's results as they were.
  EXPECT_EQ(read_csv(results / "history.csv").size(), 2u);
}

// A checkpoint of an earlier format (format 5's deflection curves lack a column, format 4's statistics the residual
// and commit times) is refused before anything is read, and the stopped run's results stay as they were.
TEST(Resume, RefusesACheckpointOfAnEarlierFormat) {
  const ProgramRun first = run_case(kCase, "resume_format", "--stop-after 2");
  ASSERT_EQ(first.exit_code, 5) << first.stderr_text;
  const std::filesystem::path results = first.output / "results";
  {
    // The format version follows the magic string (its 8-byte length and 20 characters).
    std::fstream checkpoint(results / "checkpoint.bin", std::ios::in | std::ios::out | std::ios::binary);
    checkpoint.seekg(28);
    int version = 0;
    checkpoint.read(reinterpret_cast<char*>(&version), sizeof version);
    ASSERT_EQ(version, 9);
    version = 8;
    checkpoint.seekp(28);
    checkpoint.write(reinterpret_cast<const char*>(&version), sizeof version);
  }
  const ProgramRun resumed = run_program("run " + case_path(kCase) + " -q -o " + results.string() + " --resume",
                                         "resume_format_again");
  EXPECT_EQ(resumed.exit_code, 2);
  EXPECT_NE(resumed.stderr_text.find("another version"), std::string::npos) << resumed.stderr_text;
  EXPECT_EQ(read_csv(results / "history.csv").size(), 2u);
}

}  // namespace
}  // namespace strandfem::verification
