#include "strandfem/io/load_keys.hpp"

#include "strandfem/io/case_keys.hpp"

#include <cmath>
#include <tuple>
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

const std::vector<SettingKey<LoadStep>>& step_key_table() {
  static const std::vector<SettingKey<LoadStep>> table = keys_in_section<LoadStep>(KeySection::kPhysics, {
        text_key("name", &LoadStep::name, "text", "step name in progress lines and results").default_is("`step1`, `step2`, … by position"),
        integer_key("increments", &LoadStep::increments, 1, kMaxIncrementsPerStep,
                    "equal load levels the step reaches (totals at its end); cut increments never step past the next level, so "
                    "results land on them")
            .must_be_given(),
        integer_key("cycles", &LoadStep::cycles, 1, kMaxCycles,
                    "the step's actions go to their values and back to their totals before the step, this many times, each half in "
                    "`increments`; actions not listed (the tension) are held. Writes `loops.csv` and `deflection_curves.csv`")
            .default_is("— (not cyclic)"),
    });
  return table;
}

const std::vector<SettingKey<StrandEndLoads>>& strand_end_load_key_table() {
  using E = StrandEndLoads;
  static const std::vector<SettingKey<E>> table = keys_in_section<E>(KeySection::kPhysics, {
        optional_number_key("axial_strain", &E::axial_strain, NumberRange::any(), "−", "strands: imposed strain at the core end z = L (u_z = ε L)"),
        optional_number_key("axial_force", &E::axial_force, NumberRange::any(), "N", "strands: force at the core end z = L"),
        optional_number_key("torque", &E::torque, NumberRange::any(), "N·mm", "strands with `ends: free`: moment about z at z = L"),
        optional_number_key("twist", &E::twist, NumberRange::any(), "deg", "strands with `ends: free`: rotation about z at z = L", kDegree),
    });
  return table;
}

const std::vector<SettingKey<TransverseForceKeys>>& transverse_force_key_table() {
  using T = TransverseForceKeys;
  static const std::vector<SettingKey<T>> table = [] {
    auto direction = described_key<T>("direction", "`[dx, dy, 0]`", "its direction across the strand", "");
    direction.read = [](const YamlReader& reader, const YAML::Node& node, const std::string& path, T& t) {
      const auto d = reader.numbers(node, path, 3);
      const Vec3 v(d[0], d[1], d[2]);
      if (std::abs(v.z()) > 1e-12 || v.norm() == 0)
        reader.fail(node, path, "expected a non-zero direction perpendicular to the strand axis (z = 0)");
      t.direction = v.normalized();
    };
    direction.value = [](const T& t) { return nlohmann::json::array({t.direction.x(), t.direction.y(), t.direction.z()}); };
    return keys_in_section<T>(KeySection::kPhysics, {
        number_key("value", &T::value, NumberRange::any(), "N", "strands: a force on the core node nearest `z`").must_be_given(),
        number_key("z", &T::z, NumberRange::any(), "mm", "where").must_be_given(),
        std::move(direction.default_is("`[0, 1, 0]`")),
        choice_key("through", &T::through,
                   {{"core", std::string("core")}, {"section", std::string("section")}, {"saddle", std::string("saddle")}},
                   "how it reaches the wires: the core node alone (the layers through contact); every wire's node nearest z tied "
                   "rigidly to it; every node of every wire within `saddle_length` tied to it (a saddle or clamp that grips the strand over a length; "
                   "the bending references leave that length out of the span)"),
        optional_number_key("saddle_length", &T::saddle_length, NumberRange::positive(), "mm", "with `through: saddle`"),
    });
  }();
  return table;
}

