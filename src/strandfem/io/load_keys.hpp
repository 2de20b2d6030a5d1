// The case file's `supports:` and `steps:` keys: supports, load steps and their nodal actions, refusing the
// contradictory ones (a DOF driven twice in a step, a load where a support or a motion holds it).
#pragma once
#include <functional>
#include <array>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "strandfem/analysis/strand_builder.hpp"
#include "strandfem/io/case_file.hpp"
#include "strandfem/io/setting_keys.hpp"
#include "strandfem/io/yaml_reader.hpp"

namespace strandfem {

// A strand step's loads at the core end z = L as the case gives them (the twist held in radians).
struct StrandEndLoads {
  std::optional<double> axial_strain, axial_force, torque, twist;
};

// A step's transverse force on a strand as the case gives it.
struct TransverseForceKeys {
  double value = 0;                // N
  double z = 0;                    // mm: the core node nearest it
  Vec3 direction = Vec3::UnitY();  // unit, across the strand
  std::string through = "core";    // core | section | saddle
  std::optional<double> saddle_length;  // mm, with through: saddle
};

struct SupportKeys {
  YAML::Node at;                    // node selector
  std::array<bool, 6> fixed{};      // ux, uy, uz, rx, ry, rz
};

// A dead load on a node, in global axes.
struct ForceKeys {
  YAML::Node at;
  std::optional<Vec3> force, moment;  // N, N mm
};

// Imposed motions of a node: displacements in mm, rotations held in radians.
struct MotionKeys {
  YAML::Node at;
  std::array<std::optional<double>, 6> components;  // ux, uy, uz, rx, ry, rz
};

const std::vector<SettingKey<SupportKeys>>& support_key_table();
const std::vector<SettingKey<ForceKeys>>& force_key_table();    // at least one of force and moment: the reader checks
const std::vector<SettingKey<MotionKeys>>& motion_key_table();

// The keys of `steps[i]` (name, increments, cycles; strands also the end loads) and `steps[i].transverse_force`.
// Which loads exclude each other, and what needs free ends or a saddle: the reader checks.
const std::vector<SettingKey<LoadStep>>& step_key_table();
const std::vector<SettingKey<StrandEndLoads>>& strand_end_load_key_table();
const std::vector<SettingKey<TransverseForceKeys>>& transverse_force_key_table();

class LoadKeys {
 public:
  // The case's node selectors (strand core positions, beam points, hubs), as the case reader resolves them.
  using NodeSelector = std::function<int(const YAML::Node&, const std::string&)>;
  LoadKeys(const YamlReader& reader, CaseDefinition& out, NodeSelector node_at)
      : reader_(reader), out_(out), node_at_(std::move(node_at)) {}

  // DOFs the model holds before any key is read (a strand's clamps), named `holder` in messages.
  void hold(const Support& support, const std::string& holder);
  // `supports:` (docs/case-files.md) into out.model.supports.
  void parse_supports(const YAML::Node& node);
  // `steps:` into out.model.steps; `strand`: the strand's built parts, whose nodes the strand loads act on (null
  // for beam cases).
  void parse_steps(const YAML::Node& node, const StrandModelParts* strand);

 private:
  void add_action(LoadStep& step, int step_index, const NodalAction& action, const YAML::Node& where, const std::string& path);
  void parse_strand_actions(const YAML::Node& s, const std::string& path, int index, const StrandModelParts& strand,
                            LoadStep& step);
  void parse_forces(const YAML::Node& node, const std::string& path, int index, LoadStep& step);
  void parse_motions(const YAML::Node& node, const std::string& path, int index, LoadStep& step);

  const YamlReader& reader_;
  CaseDefinition& out_;
  NodeSelector node_at_;
  // The keys that hold or drive each DOF (first support, motion, non-zero force; the last step that acted on it):
  // contradictions name both keys.
  struct DofUse {
    std::string support, motion, force, last_path;
    int last_step = -1;
  };
  std::map<std::pair<int, int>, DofUse> dof_uses_;
};

}  // namespace strandfem
