// Requirement: the program runs a strand with no contact through 1 % axial strain, writes every output,
// gives the same numbers for any thread count, reports model sizes, rejects bad input with exit code 2
// and a message naming the key, and stops with exit code 3 keeping converged results.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "program_runner.hpp"
#include "strandfem/io/case_file.hpp"
#include "strandfem/solver/static_analysis.hpp"

namespace strandfem::verification {
namespace {

TEST(StrandProgram, SevenWireWithoutContactWritesAllOutputsAndIsThreadIndependent) {
  const ProgramRun one = run_case("cases/examples/seven_wire_axial.yaml", "seven_t1", "-t 1");
  const ProgramRun two = run_case("cases/examples/seven_wire_axial.yaml", "seven_t2", "-t 2");
  ASSERT_EQ(one.exit_code, 0) << one.stderr_text;
  ASSERT_EQ(two.exit_code, 0) << two.stderr_text;
  for (const char* f : {"history.csv", "displacements.csv", "summary.json", "result.pvd", "result_00000.vtu"})
    EXPECT_TRUE(std::filesystem::exists(one.output / "results" / f)) << f;
  const auto h1 = read_csv(one.output / "results" / "history.csv"), h2 = read_csv(two.output / "results" / "history.csv");
  ASSERT_EQ(h1.size(), 10u);
  ASSERT_EQ(h1.size(), h2.size());
  EXPECT_NEAR(h1.back().at("axial_strain"), 0.01, 1e-12);
  EXPECT_GT(h1.back().at("axial_force_N"), 0.0);
  for (std::size_t i = 0; i < h1.size(); ++i)
    for (const auto& [key, value] : h1[i]) EXPECT_NEAR(value, h2[i].at(key), 1e-9 * (1 + std::abs(value))) << key;
  const auto d = read_csv(one.output / "results" / "displacements.csv");
  EXPECT_EQ(d.size(), 343u);
  const nlohmann::json summary = nlohmann::json::parse(std::ifstream(one.output / "results" / "summary.json"));
  EXPECT_EQ(summary["status"], "converged");
  EXPECT_EQ(summary["nodes"], 343);
  EXPECT_EQ(summary["elements"], 168);
  EXPECT_GT(summary["dofs"].get<int>(), 0);
  EXPECT_TRUE(summary.contains("EI_max_Nm2") && summary.contains("axial_stiffness_N") && summary.contains("wall_time_s"));
  // Without contact the core carries the load and the helical wires act as springs: the force lies
  // between the core alone (E A_core eps) and the linear strand theory (C11 eps).
  const double core = 188000 * M_PI * 3.94 * 3.94 / 4 * 0.01;
  EXPECT_GT(h1.back().at("axial_force_N"), core);
  EXPECT_LT(h1.back().at("axial_force_N"), summary["axial_stiffness_N"]["fixed_ends"].get<double>() * 0.01);
}

TEST(StrandProgram, InfoReportsPaperMeshSizesAndReferences) {
  const ProgramRun r = run_program("info " + case_path("cases/paper/wire_120.yaml"), "info120");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(r.output / "stdout.txt"));
  EXPECT_EQ(j["elements"], 2640);
  EXPECT_EQ(j["nodes"], 5400);
  EXPECT_NEAR(j["layers"][2]["radial_overlap_mm"].get<double>(), 0.19, 0.01);
  EXPECT_NE(r.stderr_text.find("warning: layer 2"), std::string::npos);
  const ProgramRun c = run_program("info " + case_path("cases/paper/cardinal.yaml"), "infocardinal");
  const nlohmann::json k = nlohmann::json::parse(std::ifstream(c.output / "stdout.txt"));
  EXPECT_NEAR(k["EI_max_Nm2"].get<double>(), 1800.4, 1.8);
  EXPECT_NEAR(k["EI_min_Nm2"].get<double>(), 28.3, 0.03);
}

struct BadInput {
  const char* name;
  const char* replace;  // text of the 7-wire case to replace...
  const char* with;     // ...by this
  const char* key;      // the message must name this key
};

TEST(StrandProgram, BadInputGivesExitCode2NamingTheKey) {
  const BadInput cases[] = {
      {"negative_diameter", "diameter: 3.73", "diameter: -3.73", "strand.layers[1].diameter"},
      {"lay_angle_90", "lay_angle: 11.8", "lay_angle: 90", "strand.layers[1].lay_angle"},
      {"zero_wires", "wires: 6", "wires: 0", "strand.layers[1].wires"},
      {"unknown_key", "ends: fixed", "ends: fixed\n  colour: red", "strand.colour"},
      {"big_overlap", "wires: 6", "wires: 9", "strand.layers[1]"},
      {"bad_end", "ends: fixed", "ends: glued", "strand.ends"},
      {"bad_solver", "steps:", "solver: {linear_solver: magic}\nsteps:", "solver.linear_solver"},
      {"missing_length", "length: 200", "", "strand.length"},
      {"negative_friction", "steps:", "contact: {friction: -0.1}\nsteps:", "contact.friction"},
      {"unknown_contact_key", "steps:", "contact: {friction: 0.1, stiffness: 3}\nsteps:", "contact.stiffness"},
      {"bad_overlap_mode", "steps:", "contact: {initial_overlap: squash}\nsteps:", "contact.initial_overlap"},
      {"friction_pair_material", "steps:", "contact: {friction_pairs: [{materials: [steel, copper], mu: 0.2}]}\nsteps:",
       "contact.friction_pairs[0].materials[1]"},
      {"friction_pair_orthotropy", "steps:", "contact: {friction_pairs: [{materials: [steel, steel], mu: 0.2, orthotropy_ratio: 0}]}\nsteps:",
       "contact.friction_pairs[0].orthotropy_ratio"},
      {"friction_zone_order", "steps:", "contact: {friction_zones: [{z: [50, 10], mu: 0.2}]}\nsteps:", "contact.friction_zones[0].z"},
      {"friction_zone_material", "steps:", "contact: {friction_zones: [{z: [10, 50], mu: 0.2, materials: [[steel, tin]]}]}\nsteps:",
       "contact.friction_zones[0].materials[0][1]"},
      {"friction_zone_pairs", "steps:", "contact: {friction_zones: [{z: [10, 50], mu: 0.2, materials: [steel, steel]}]}\nsteps:",
       "contact.friction_zones[0].materials[0]"},
      {"axis_on_strand", "steps:", "contact: {axis: [1, 0, 0]}\nsteps:", "contact.axis"},
      {"line_points", "steps:", "contact: {line_points: 0}\nsteps:", "contact.line_points"},
  };
  std::ifstream in(case_path("cases/examples/seven_wire_axial.yaml"));
  const std::string base((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const BadInput& c : cases) {
    std::string text = base;
    const auto pos = text.find(c.replace);
    ASSERT_NE(pos, std::string::npos) << c.name;
    text.replace(pos, std::string(c.replace).size(), c.with);
    const std::string file = ::testing::TempDir() + "/bad_" + c.name + ".yaml";
    std::ofstream(file) << text;
    const ProgramRun r = run_program("run " + file + " -q -o " + ::testing::TempDir() + "/bad_out", std::string("bad_") + c.name);
    EXPECT_EQ(r.exit_code, 2) << c.name << ": " << r.stderr_text;
    EXPECT_NE(r.stderr_text.find(c.key), std::string::npos) << c.name << ": " << r.stderr_text;
  }
  EXPECT_EQ(run_program("run /nonexistent.yaml -q", "bad_missing_file").exit_code, 2);
}

TEST(StrandProgram, NonConvergenceGivesExitCode3AndKeepsConvergedIncrements) {
  std::ifstream in(case_path("cases/verification/straight_wire_axial_torque.yaml"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // A moment that rolls the wire up twice in one increment, with one Newton iteration and no cut-back.
  text.replace(text.find("moment: [0, 0, 2000]"), 20, "moment: [0, 0, 9.0e7]");
  text.replace(text.find("solver: {"), 9, "solver: {max_iterations: 3, max_cutbacks: 1, ");
  const std::string file = ::testing::TempDir() + "/diverging.yaml";
  std::ofstream(file) << text;
  const std::string out = ::testing::TempDir() + "/diverging_out";
  const ProgramRun r = run_program("run " + file + " -q -o " + out, "diverging");
  EXPECT_EQ(r.exit_code, 3) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("did not converge"), std::string::npos);
  // The stop names where Newton failed, what was tried, and what in the case to check.
  for (const char* part : {"increment 1:", "relative residual", "the last attempt gave up: a correction longer than the model",
                           "tried:", "line search", "halving the increment 1 times", "check:", "raise its `increments`"})
    EXPECT_NE(r.stderr_text.find(part), std::string::npos) << part << "\n" << r.stderr_text;
  EXPECT_EQ(read_csv(std::filesystem::path(out) / "history.csv").size(), 2u);  // the pull step converged
  const nlohmann::json summary = nlohmann::json::parse(std::ifstream(std::filesystem::path(out) / "summary.json"));
  EXPECT_EQ(summary["status"], "not_converged");
}

// A progress line says when an increment is smaller than the step's nominal one, after how many cut-backs, and
// whether line search was on: from the cut-back until the increments are back at their nominal size (the resume
// case cuts its first increment once).
TEST(StrandProgram, ProgressLinesReportCutBacks) {
  const std::string out = ::testing::TempDir() + "/progress_out";
  const ProgramRun r = run_program("run " + case_path("cases/verification/resume_axial_cycles.yaml") + " -o " + out, "progress");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("increment 1 (fraction 0.166667, 1/2 of the nominal increment after 1 cut-back, with line search)"),
            std::string::npos) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("increment 2 (fraction 0.333333, 1/2 of the nominal increment, with line search)"), std::string::npos)
      << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("'pull' increment 5 (fraction 1): "), std::string::npos) << r.stderr_text;
}

