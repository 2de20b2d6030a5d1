#include "strandfem/io/model_keys.hpp"

namespace strandfem {

const std::vector<SettingKey<Material>>& material_key_table() {
  static const std::vector<SettingKey<Material>> table = keys_in_section<Material>(KeySection::kPhysics, {
        number_key("E", &Material::youngs_modulus, NumberRange::positive(), "MPa", "Young's modulus").must_be_given(),
        number_key("nu", &Material::poisson_ratio, NumberRange::open(-1, 0.5), "", "Poisson's ratio").must_be_given(),
        number_key("density", &Material::density, NumberRange::non_negative(), "t/mm³", "for the mass per length in summary.json")
            .default_is("—"),
    });
  return table;
}

const std::vector<SettingKey<BilinearHardening>>& plasticity_key_table() {
  using B = BilinearHardening;
  static const std::vector<SettingKey<B>> table = keys_in_section<B>(KeySection::kPhysics, {
        number_key("yield_stress", &B::yield_stress, NumberRange::positive(), "MPa",
                   "bilinear kinematic hardening (docs/theory.md, \"Plasticity\"): wires of this material get a fibre section (4 × 24 "
                   "fibres, J2 per fibre); needs circular sections")
            .must_be_given(),
        number_key("tangent_modulus", &B::tangent_modulus, NumberRange::non_negative(), "MPa", "hardening slope")
            .must_be_given()
            .typed("MPa, 0 ≤ Et < E"),
        choice_key("stress_measure", &B::stress_measure,
                   {{"true_stress", StressMeasure::true_stress}, {"engineering", StressMeasure::engineering}},
                   "the law in true stress against logarithmic strain, or in engineering stress and strain"),
    });
  return table;
}

namespace {
// A list of numbers, one per layer around the core: its length is checked against the conductor's layers.
SettingKey<StrandSettings> layer_list_key(const char* name, std::vector<double> StrandSettings::*member, double scale, std::string type,
                                          std::string meaning) {
  auto key = described_key<StrandSettings>(name, std::move(type), std::move(meaning), "");
  key.read = [member, scale](const YamlReader& reader, const YAML::Node& node, const std::string& path, StrandSettings& s) {
    if (!node.IsSequence() || node.size() == 0) reader.fail(node, path, "expected a list of numbers, one per layer around the core");
    s.*member = reader.numbers(node, path, node.size());
    for (std::size_t i = 0; i < node.size(); ++i) {
      const double v = (s.*member)[i];
      if (!(v > 0) || (scale != 1 && !(v < 90))) reader.fail(node[i], path, scale != 1 ? "expected an angle in (0, 90) degrees" : "expected a number > 0");
      (s.*member)[i] = v * scale;
    }
  };
  key.value = [member, scale](const StrandSettings& s) {
    if ((s.*member).empty()) return nlohmann::json(nullptr);
    nlohmann::json list = nlohmann::json::array();
    for (double v : s.*member) list.push_back(v / scale);
    return list;
  };
  return key;
}
}  // namespace

const std::vector<SettingKey<StrandSettings>>& strand_key_table() {
  using S = StrandSettings;
  static const std::vector<SettingKey<S>> table = keys_in_section<S>(KeySection::kPhysics, {
        number_key("length", &S::length, NumberRange::positive(), "mm", "strand length").must_be_given(),
        choice_key("ends", &S::ends, {{"fixed", std::string("fixed")}, {"free", std::string("free")}},
                   "end z = L: axial displacement free (fixed), plus rotation about z (free); end z = 0 clamped"),
        number_key("clamp_length", &S::clamp_length, NumberRange::non_negative(), "mm",
                   "every wire's nodes within this length of each end are tied rigidly to the end plane, as a clamp that grips the "
                   "strand over its jaws")
            .typed("mm, ≥ 0 and below half the length"),
        text_key("conductor", &S::conductor, "name",
                 "a conductor of the catalogue (`strandfem conductors`; a file of your own with `--catalogue`) instead of `layers`: its "
                 "layers, wire materials (`materials` may replace one by name) and lay angles; directions alternating, outer layer right")
            .default_is("—"),
        layer_list_key("lay_ratios", &S::lay_ratios, 1, "list, one per layer around the core",
                       "with `conductor`: lay length over the layer's outer diameter; `strandfem info` warns outside EN 50182's range")
            .default_is("the catalogue's lay angles, else the middle of EN 50182's range"),
        layer_list_key("lay_angles", &S::lay_angles, kRadiansPerDegree, "list of deg, one per layer around the core",
                       "with `conductor`, instead of `lay_ratios`")
            .default_is("—"),
    });
  return table;
}

const std::vector<SettingKey<LayerSpec>>& layer_key_table() {
  using L = LayerSpec;
  static const std::vector<SettingKey<L>> table = [] {
    // Read after `wires`, whose count the list must match.
    auto start_angles = described_key<L>("start_angles", "list of deg, one per wire",
                                         "per-wire angular positions at z = 0 (instead of `start_angle`); stacked wires are refused", "");
    start_angles.read = [](const YamlReader& reader, const YAML::Node& node, const std::string& path, L& l) {
      l.wire_start_angles.clear();
      for (double a : reader.numbers(node, path, static_cast<std::size_t>(l.wires))) l.wire_start_angles.push_back(a * kRadiansPerDegree);
    };
    start_angles.value = [](const L& l) {
      if (l.wire_start_angles.empty()) return nlohmann::json(nullptr);
      nlohmann::json angles = nlohmann::json::array();
      for (double a : l.wire_start_angles) angles.push_back(a / kRadiansPerDegree);
      return angles;
    };
    return keys_in_section<L>(KeySection::kPhysics, {
        integer_key("wires", &L::wires, 1, kMaxWiresPerLayer, "layer 0 (the core) has 1").must_be_given(),
        number_key("diameter", &L::wire_diameter, NumberRange::positive(), "mm", "wire diameter").must_be_given(),
        text_key("material", &L::material, "name", "one of `materials`").must_be_given(),
        degree_key("lay_angle", &L::lay_angle, NumberRange::open(0, 90), "from the strand axis; not for the core").must_be_given(),
        choice_key("lay_direction", &L::lay_direction, {{"right", 1}, {"left", -1}}, "not for the core")
            .default_is("alternating, outer layer right"),
        degree_key("start_angle", &L::start_angle, NumberRange{}, "angular position of the layer's first wire at z = 0; wires evenly spaced"),
        std::move(start_angles.default_is("—")),
    });
  }();
  return table;
}

const std::vector<SettingKey<MeshSpec>>& mesh_key_table() {
  static const std::vector<SettingKey<MeshSpec>> table = keys_in_section<MeshSpec>(KeySection::kPhysics, {
        number_key("element_length", &MeshSpec::element_length, NumberRange::positive(), "mm",
                   "target element length (or `mesh.elements_per_wire`, not both). At most 250,000 nodes (1,500,000 DOFs), checked "
                   "before anything is allocated; elements at least 1e-6 mm and 1e-6 of the coordinates' magnitude long"),
        integer_key("elements_per_wire", &MeshSpec::elements_per_wire, 1, kMaxElementsPerLine,
                    "elements along each wire, instead of `mesh.element_length`")
            .default_is("—"),
    });
  return table;
}

}  // namespace strandfem
