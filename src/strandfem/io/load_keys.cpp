#include "strandfem/io/load_keys.hpp"

#include "strandfem/io/case_keys.hpp"

#include <cmath>
#include <numbers>

namespace strandfem {
namespace {
constexpr double kDegree = std::numbers::pi / 180.0;
// A cut-back halves the increment, and 30 of them reach 1e-9 of it; the load-factor grid of a step is resolved to
// 1e-12, far below 1 / kMaxIncrementsPerStep.
constexpr int kMaxIncrementsPerStep = 1000000;
constexpr int kMaxCycles = 10000;
const char* const kComponentNames[6] = {"ux", "uy", "uz", "rx", "ry", "rz"};
}  // namespace

void LoadKeys::hold(const Support& support, const std::string& holder) {
  for (int c = 0; c < 6; ++c)
    if (support.fixed[c]) dof_uses_[{support.node, c}].support = holder;
}

void LoadKeys::parse_supports(const YAML::Node& node) {
  if (!node.IsSequence()) reader_.fail(node, "supports", "expected a list of {at, fix}");
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string path = list_item("supports", i);
    reader_.check_keys(node[i], path, allowed_keys("supports[i]"));
    Support s;
    s.node = node_at_(reader_.require(node[i], path, "at"), path + ".at");
    const YAML::Node fix = reader_.require(node[i], path, "fix");
    if (fix.IsScalar() && fix.Scalar() == "all") s.fixed.fill(true);
    else if (fix.IsSequence()) {
      for (std::size_t k = 0; k < fix.size(); ++k) {
        const std::string c = reader_.choice(fix[k], list_item(path + ".fix", k), {"ux", "uy", "uz", "rx", "ry", "rz"});
        for (int j = 0; j < 6; ++j) if (c == kComponentNames[j]) s.fixed[j] = true;
      }
    } else reader_.fail(fix, path + ".fix", "expected 'all' or a list of ux, uy, uz, rx, ry, rz");
    for (int c = 0; c < 6; ++c)
      if (s.fixed[c] && dof_uses_[{s.node, c}].support.empty()) dof_uses_[{s.node, c}].support = path;
    out_.model.supports.push_back(s);
  }
}

// Adds an action to a step unless it contradicts another on the same DOF: two in one step (one would silently
// win), or a non-zero force where a support or a motion holds the DOF (a motion holds it in every step), which
// would never act. Motions on supported DOFs are how a support is moved; zero forces release earlier ones.
void LoadKeys::add_action(LoadStep& step, int step_index, const NodalAction& action, const YAML::Node& where, const std::string& path) {
  DofUse& use = dof_uses_[{action.node, action.component}];
  const std::string dof = std::string(kComponentNames[action.component]) + " of node " + std::to_string(action.node);
  if (use.last_step == step_index)
    reader_.fail(where, path, dof + " is driven twice in this step (also by " + use.last_path + "): give one action per DOF");
  if (action.kind == NodalAction::kForce && action.value != 0) {
    if (!use.support.empty()) reader_.fail(where, path, dof + " is held by " + use.support + ": a load on it would never act");
    if (!use.motion.empty())
      reader_.fail(where, path, dof + " is driven by a motion in another step (" + use.motion +
                                    "), which holds it in every step: a load on it would never act");
    if (use.force.empty()) use.force = path;
  }
  if (action.kind == NodalAction::kMotion) {
    if (!use.force.empty())
      reader_.fail(where, path, dof + " is loaded in another step (" + use.force +
                                    "): a motion would hold it in every step, and that load would never act");
    if (use.motion.empty()) use.motion = path;
  }
  use.last_step = step_index;
  use.last_path = path;
  step.actions.push_back(action);
}

void LoadKeys::parse_steps(const YAML::Node& node, const StrandModelParts* strand) {
  if (!node.IsSequence() || node.size() == 0) reader_.fail(node, "steps", "expected a list of load steps");
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YAML::Node s = node[i];
    const std::string path = list_item("steps", i);
    if (out_.strand)
      reader_.check_keys(s, path, allowed_keys("steps[i]"));
    else
      reader_.check_keys(s, path, allowed_keys("steps[i] (beams)"));
    LoadStep step;
    step.name = s["name"] ? reader_.text(s["name"], path + ".name") : "step" + std::to_string(i + 1);
    step.increments = reader_.integer(reader_.require(s, path, "increments"), path + ".increments", 1, kMaxIncrementsPerStep);
    if (s["cycles"]) step.cycles = reader_.integer(s["cycles"], path + ".cycles", 1, kMaxCycles);
    const int index = static_cast<int>(i);
    if (strand) parse_strand_actions(s, path, index, *strand, step);
    if (s["forces"]) parse_forces(s["forces"], path + ".forces", index, step);
    if (s["motions"]) parse_motions(s["motions"], path + ".motions", index, step);
    out_.model.steps.push_back(step);
  }
}