// With -v each Newton iteration's line says what preceded it (a correction cut by the step control or by line search,
// a round of contact changes), and a failed attempt says why it gave up (the same case's first increment).
TEST(StrandProgram, VerboseLinesSayWhatEachIterationDidAndWhyAnAttemptGaveUp) {
  const std::string out = ::testing::TempDir() + "/verbose_out";
  const ProgramRun r = run_program("run " + case_path("cases/verification/resume_axial_cycles.yaml") + " -v -o " + out, "verbose");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  for (const char* part : {"step 1 increment 1: attempt at fraction 0.333333 gave up after", "(contact step control)",
                           "(line search)", "after a contact round ("})
    EXPECT_NE(r.stderr_text.find(part), std::string::npos) << part << "\n" << r.stderr_text;
}

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The end-of-run report on stdout gives what summary.json measured: for a pulled strand the secant slope beside
// the fixed-end theory (Costello, within 0.5 % for Table 1's strand); -q silences it.
TEST(StrandProgram, EndOfRunReportGivesTheAxialSlopeBesideTheTheory) {
  const std::string out = ::testing::TempDir() + "/report_axial_out";
  const ProgramRun r = run_program("run " + case_path("cases/paper/seven_wire_fixed.yaml") + " -o " + out, "report_axial");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const nlohmann::json summary = nlohmann::json::parse(std::ifstream(std::filesystem::path(out) / "summary.json"));
  const auto history = read_csv(std::filesystem::path(out) / "history.csv");
  const nlohmann::json& axial = summary["axial"];
  const double secant = history.back().at("axial_force_N") / history.back().at("axial_strain");
  EXPECT_NEAR(axial["secant_stiffness_N"].get<double>(), secant, 1e-6 * secant);
  const double costello = summary["axial_stiffness_N"]["fixed_ends"].get<double>();
  EXPECT_EQ(axial["theory_ends"], "fixed");
  EXPECT_NEAR(axial["relative_to_theory"].get<double>(), secant / costello - 1, 1e-7);  // history.csv rounds
  EXPECT_LT(std::abs(secant / costello - 1), 0.005);
  const std::string stdout_text = read_text(r.output / "stdout.txt");
  const std::string slope = fmt::format("secant slope {:.5g} MN against {:.5g} MN of the linear theory for fixed ends", 1e-6 * secant,
                                        1e-6 * costello);
  EXPECT_NE(stdout_text.find(slope), std::string::npos) << stdout_text;
  EXPECT_NE(stdout_text.find("results in " + out), std::string::npos) << stdout_text;
  const ProgramRun quiet = run_program("run " + case_path("cases/paper/seven_wire_fixed.yaml") + " -q -o " + out, "report_quiet");
  ASSERT_EQ(quiet.exit_code, 0) << quiet.stderr_text;
  EXPECT_EQ(read_text(quiet.output / "stdout.txt"), "");
}