const std::vector<SettingKey<SupportKeys>>& support_key_table() {
  static const std::vector<SettingKey<SupportKeys>> table = [] {
    auto fix = described_key<SupportKeys>("fix", "`all` \\| list of `ux, uy, uz, rx, ry, rz`", "held DOFs", "");
    fix.read = [](const YamlReader& reader, const YAML::Node& node, const std::string& path, SupportKeys& s) {
      if (node.IsScalar() && node.Scalar() == "all") s.fixed.fill(true);
      else if (node.IsSequence())
        for (std::size_t k = 0; k < node.size(); ++k) {
          const std::string c = reader.choice(node[k], list_item(path, k), {"ux", "uy", "uz", "rx", "ry", "rz"});
          for (int j = 0; j < 6; ++j)
            if (c == kComponentNames[j]) s.fixed[j] = true;
        }
      else reader.fail(node, path, "expected 'all' or a list of ux, uy, uz, rx, ry, rz");
    };
    fix.value = [](const SupportKeys& s) {
      nlohmann::json held = nlohmann::json::array();
      for (int j = 0; j < 6; ++j)
        if (s.fixed[j]) held.push_back(kComponentNames[j]);
      return held;
    };
    return keys_in_section<SupportKeys>(KeySection::kPhysics, {
        node_key("at", &SupportKeys::at, "selector", "the node").must_be_given(),
        std::move(fix.must_be_given()),
    });
  }();
  return table;
}

const std::vector<SettingKey<ForceKeys>>& force_key_table() {
  using F = ForceKeys;
  static const std::vector<SettingKey<F>> table = keys_in_section<F>(KeySection::kPhysics, {
        node_key("at", &F::at, "selector", "dead loads in global axes, on this node").must_be_given(),
        vector_key("force", &F::force, "`[fx, fy, fz]` N", "force").default_is("—"),
        vector_key("moment", &F::moment, "`[mx, my, mz]` N·mm", "moment").default_is("—"),
    });
  return table;
}

const std::vector<SettingKey<MotionKeys>>& motion_key_table() {
  static const std::vector<SettingKey<MotionKeys>> table = [] {
    std::vector<SettingKey<MotionKeys>> keys = {node_key("at", &MotionKeys::at, "selector",
                                                         "imposed motions of this node (the DOF is then held in every step; on a "
                                                         "supported DOF the support moves)")
                                                    .must_be_given()};
    for (int c = 0; c < 6; ++c) {
      const bool rotation = c >= 3;
      const double scale = rotation ? kDegree : 1.0;
      auto key = described_key<MotionKeys>(kComponentNames[c], rotation ? "deg" : "mm",
                                           std::string(rotation ? "rotation about " : "displacement along ") + "xyz"[c % 3], "");
      key.read = [c, scale](const YamlReader& reader, const YAML::Node& node, const std::string& path, MotionKeys& m) {
        m.components[c] = reader.number(node, path) * scale;
      };
      key.value = [c, scale](const MotionKeys& m) { return m.components[c] ? nlohmann::json(*m.components[c] / scale) : nlohmann::json(nullptr); };
      keys.push_back(std::move(key.default_is("—")));
    }
    return keys_in_section<MotionKeys>(KeySection::kPhysics, std::move(keys));
  }();
  return table;
}

void LoadKeys::hold(const Support& support, const std::string& holder) {
  for (int c = 0; c < 6; ++c)
    if (support.fixed[c]) dof_uses_[{support.node, c}].support = holder;
}

