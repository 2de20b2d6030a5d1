#include "strandfem/io/contact_keys.hpp"

#include "strandfem/io/case_keys.hpp"

#include <tuple>
#include <utility>
#include <vector>

namespace strandfem {

namespace {

const NumberRange kFrictionRange = NumberRange::half_open(0, 10);  // Coulomb coefficients the reader accepts

std::string material_name(const YamlReader& reader, const YAML::Node& node, const std::string& path,
                          const std::map<std::string, Material>& materials) {
  const std::string name = reader.text(node, path);
  if (!materials.count(name)) {
    std::string known;
    for (const auto& [material, properties] : materials) known += (known.empty() ? "" : ", ") + material;
    reader.fail(node, path, "unknown material '" + name + "' (the case's: " + known + "; others go under 'materials')");
  }
  return name;
}
// Two material names [a, b] at `node`.
std::pair<std::string, std::string> material_pair(const YamlReader& reader, const YAML::Node& node, const std::string& path,
                                                  const std::map<std::string, Material>& materials, const std::string& expected) {
  if (!node.IsSequence() || node.size() != 2) reader.fail(node, path, expected);
  return {material_name(reader, node[0], path + "[0]", materials), material_name(reader, node[1], path + "[1]", materials)};
}
}  // namespace

const std::vector<SettingKey<ContactSettings>>& contact_key_table() {
  using S = ContactSettings;
  constexpr KeySection kPhysics = KeySection::kPhysics;  // the keys a strand's description sets; the rest are advanced
  static const std::vector<SettingKey<S>> table = [] {
    std::vector<SettingKey<S>> t = {
        boolean_key("enabled", &S::enabled, "`false` keeps the section but turns contact off").in_section(kPhysics).default_is("true"),
        number_key("friction", &S::friction, kFrictionRange, "μ", "the coefficient of every pair the rules below leave").in_section(kPhysics),
        number_key("orthotropy_ratio", &S::orthotropy_ratio, NumberRange::positive(), "",
                   "μ2/μ1: μ1 along friction direction 1, μ2 across it on the contact plane (section 5.3)")
            .in_section(kPhysics),
        choice_key("friction_direction", &S::friction_direction,
                   {{"strand_axis", FrictionDirection::kStrandAxis}, {"slave_wire", FrictionDirection::kSlaveWire}},
                   "what direction 1 of an orthotropic point follows on the contact plane: the strand axis (section 5.3's text), or "
                   "the slave wire's tangent (the x axis of the paper's CONTA176 elements; the slave is the inner wire at a crossing)")
            .in_section(kPhysics),
        vector_key("axis", &S::strand_axis, "`[x, y, z]`", "beam cases: the \"strand axis\" of friction direction 1")
            .in_section(kPhysics)
            .default_is("`[0, 0, 1]`"),
        number_key("normal_factor", &S::normal_factor, NumberRange::positive(), "", "fKn of eq. 2.5",
                   "to check that a result does not depend on the penalty (a stiffer one moves the bending curve by < 1.5 %, "
                   "docs/validation.md)"),
        number_key("normal_multiplier", &S::normal_multiplier, NumberRange::positive(), "", "ξn of eq. 2.5", "as `normal_factor`"),
        choice_key("tangential_penalty", &S::tangential_penalty,
                   {{"elastic_slip", TangentialPenalty::kElasticSlip}, {"paper", TangentialPenalty::kPaper}},
                   "stick stiffness: `elastic_slip` k_t,i = μ_i P / (elastic_slip · h) along the strand axis (i = 1) and across (2), "
                   "P the current normal force; `paper`: eq. 2.6 with the factors below (docs/theory.md)",
                   "`paper` to reproduce eq. 2.6 literally"),
        number_key("elastic_slip", &S::elastic_slip, NumberRange::positive(), "fraction of the contact element length",
                   "allowed elastic slip of a sticking point (0.005 mm for 10 mm elements, a tenth of Abaqus' default; the bending "
                   "loop depends on it, docs/validation.md)",
                   "to check a loop's dependence on the stick's elastic slip"),
        integer_key("stick_augmentations", &S::stick_augmentations, 0, 100,
                    "augmentation rounds of the stick per increment: after Newton converges, sticking points take their elastic slip "
                    "into an offset and Newton corrects again, so that the stick tends to Coulomb's and the loop no longer depends on "
                    "`elastic_slip`; line contacts carrying under a tenth of the largest line load keep the penalty stick; the rounds "
                    "also end once one moves the nodes by less than `solver.displacement_tolerance` of the increment's motion and the "
                    "loads by less than `solver.force_tolerance` (0: the penalty stick alone; docs/theory.md, \"Augmented stick\")",
                    "5 for bending loops that must not depend on the elastic slip (docs/validation/regularization.md gives the cost)"),
        number_key("stick_tolerance", &S::stick_tolerance, NumberRange::below(1), "",
                   "the rounds stop once no sticking point has slipped elastically by more than this fraction of its allowed slip",
                   "convergence studies of the augmented stick"),
        number_key("tangential_factor", &S::tangential_factor, NumberRange::positive(), "", "fKt of eq. 2.6 (`tangential_penalty: paper`)",
                   "only with `tangential_penalty: paper`"),
        number_key("tangential_multiplier", &S::tangential_multiplier, NumberRange::positive(), "", "ξt of eq. 2.6",
                   "only with `tangential_penalty: paper`"),
        number_key("search_margin", &S::search_margin, NumberRange::positive(), "mm",
                   "boxes inflated by radius + margin; re-search after a node moved margin/2",
                   "raise for large sideways motions of wires between searches"),
        number_key("line_contact_angle", &S::line_contact_angle, NumberRange::open(0, 90), "deg",
                   "for wires the strand's layout does not classify (beam lines, layers laid the same way): centerlines closer than "
                   "this are in line contact, others in point contact. Wires of one layer and a helix on the core are always in line "
                   "contact, helices of opposite hand in different layers always cross (docs/theory.md, Search)",
                   "beam cases whose wires cross at small angles"),
        integer_key("line_points", &S::line_points, 1, 10, "Gauss points per slave element of a line contact",
                    "convergence studies of line contact"),
        choice_key("initial_overlap", &S::initial_overlap, {{"offset", InitialOverlap::kOffset}, {"keep", InitialOverlap::kKeep}},
                   "`offset`: each point's reference overlap (and gaps below `touch_tolerance`) is subtracted, stress-free start; "
                   "`keep`: pressed out in the first increment",
                   "`keep` to let a nominal overlap be pressed out as a load"),
        number_key("touch_tolerance", &S::touch_tolerance, NumberRange::half_open(0, 0.5), "fraction of r_a + r_b",
                   "reference gaps below it count as touching: offset to zero, stick anchors set there (0.02: 0.07 mm for 3.3 mm "
                   "wires; nominal helix geometry leaves layer-to-layer gaps of that order)",
                   "layers whose nominal radii leave gaps larger than 2 % of the wire radii"),
        number_key("stabilization", &S::stabilization, NumberRange::half_open(0, 1), "fraction of the normal penalty",
                   "contact stabilization: at every contact point a tangential spring of this fraction of the normal penalty on the "
                   "motion of the two surface points since the last converged increment (restarted at each one, so a damper in load "
                   "time), beside friction (0: none); its energy is added to summary.json's `energy.stabilization_energy_Nmm` "
                   "(docs/theory.md, \"Contact stabilization\")",
                   "the automatic stabilization switches it on (1e-4) where a step cannot go on; set it for strands whose contacts "
                   "slide freely and whose wires shift sideways along their layer (frictionless strands, `tangential_penalty: paper`)"),
        number_key("pattern_margin", &S::pattern_margin, NumberRange::half_open(0, 1), "fraction of r_a + r_b",
                   "element pairs enter the tangent's sparsity pattern once a point is closed or open by less than this, leave beyond "
                   "twice it; a point that closes outside the pattern widens it at once. Results do not depend on it (tested to 1e-6)",
                   "performance only"),
    };
    // The onset width is optional: left out, it follows the thinner wire's diameter.
    SettingKey<S> smoothing = described_key<S>("normal_smoothing", "mm, " + NumberRange::non_negative().text(),
                            "width s of the band over which the normal force sets in, k_n (g − s)² / (4 s) for \\|g\\| < s, where halving "
                            "it moves no result (docs/theory.md, \"Normal onset\"); 0: the plain penalty law",
                            "widen (to about 1e-3 mm) to run a study of many bending variants 2 to 10 times faster, at the price of first "
                            "loops 1–6 % smaller on Cardinal (docs/validation/default-settings.md); 0 to compare with a code that uses "
                            "the plain law");
    smoothing.read = [](const YamlReader& reader, const YAML::Node& node, const std::string& path, S& s) {
      s.normal_smoothing = reader.non_negative(node, path, "mm");
    };
    smoothing.value = [](const S& s) { return s.normal_smoothing ? nlohmann::json(*s.normal_smoothing) : nlohmann::json(nullptr); };
    smoothing.default_is(number_text(kNormalOnsetPerDiameter) + " × the thinner wire's diameter");
    t.push_back(smoothing);
    return t;
  }();
  return table;
}

const std::vector<SettingKey<FrictionPairKeys>>& friction_pair_key_table() {
  using P = FrictionPairKeys;
  static const std::vector<SettingKey<P>> table = keys_in_section<P>(KeySection::kPhysics, {
        node_key("materials", &P::materials, "`[a, b]`", "a material pair (order free)").must_be_given(),
        optional_number_key("mu", &P::mu, kFrictionRange, "μ", "its coefficient, over `contact.friction`"),
        optional_number_key("orthotropy_ratio", &P::orthotropy_ratio, NumberRange::positive(), "", "its μ2/μ1, over `contact.orthotropy_ratio`"),
        choice_key("contacts", &P::contacts, {{"lateral", std::string("lateral")}, {"radial", std::string("radial")}},
                   "the only interface the entry applies to; the first entry that applies and sets the value wins")
            .default_is("both"),
    });
  return table;
}

const std::vector<SettingKey<FrictionZoneKeys>>& friction_zone_key_table() {
  using Z = FrictionZoneKeys;
  static const std::vector<SettingKey<Z>> table = [] {
    auto z = described_key<Z>("z", "`[z_min, z_max]` mm", "an axial band (the multi-level model, section 5.2), over pairs; first match wins", "");
    z.read = [](const YamlReader& reader, const YAML::Node& node, const std::string& path, Z& zone) {
      const auto band = reader.numbers(node, path, 2);
      if (!(band[1] > band[0])) reader.fail(node, path, "expected [z_min, z_max] with z_max > z_min (mm)");
      zone.z_min = band[0];
      zone.z_max = band[1];
    };
    z.value = [](const Z& zone) { return nlohmann::json::array({zone.z_min, zone.z_max}); };
    return keys_in_section<Z>(KeySection::kPhysics, {
        std::move(z.must_be_given()),
        number_key("mu", &Z::mu, kFrictionRange, "μ", "its coefficient").must_be_given(),
        node_key("materials", &Z::materials, "list of pairs",
                 "the material pairs it applies to, e.g. `[[aluminum, aluminum], [aluminum, steel]]`")
            .default_is("all"),
        choice_key("contacts", &Z::contacts, {{"lateral", std::string("lateral")}, {"radial", std::string("radial")}},
                   "the interface it applies to (section 5.2 changes the radial contacts)")
            .default_is("both"),
    });
  }();
  return table;
}

ContactSettings parse_contact_settings(const YamlReader& reader, const YAML::Node& node,
                                       const std::map<std::string, Material>& materials, bool strand) {
  static const std::vector<const char*> names = key_names(contact_key_table(), {"friction_pairs", "friction_zones"});
  reader.check_keys(node, "contact", names);
  ContactSettings c;
  c.enabled = true;
  read_setting_keys(reader, node, "contact", contact_key_table(), c);
  // The interface an entry is limited to (paper section 2.2): none, lateral or radial contacts alone.
  const auto interface = [](const std::string& contacts) -> std::optional<ContactInterface> {
    if (contacts.empty()) return std::nullopt;
    return contacts == "radial" ? ContactInterface::kRadial : ContactInterface::kLateral;
  };
  if (const YAML::Node pairs = node["friction_pairs"]) {
    if (!pairs.IsSequence()) reader.fail(pairs, "contact.friction_pairs", "expected a list of {materials: [a, b], mu}");
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      const std::string path = list_item("contact.friction_pairs", i);
      reader.check_keys(pairs[i], path, allowed_keys("contact.friction_pairs[i]"));
      FrictionPairKeys keys;
      read_setting_keys(reader, pairs[i], path, friction_pair_key_table(), keys);
      MaterialPairFriction f;
      std::tie(f.material_a, f.material_b) = material_pair(reader, keys.materials, path + ".materials", materials, "expected two material names");
      f.coefficient = keys.mu;
      f.orthotropy_ratio = keys.orthotropy_ratio;
      if (!f.coefficient && !f.orthotropy_ratio) reader.fail(pairs[i], path, "expected 'mu', 'orthotropy_ratio' or both");
      f.interface = interface(keys.contacts);
      c.pair_friction.push_back(f);
    }
  }
  if (const YAML::Node zones = node["friction_zones"]) {
    if (!zones.IsSequence()) reader.fail(zones, "contact.friction_zones", "expected a list of {z: [z_min, z_max], mu}");
    for (std::size_t i = 0; i < zones.size(); ++i) {
      const std::string path = list_item("contact.friction_zones", i);
      reader.check_keys(zones[i], path, allowed_keys("contact.friction_zones[i]"));
      FrictionZoneKeys keys;
      read_setting_keys(reader, zones[i], path, friction_zone_key_table(), keys);
      FrictionZone zone{keys.z_min, keys.z_max, keys.mu, {}, interface(keys.contacts)};
      if (zones[i]["materials"]) {
        const YAML::Node pairs = keys.materials;
        const std::string expected = "expected a list of material pairs, e.g. [[aluminum, aluminum], [aluminum, steel]]";
        if (!pairs.IsSequence() || pairs.size() == 0) reader.fail(pairs, path + ".materials", expected);
        for (std::size_t k = 0; k < pairs.size(); ++k)
          zone.material_pairs.push_back(material_pair(reader, pairs[k], list_item(path + ".materials", k), materials, expected));
      }
      c.zone_friction.push_back(zone);
    }
  }
  if (node["axis"]) {
    if (strand) reader.fail(node["axis"], "contact.axis", "strands use their own axis (z); 'axis' is for beam cases");
    if (!(c.strand_axis.norm() > 0)) reader.fail(node["axis"], "contact.axis", "expected a nonzero direction");
  }
  return c;
}