// For a bent strand the report gives each cycle's peak beside eq. 3.1's bounds, as loops.csv has them.
TEST(StrandProgram, EndOfRunReportGivesEachCyclesPeakBesideEq31) {
  const std::string out = ::testing::TempDir() + "/report_bending_out";
  const ProgramRun r = run_program("run " + case_path("cases/verification/bending_cycles_frictionless.yaml") + " -o " + out, "report_bending");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const auto loops = read_csv(std::filesystem::path(out) / "loops.csv");
  ASSERT_EQ(loops.size(), 1u);
  const std::string peak = fmt::format("cycle 1: peak {:.4g} mm at {:.5g} N (eq. 3.1: {:.4g} mm with EImax, {:.4g} mm with EImin)",
                                       loops[0].at("peak_deflection_mm"), loops[0].at("peak_load_N"), loops[0].at("eq31_ei_max_mm"),
                                       loops[0].at("eq31_ei_min_mm"));
  const std::string stdout_text = read_text(r.output / "stdout.txt");
  EXPECT_NE(stdout_text.find(peak), std::string::npos) << stdout_text;
  EXPECT_EQ(stdout_text.find("axial:"), std::string::npos) << stdout_text;
  // The progress lines say how far through the protocol each increment is.
  EXPECT_NE(r.stderr_text.find("; 100 % of the run"), std::string::npos) << r.stderr_text;
}