void LoadKeys::parse_supports(const YAML::Node& node) {
  if (!node.IsSequence()) reader_.fail(node, "supports", "expected a list of {at, fix}");
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string path = list_item("supports", i);
    reader_.check_keys(node[i], path, allowed_keys("supports[i]"));
    SupportKeys keys;
    read_setting_keys(reader_, node[i], path, support_key_table(), keys);
    Support s;
    s.node = node_at_(keys.at, path + ".at");
    s.fixed = keys.fixed;
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
    step.name = "step" + std::to_string(i + 1);
    read_setting_keys(reader_, s, path, step_key_table(), step);
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
  StrandEndLoads loads;
  read_setting_keys(reader_, s, path, strand_end_load_key_table(), loads);
  if (loads.axial_strain)
    add_action(step, index, axial_strain_action(strand, *loads.axial_strain, out_.axial_length), s["axial_strain"], path + ".axial_strain");
  if (loads.axial_force) add_action(step, index, axial_force_action(strand, *loads.axial_force), s["axial_force"], path + ".axial_force");
  if (loads.torque || loads.twist) {
    if (out_.end_type == "fixed") reader_.fail(s, path, "torque and twist need strand.ends: free (fixed ends hold the rotation)");
    if (loads.torque) add_action(step, index, torque_action(strand, *loads.torque), s["torque"], path + ".torque");
    else add_action(step, index, twist_action(strand, *loads.twist), s["twist"], path + ".twist");
  }
  if (s["transverse_force"]) {
    const YAML::Node t = s["transverse_force"];
    const std::string tp = path + ".transverse_force";
    reader_.check_keys(t, tp, allowed_keys("steps[i].transverse_force"));
    TransverseForceKeys keys;
    read_setting_keys(reader_, t, tp, transverse_force_key_table(), keys);
    YAML::Node selector;
    selector["core_z"] = t["z"];
    TransverseLoad load{node_at_(selector, tp), keys.value, keys.direction};
    // through: core (the load acts on the core node alone and reaches the other layers through contact), section
    // (every wire's node at that z is tied rigidly to the core node) or saddle (every node within saddle_length).
    if (keys.through == "section") add_rigid_section(out_.model.mesh, load.node, out_.model.ties);
    if (keys.saddle_length && keys.through != "saddle") reader_.fail(t["saddle_length"], tp + ".saddle_length", "only with through: saddle");
    if (keys.through == "saddle") {
      reader_.require(t, tp, "saddle_length");
      const double saddle = *keys.saddle_length;
      const double z = out_.model.mesh.nodes[load.node].reference.position.z();
      if (z - 0.5 * saddle <= out_.clamp_length || z + 0.5 * saddle >= out_.axial_length - out_.clamp_length)
        reader_.fail(t["saddle_length"], tp + ".saddle_length", "the saddle reaches the clamps: expected it to lie between them");
      if (out_.saddle_length > 0 && out_.saddle_length != saddle)
        reader_.fail(t["saddle_length"], tp + ".saddle_length", "one saddle per strand: every step's must be the same");
      add_rigid_block(out_.model.mesh, load.node, z - 0.5 * saddle, z + 0.5 * saddle, out_.model.ties);
      out_.saddle_length = saddle;
    }
    for (const NodalAction& a : transverse_actions(load)) add_action(step, index, a, t, tp);
  }
}

void LoadKeys::parse_forces(const YAML::Node& node, const std::string& path, int index, LoadStep& step) {
  if (!node.IsSequence()) reader_.fail(node, path, "expected a list of {at, force, moment}");
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string p = list_item(path, i);
    reader_.check_keys(node[i], p, allowed_keys("steps[i].forces[i]"));
    ForceKeys keys;
    read_setting_keys(reader_, node[i], p, force_key_table(), keys);
    const int n = node_at_(keys.at, p + ".at");
    if (!keys.force && !keys.moment) reader_.fail(node[i], p, "expected 'force' and/or 'moment'");
    for (const auto& [key, value, offset] : {std::tuple{"force", keys.force, 0}, std::tuple{"moment", keys.moment, 3}}) {
      if (!value) continue;
      for (int c = 0; c < 3; ++c) add_action(step, index, {NodalAction::kForce, n, offset + c, (*value)[c]}, node[i][key], p + "." + key);
    }
  }
}

void LoadKeys::parse_motions(const YAML::Node& node, const std::string& path, int index, LoadStep& step) {
  if (!node.IsSequence()) reader_.fail(node, path, "expected a list of {at, ux.., rz (deg)}");
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string p = list_item(path, i);
    reader_.check_keys(node[i], p, allowed_keys("steps[i].motions[i]"));
    MotionKeys keys;
    read_setting_keys(reader_, node[i], p, motion_key_table(), keys);
    const int n = node_at_(keys.at, p + ".at");
    for (int c = 0; c < 6; ++c)
      if (keys.components[c])
        add_action(step, index, {NodalAction::kMotion, n, c, *keys.components[c]}, node[i][kComponentNames[c]], p + "." + kComponentNames[c]);
  }
}

}  // namespace strandfem
