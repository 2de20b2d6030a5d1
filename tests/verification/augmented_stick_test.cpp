// Requirement: the augmented stick (contact.stick_augmentations) tends to Coulomb's rigid stick, so that a friction
// loop no longer depends on the penalty's elastic slip: against a closed form for two pressed wires, and on a
// 19-wire strand bent once under tension at two elastic slips; under tension, where rounds turn points between stick and
// slip without moving the strand, the rounds end after one.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "program_runner.hpp"
#include "test_strands.hpp"

namespace strandfem::verification {
namespace {

// A shipped case file's text with its first `key` text replaced (nothing replaced for an empty key); a key the file
// does not hold fails the test.
std::string shipped_case_with(const char* file, const std::string& key, const std::string& replacement) {
  std::ifstream in(case_path(file));
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  if (key.empty()) return yaml;
  const auto at = yaml.find(key);
  EXPECT_NE(at, std::string::npos) << key << " is not in " << file;
  if (at != std::string::npos) yaml.replace(at, key.size(), replacement);
  return yaml;
}

std::filesystem::path run_inline_case(const std::string& text, const std::string& tag) {
  const std::string file = ::testing::TempDir() + "/" + tag + ".yaml";
  std::ofstream(file) << text;
  const std::string out = ::testing::TempDir() + "/" + tag + "_out";
  const ProgramRun r = run_program("run " + file + " -q -t 1 -o " + out, tag);
  EXPECT_EQ(r.exit_code, 0) << r.stderr_text;
  return out;
}

// Wire B (20 mm, 3 line-contact elements) pressed onto wire A, then pulled along it to +a, back to -a and to +a, under
// the elastic-slip law with an allowed slip s = a / 4 (0.00075 x h, h = 20/3 mm).
std::string pressed_wires(const std::string& contact) {
  return R"(
materials:
  steel: {E: 200000, nu: 0.3}
beams:
  - {name: A, material: steel, section: {diameter: 3.0}, shape: {type: straight, start: [0, 0, 0], end: [0, 0, 40]}, elements: 4}
  - {name: B, material: steel, section: {diameter: 3.0}, shape: {type: straight, start: [3, 0, 10], end: [3, 0, 30]}, elements: 3}
hubs:
  - {name: ground, position: [0, 0, 20], links: [{beam: A}]}
  - {name: press, position: [3, 0, 20], links: [{beam: B}]}
supports:
  - {at: {hub: ground}, fix: all}
  - {at: {hub: press}, fix: all}
contact: {friction: 0.2, elastic_slip: 0.00075)" + contact + R"(}
steps:
  - {name: press, increments: 2, motions: [{at: {hub: press}, ux: -0.0001}]}
  - {name: pull, increments: 20, motions: [{at: {hub: press}, uz: 0.02}]}
  - {name: reverse, increments: 40, motions: [{at: {hub: press}, uz: -0.02}]}
  - {name: return, increments: 40, motions: [{at: {hub: press}, uz: 0.02}]}
solver: {force_tolerance: 1.0e-7, moment_tolerance: 1.0e-7, displacement_tolerance: 1.0e-7}
output: {monitor: {hub: press}, vtu: false}
)";
}

struct Loop {
  double pressed_force = 0, area = 0, friction_work = 0;
  std::vector<std::pair<double, double>> pull;  // (u, f) of the pull step
};

Loop pressed_wires_loop(const std::filesystem::path& out) {
  Loop loop;
  const auto rows = read_csv(out / "history.csv");
  double previous_u = 0, previous_f = 0;
  for (const auto& r : rows) {
    const int step = static_cast<int>(r.at("step"));
    const double u = r.at("monitor_uz_mm"), f = r.at("monitor_fz_N");
    if (step == 1) loop.pressed_force = -r.at("monitor_fx_N");
    if (step == 2) loop.pull.emplace_back(u, f);
    if (step >= 3) loop.area += 0.5 * (f + previous_f) * (u - previous_u);
    previous_u = u, previous_f = f;
  }
  loop.area = std::abs(loop.area);
  return loop;
}

TEST(AugmentedStick, PressedWiresSlideAtOnceAsUnderCoulombsRigidStick) {
  const double a = 0.02, s = a / 4;
  const Loop penalty = pressed_wires_loop(run_inline_case(pressed_wires(""), "aug_wires_penalty"));
  const Loop augmented = pressed_wires_loop(run_inline_case(pressed_wires(", stick_augmentations: 5"), "aug_wires_augmented"));
  const double Q = 0.2 * augmented.pressed_force;
  ASSERT_GT(Q, 0.0);
  // The penalty stick reaches mu P only after its elastic slip s: the elastic-perfectly-plastic loop 4 Q (a - s).
  EXPECT_NEAR(penalty.area, 4 * Q * (a - s), 0.03 * 4 * Q * a);
  // Augmented: rigid-plastic, the loop 4 Q a, and the pull at mu P from its second increment (u = a / 10).
  EXPECT_NEAR(augmented.area, 4 * Q * a, 0.03 * 4 * Q * a);
  for (const auto& [u, f] : augmented.pull)
    if (u >= 0.1 * a - 1e-12) EXPECT_NEAR(f, Q, 1e-3 * Q) << "u = " << u;
}

nlohmann::json first_loop(const std::filesystem::path& out) {
  return nlohmann::json::parse(std::ifstream(out / "summary.json"))["bending"]["loops"].at(0);
}

TEST(AugmentedStick, NineteenWireLoopNoLongerDependsOnTheElasticSlip) {
  const auto penalty = first_loop(run_inline_case(nineteen_wire_bent_once(", elastic_slip: 0.001"), "aug_19_penalty"));
  const auto coarse = first_loop(run_inline_case(nineteen_wire_bent_once(", elastic_slip: 0.001, stick_augmentations: 5"), "aug_19_coarse"));
  const auto fine = first_loop(run_inline_case(nineteen_wire_bent_once(", elastic_slip: 0.0005, stick_augmentations: 5"), "aug_19_fine"));
  const double area = fine["area_Nmm"].get<double>();
  // Halving the elastic slip moves the augmented loop by about 1 %, the peak by less; the penalty's loop is a
  // third smaller (docs/validation/regularization.md).
  EXPECT_NEAR(coarse["area_Nmm"].get<double>(), area, 0.02 * area);
  EXPECT_NEAR(coarse["peak_deflection_mm"].get<double>(), fine["peak_deflection_mm"].get<double>(), 0.01 * fine["peak_deflection_mm"].get<double>());
  EXPECT_LT(penalty["area_Nmm"].get<double>(), 0.85 * area);
  // Friction's work is the loop but for the work the stick's springs hold (under 20 % of it).
  EXPECT_NEAR(fine["friction_dissipation_Nmm"].get<double>(), area, 0.2 * area);
}

// The 19-wire strand of paper Table 2 pulled in 8 increments (cases/paper/axial/strand_19.yaml). Each increment's
// first round moves the strand by far less than Newton's tests allow, so it is its last; the axial force is the
// penalty stick's within 1e-4 (measured 5e-5).
TEST(AugmentedStick, RoundsThatMoveNothingEndUnderTension) {
  const std::string penalty_yaml = shipped_case_with("cases/paper/axial/strand_19.yaml", "", "");
  const std::string yaml = shipped_case_with("cases/paper/axial/strand_19.yaml", "friction: 0.115", "friction: 0.115, stick_augmentations: 5");
  ASSERT_NE(yaml, penalty_yaml);
  const auto augmented = nlohmann::json::parse(std::ifstream(run_inline_case(yaml, "aug_19_axial") / "summary.json"));
  const auto penalty = nlohmann::json::parse(std::ifstream(run_inline_case(penalty_yaml, "pen_19_axial") / "summary.json"));
  const int increments = 8;
  EXPECT_GE(augmented["solver_statistics"]["stick_augmentations"].get<int>(), 1);
  EXPECT_LE(augmented["solver_statistics"]["stick_augmentations"].get<int>(), increments);
  const double force = penalty["axial"]["axial_force_N"].get<double>();
  EXPECT_NEAR(augmented["axial"]["axial_force_N"].get<double>(), force, 1e-4 * force);
}

// A round after which Newton fails is abandoned: the increment keeps the iterate that converged before it, and its
// history row records that iterate's residual, not the failed attempt's. The 7-wire strand at mu 5 with rounds at
// any elastic slip abandons rounds in most bending increments (15 measured).
TEST(AugmentedStick, AnAbandonedRoundKeepsAndRecordsTheConvergedIterate) {
  const std::string yaml = shipped_case_with("cases/verification/bending_cycles_sticking.yaml", "contact: {friction: 5}",
                                             "contact: {friction: 5, stick_augmentations: 5, stick_tolerance: 1.0e-6}");
  const auto out = run_inline_case(yaml, "aug_abandoned");
  const auto summary = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_GE(summary["solver_statistics"]["abandoned_augmentations"].get<int>(), 1);
  const double tolerance = 1.0e-5;  // the case's force and moment tolerances
  for (const auto& row : read_csv(out / "history.csv"))
    EXPECT_LE(row.at("residual_norm"), tolerance) << "step " << row.at("step") << " increment " << row.at("increment");
}

}  // namespace
}  // namespace strandfem::verification