TEST(NewtonConvergence, ResidualDecreasesQuadratically) {
  CaseDefinition c = load_case(case_path("cases/verification/cantilever_roll_up.yaml"));
  // From the plain predictor (driven DOFs moved alone): an extrapolated one starts so close that the first
  // residuals are not yet in Newton's asymptotic range, and the order could not be read off them.
  c.model.options.extrapolate = false;
  StaticAnalysis analysis(c.model);
  std::vector<std::vector<double>> histories;
  ASSERT_TRUE(analysis.run([&](const IncrementReport& r) { histories.push_back(r.residual_history); }).converged);
  int checked = 0;
  for (const auto& h : histories) {
    EXPECT_LE(h.size(), 9u);
    // Order of convergence from the last three residuals r1 > r2 > r3 of each increment:
    // p = log(r3 / r2) / log(r2 / r1) is 2 for Newton with a consistent tangent, 1 for a wrong one.
    // Taken where the residual first drops below 1e-8, above the round-off floor (~1e-11).
    std::size_t j = 2;
    while (j < h.size() && h[j] >= 1e-8) ++j;
    if (j >= h.size()) continue;
    const double r1 = h[j - 2], r2 = h[j - 1], r3 = h[j];
    const double order = std::log(r3 / r2) / std::log(r2 / r1);
    EXPECT_GT(order, 1.8) << "residuals " << r1 << ", " << r2 << ", " << r3;
    ++checked;
  }
  EXPECT_GE(checked, 15);
}

// The cantilever rolled into a circle in eight increments from the plain predictor, without cut-backs: the first
// correction of the first increment (the linear response to an eighth of the moment) raises the residual a
// thousandfold.
CaseDefinition roll_up_in_eight_increments(int line_search_cuts) {
  CaseDefinition c = load_case(case_path("cases/verification/cantilever_roll_up.yaml"));
  c.model.options.extrapolate = false;
  c.model.options.line_search_cuts = line_search_cuts;
  c.model.options.max_cutbacks = 0;
  c.model.steps.at(0).increments = 8;
  return c;
}

// The line search never cuts an attempt's first correction (it carries the load step; docs/theory.md, "Line
// search"), and does cut later ones.
TEST(NewtonConvergence, LineSearchTakesTheFirstCorrectionInFull) {
  auto first_attempt = [](int line_search_cuts) {
    CaseDefinition c = roll_up_in_eight_increments(line_search_cuts);
    StaticAnalysis analysis(c.model);
    // The first attempt of the first increment, iteration by iteration (it may not converge: no cut-back here).
    std::vector<double> history;
    bool first_attempt_over = false;
    analysis.run({}, [&](const IncrementReport& r) {
      if (r.residual_history.size() <= history.size()) first_attempt_over = true;
      if (!first_attempt_over) history = r.residual_history;
    });
    return history;
  };
  const std::vector<double> full = first_attempt(0), searched = first_attempt(20);
  ASSERT_GE(full.size(), 4u);
  ASSERT_GE(searched.size(), 4u);
  EXPECT_GT(full[1], full[0]) << "the first correction must raise the residual for this test to mean anything";
  EXPECT_EQ(searched[1], full[1]);  // the same iterate: the first correction was not cut
  // Later corrections are cut while they raise the residual: with 20 halvings none of them does.
  bool full_rose = false;
  for (std::size_t k = 2; k < full.size(); ++k) full_rose |= full[k] > full[k - 1];
  for (std::size_t k = 2; k < searched.size(); ++k) EXPECT_LE(searched[k], searched[k - 1]) << "correction " << k;
  EXPECT_TRUE(full_rose) << "without the search a later correction must raise the residual";
}