// The strand's loads, as strand_builder turns them into nodal actions.
void LoadKeys::parse_strand_actions(const YAML::Node& s, const std::string& path, int index, const StrandModelParts& strand,
                                    LoadStep& step) {
  if (s["axial_strain"] && s["axial_force"]) reader_.fail(s, path, "give axial_strain or axial_force, not both");
  if (s["torque"] && s["twist"]) reader_.fail(s, path, "give torque or twist, not both");
  if (s["axial_strain"])
    add_action(step, index, axial_strain_action(strand, reader_.number(s["axial_strain"], path + ".axial_strain"), out_.axial_length),
               s["axial_strain"], path + ".axial_strain");
  if (s["axial_force"])
    add_action(step, index, axial_force_action(strand, reader_.number(s["axial_force"], path + ".axial_force")), s["axial_force"],
               path + ".axial_force");
  if (s["torque"] || s["twist"]) {
    if (out_.end_type == "fixed") reader_.fail(s, path, "torque and twist need strand.ends: free (fixed ends hold the rotation)");
    if (s["torque"]) add_action(step, index, torque_action(strand, reader_.number(s["torque"], path + ".torque")), s["torque"], path + ".torque");
    else add_action(step, index, twist_action(strand, reader_.number(s["twist"], path + ".twist") * kDegree), s["twist"], path + ".twist");
  }
  if (s["transverse_force"]) {
    const YAML::Node t = s["transverse_force"];
    const std::string tp = path + ".transverse_force";
    reader_.check_keys(t, tp, allowed_keys("steps[i].transverse_force"));
    const double value = reader_.number(reader_.require(t, tp, "value"), tp + ".value");
    YAML::Node selector;
    selector["core_z"] = reader_.require(t, tp, "z");
    TransverseLoad load{node_at_(selector, tp), value, Vec3::UnitY()};
    // through: core (the load acts on the core node alone and reaches the other layers through contact), section
    // (every wire's node at that z is tied rigidly to the core node) or saddle (every node within saddle_length).
    const std::string through = t["through"] ? reader_.choice(t["through"], tp + ".through", {"core", "section", "saddle"}) : "core";
    if (through == "section") add_rigid_section(out_.model.mesh, load.node, out_.model.ties);
    if (t["saddle_length"] && through != "saddle") reader_.fail(t["saddle_length"], tp + ".saddle_length", "only with through: saddle");
    if (through == "saddle") {
      const double saddle = reader_.positive(reader_.require(t, tp, "saddle_length"), tp + ".saddle_length", "mm");
      const double z = out_.model.mesh.nodes[load.node].reference.position.z();
      if (z - 0.5 * saddle <= out_.clamp_length || z + 0.5 * saddle >= out_.axial_length - out_.clamp_length)
        reader_.fail(t["saddle_length"], tp + ".saddle_length", "the saddle reaches the clamps: expected it to lie between them");
      if (out_.saddle_length > 0 && out_.saddle_length != saddle)
        reader_.fail(t["saddle_length"], tp + ".saddle_length", "one saddle per strand: every step's must be the same");
      add_rigid_block(out_.model.mesh, load.node, z - 0.5 * saddle, z + 0.5 * saddle, out_.model.ties);
      out_.saddle_length = saddle;
    }
    if (t["direction"]) {
      const auto d = reader_.numbers(t["direction"], tp + ".direction", 3);
      load.direction = Vec3(d[0], d[1], d[2]);
      if (std::abs(load.direction.z()) > 1e-12 || load.direction.norm() == 0)
        reader_.fail(t["direction"], tp + ".direction", "expected a non-zero direction perpendicular to the strand axis (z = 0)");
      load.direction.normalize();
    }
    for (const NodalAction& a : transverse_actions(load)) add_action(step, index, a, t, tp);
  }
}

void LoadKeys::parse_forces(const YAML::Node& node, const std::string& path, int index, LoadStep& step) {
  if (!node.IsSequence()) reader_.fail(node, path, "expected a list of {at, force, moment}");
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string p = list_item(path, i);
    reader_.check_keys(node[i], p, allowed_keys("steps[i].forces[i]"));
    const int n = node_at_(reader_.require(node[i], p, "at"), p + ".at");
    if (!node[i]["force"] && !node[i]["moment"]) reader_.fail(node[i], p, "expected 'force' and/or 'moment'");
    for (const char* key : {"force", "moment"}) {
      if (!node[i][key]) continue;
      const auto v = reader_.numbers(node[i][key], p + "." + key, 3);
      const int offset = std::string(key) == "force" ? 0 : 3;
      for (int c = 0; c < 3; ++c) add_action(step, index, {NodalAction::kForce, n, offset + c, v[c]}, node[i][key], p + "." + key);
    }
  }
}

void LoadKeys::parse_motions(const YAML::Node& node, const std::string& path, int index, LoadStep& step) {
  if (!node.IsSequence()) reader_.fail(node, path, "expected a list of {at, ux.., rz (deg)}");
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string p = list_item(path, i);
    reader_.check_keys(node[i], p, allowed_keys("steps[i].motions[i]"));
    const int n = node_at_(reader_.require(node[i], p, "at"), p + ".at");
    for (int c = 0; c < 6; ++c)
      if (const YAML::Node v = node[i][kComponentNames[c]])
        add_action(step, index, {NodalAction::kMotion, n, c, reader_.number(v, p + "." + kComponentNames[c]) * (c >= 3 ? kDegree : 1.0)}, v,
                   p + "." + kComponentNames[c]);
  }
}

}  // namespace strandfem