nlohmann::json resolved_contact_settings(const ContactSettings& k) {
  nlohmann::json resolved = resolved_setting_keys(contact_key_table(), k);
  resolved["normal_onset_per_diameter"] = k.normal_smoothing ? nlohmann::json(nullptr) : nlohmann::json(kNormalOnsetPerDiameter);
  resolved["zones"] = k.zone_friction.size();
  // Each material pair with the coefficient and the mu2/mu1 it runs with (outside zones) on the interfaces it
  // names; mu and orthotropy_ratio also at the top where they are the same on all of them.
  nlohmann::json pairs = nlohmann::json::array();
  for (const MaterialPairFriction& p : k.pair_friction) {
    nlohmann::json entry = {{"materials", {p.material_a, p.material_b}},
                            {"contacts", p.interface ? to_string(*p.interface) : "all"}};
    std::vector<std::pair<double, double>> values;
    for (ContactInterface on : {ContactInterface::kLateral, ContactInterface::kRadial}) {
      if (p.interface && *p.interface != on) continue;
      const double mu = k.friction_outside_zones(p.material_a, p.material_b, on);
      const double ratio = k.orthotropy_at(p.material_a, p.material_b, on);
      entry[to_string(on)] = {{"mu", mu}, {"orthotropy_ratio", ratio}};
      values.emplace_back(mu, ratio);
    }
    if (values.size() == 1 || values[0] == values[1]) {
      entry["mu"] = values[0].first;
      entry["orthotropy_ratio"] = values[0].second;
    }
    pairs.push_back(entry);
  }
  resolved["pairs"] = pairs;
  return resolved;
}

}  // namespace strandfem