// After a cut-back the retry's first correction is searched too (docs/theory.md, "Line search"): the roll-up's
// first attempt, given too few corrections to converge, takes its first correction in full; the retry at half
// the size cuts it while it raises the residual.
TEST(NewtonConvergence, LineSearchCutsTheFirstCorrectionOfARetryAfterACutBack) {
  CaseDefinition c = roll_up_in_eight_increments(20);
  c.model.options.max_cutbacks = 1;
  c.model.options.max_iterations = 2;
  StaticAnalysis analysis(c.model);
  std::vector<std::vector<double>> attempts;  // residual histories of the first increment's attempts
  bool next_attempt = true;
  analysis.run({}, [&](const IncrementReport& r) {
    if (r.increment != 1) return;
    if (r.failure != AttemptFailure::kNone) {  // the attempt gave up: the next report starts the retry
      next_attempt = true;
      return;
    }
    if (next_attempt) attempts.emplace_back();
    next_attempt = false;
    attempts.back() = r.residual_history;
  });
  ASSERT_GE(attempts.size(), 2u) << "the first attempt must fail and be retried for this test to mean anything";
  ASSERT_GE(attempts[0].size(), 2u);
  ASSERT_GE(attempts[1].size(), 2u);
  EXPECT_GT(attempts[0][1], attempts[0][0]) << "the first attempt's first correction is taken in full";
  EXPECT_LE(attempts[1][1], attempts[1][0]) << "the retry's first correction is cut while it raises the residual";
}

// An attempt whose full first correction raised the residual is measured from there by the divergence check, not
// from the predictor: the roll-up, whose searched corrections then fall slowly (967 -> 131 -> 6.7 -> ... -> 2.2
// after eight) but stay above the predictor's residual of 1 for longer than the check's eight corrections.
TEST(NewtonConvergence, DivergenceCheckStartsAfterTheFullFirstCorrection) {
  CaseDefinition c = roll_up_in_eight_increments(20);
  c.model.options.max_iterations = 200;
  StaticAnalysis analysis(c.model);
  std::size_t longest = 0;
  int converged_increments = 0;
  const AnalysisStatus status = analysis.run([&](const IncrementReport&) { ++converged_increments; },
                                             [&](const IncrementReport& r) {
                                               if (r.increment == 1) longest = std::max(longest, r.residual_history.size());
                                             });
  EXPECT_GT(longest, 10u) << "the first increment's attempt must go on past eight corrections above 1";
  EXPECT_GE(converged_increments, 1) << status.message;
}

// The extrapolated predictor changes where Newton starts, not where it ends: the same converged response to
// within the tolerances, in fewer iterations on a strand pulled in equal increments (frictional contact).
TEST(NewtonConvergence, ExtrapolatedPredictorKeepsTheResultInFewerIterations) {
  struct Outcome {
    double force = 0;
    int iterations = 0;
  };
  auto run = [](bool extrapolate) {
    CaseDefinition c = load_case(case_path("cases/paper/axial/strand_19.yaml"));
    c.model.options.extrapolate = extrapolate;
    StaticAnalysis analysis(c.model);
    EXPECT_TRUE(analysis.run({}).converged);
    Outcome o;
    for (int node = 0; node < static_cast<int>(analysis.internal_forces().size() / 6); ++node)
      if (c.model.mesh.nodes[node].reference.position.z() < 1e-9) o.force -= analysis.internal_forces()[6 * node + 2];
    o.iterations = analysis.statistics().newton_iterations;
    return o;
  };
  const Outcome plain = run(false), extrapolated = run(true);
  ASSERT_GT(plain.force, 0.0);
  EXPECT_NEAR(extrapolated.force, plain.force, 5e-3 * plain.force);  // the force tolerance of the case
  EXPECT_LT(extrapolated.iterations, plain.iterations);
}

// Under applied loads with the viscous stabilization the plain predictor is kept (extrapolate left on): its first
// correction from a converged state is the tangent predictor, where a secant one overshoots the damped soft modes
// (docs/theory.md, "Extrapolated predictor"). Without the stabilization the same strand extrapolates.
TEST(NewtonConvergence, StabilizedAppliedLoadsKeepThePlainPredictor) {
  auto extrapolated_increments = [](double stabilization) {
    CaseDefinition c = load_case(case_path("cases/paper/axial/s32_200.yaml"));
    EXPECT_TRUE(c.model.options.extrapolate);
    c.model.options.stabilization = stabilization;
    StaticAnalysis analysis(c.model);
    std::vector<IncrementReport> reports;
    EXPECT_TRUE(analysis.run([&](const IncrementReport& r) { reports.push_back(r); }).converged);
    EXPECT_EQ(reports.size(), 10u);
    int extrapolated = analysis.statistics().rejected_extrapolations;
    for (const IncrementReport& r : reports) extrapolated += r.extrapolated ? 1 : 0;
    return extrapolated;
  };
  EXPECT_EQ(extrapolated_increments(0.01), 0);
  EXPECT_GT(extrapolated_increments(0.0), 0);
}

}  // namespace
}  // namespace strandfem::verification
