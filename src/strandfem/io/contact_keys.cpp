#include "strandfem/io/contact_keys.hpp"

#include "strandfem/io/case_keys.hpp"

#include <tuple>
#include <utility>
#include <vector>

namespace strandfem {

namespace {

std::string material_name(const YamlReader& reader, const YAML::Node& node, const std::string& path,
                          const std::map<std::string, Material>& materials) {
  const std::string name = reader.text(node, path);
  if (!materials.count(name)) reader.fail(node, path, "unknown material '" + name + "' (define it under 'materials')");
  return name;
}
// Two material names [a, b] at `node`.
std::pair<std::string, std::string> material_pair(const YamlReader& reader, const YAML::Node& node, const std::string& path,
                                                  const std::map<std::string, Material>& materials, const std::string& expected) {
  if (!node.IsSequence() || node.size() != 2) reader.fail(node, path, expected);
  return {material_name(reader, node[0], path + "[0]", materials), material_name(reader, node[1], path + "[1]", materials)};
}
}  // namespace

ContactSettings parse_contact_settings(const YamlReader& reader, const YAML::Node& node,
                                       const std::map<std::string, Material>& materials, bool strand) {
  reader.check_keys(node, "contact", allowed_keys("contact"));
  ContactSettings c;
  c.enabled = node["enabled"] ? reader.boolean(node["enabled"], "contact.enabled") : true;
  auto friction = [&](const YAML::Node& n, const std::string& path) {
    const double mu = reader.non_negative(n, path, "-");
    if (mu >= 10) reader.fail(n, path, "expected a friction coefficient below 10");
    return mu;
  };
  // The interface an entry is limited to (paper section 2.2): none, lateral or radial contacts alone.
  auto interface = [&](const YAML::Node& entry, const std::string& path) -> std::optional<ContactInterface> {
    const YAML::Node n = entry["contacts"];
    if (!n) return std::nullopt;
    return reader.choice(n, path + ".contacts", {"lateral", "radial"}) == "radial" ? ContactInterface::kRadial
                                                                                 : ContactInterface::kLateral;
  };
  if (node["friction"]) c.friction = friction(node["friction"], "contact.friction");
  if (const YAML::Node pairs = node["friction_pairs"]) {
    if (!pairs.IsSequence()) reader.fail(pairs, "contact.friction_pairs", "expected a list of {materials: [a, b], mu}");
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      const std::string path = list_item("contact.friction_pairs", i);
      reader.check_keys(pairs[i], path, allowed_keys("contact.friction_pairs[i]"));
      MaterialPairFriction f;
      std::tie(f.material_a, f.material_b) =
          material_pair(reader, reader.require(pairs[i], path, "materials"), path + ".materials", materials, "expected two material names");
      if (pairs[i]["mu"]) f.coefficient = friction(pairs[i]["mu"], path + ".mu");
      if (pairs[i]["orthotropy_ratio"]) f.orthotropy_ratio = reader.positive(pairs[i]["orthotropy_ratio"], path + ".orthotropy_ratio", "-");
      if (!f.coefficient && !f.orthotropy_ratio) reader.fail(pairs[i], path, "expected 'mu', 'orthotropy_ratio' or both");
      f.interface = interface(pairs[i], path);
      c.pair_friction.push_back(f);
    }
  }
  if (const YAML::Node zones = node["friction_zones"]) {
    if (!zones.IsSequence()) reader.fail(zones, "contact.friction_zones", "expected a list of {z: [z_min, z_max], mu}");
    for (std::size_t i = 0; i < zones.size(); ++i) {
      const std::string path = list_item("contact.friction_zones", i);
      reader.check_keys(zones[i], path, allowed_keys("contact.friction_zones[i]"));
      const auto z = reader.numbers(reader.require(zones[i], path, "z"), path + ".z", 2);
      if (!(z[1] > z[0])) reader.fail(zones[i]["z"], path + ".z", "expected [z_min, z_max] with z_max > z_min (mm)");
      FrictionZone zone{z[0], z[1], friction(reader.require(zones[i], path, "mu"), path + ".mu"), {}, interface(zones[i], path)};
      if (const YAML::Node pairs = zones[i]["materials"]) {
        const std::string expected = "expected a list of material pairs, e.g. [[aluminum, aluminum], [aluminum, steel]]";
        if (!pairs.IsSequence() || pairs.size() == 0) reader.fail(pairs, path + ".materials", expected);
        for (std::size_t k = 0; k < pairs.size(); ++k)
          zone.material_pairs.push_back(material_pair(reader, pairs[k], list_item(path + ".materials", k), materials, expected));
      }
      c.zone_friction.push_back(zone);
    }
  }
  auto positive = [&](const char* key, double& value, const char* unit) {
    if (node[key]) value = reader.positive(node[key], std::string("contact.") + key, unit);
  };
  positive("orthotropy_ratio", c.orthotropy_ratio, "-");
  positive("normal_factor", c.normal_factor, "-");
  positive("tangential_factor", c.tangential_factor, "-");
  positive("normal_multiplier", c.normal_multiplier, "-");
  positive("tangential_multiplier", c.tangential_multiplier, "-");
  positive("search_margin", c.search_margin, "mm");
  positive("elastic_slip", c.elastic_slip, "fraction of the contact element length");
  if (node["stick_augmentations"])
    c.stick_augmentations = reader.integer(node["stick_augmentations"], "contact.stick_augmentations", 0, 100);
  if (node["stick_tolerance"]) {
    c.stick_tolerance = reader.positive(node["stick_tolerance"], "contact.stick_tolerance", "fraction of the allowed elastic slip");
    if (c.stick_tolerance >= 1) reader.fail(node["stick_tolerance"], "contact.stick_tolerance", "expected a fraction of the allowed elastic slip below 1");
  }
  if (node["normal_smoothing"])
    c.normal_smoothing = reader.non_negative(node["normal_smoothing"], "contact.normal_smoothing", "mm");
  if (const YAML::Node n = node["stabilization"]) {
    c.stabilization = reader.non_negative(n, "contact.stabilization", "fraction of the normal penalty");
    if (c.stabilization >= 1)
      reader.fail(n, "contact.stabilization", "expected a fraction of the normal penalty below 1 (e.g. 1e-6)");
  }
  if (node["tangential_penalty"])
    c.tangential_penalty = reader.choice(node["tangential_penalty"], "contact.tangential_penalty", {"paper", "elastic_slip"}) == "paper"
                               ? TangentialPenalty::kPaper : TangentialPenalty::kElasticSlip;
  if (node["line_contact_angle"]) {
    c.line_contact_angle = reader.positive(node["line_contact_angle"], "contact.line_contact_angle", "degrees");
    if (c.line_contact_angle >= 90) reader.fail(node["line_contact_angle"], "contact.line_contact_angle", "expected an angle in (0, 90) degrees");
  }
  if (node["line_points"]) {
    c.line_points = reader.integer(node["line_points"], "contact.line_points", 1, 10);  // Gauss points per element
  }
  if (node["touch_tolerance"]) {
    c.touch_tolerance = reader.non_negative(node["touch_tolerance"], "contact.touch_tolerance", "fraction of r_a + r_b");
    if (c.touch_tolerance >= 0.5) reader.fail(node["touch_tolerance"], "contact.touch_tolerance", "expected a fraction of the radius sum below 0.5");
  }
  if (node["pattern_margin"]) {
    c.pattern_margin = reader.non_negative(node["pattern_margin"], "contact.pattern_margin", "fraction of r_a + r_b");
    if (c.pattern_margin >= 1) reader.fail(node["pattern_margin"], "contact.pattern_margin", "expected a fraction of the radius sum below 1");
  }
  if (node["friction_direction"])
    c.friction_direction = reader.choice(node["friction_direction"], "contact.friction_direction", {"strand_axis", "slave_wire"}) == "slave_wire"
                               ? FrictionDirection::kSlaveWire : FrictionDirection::kStrandAxis;
  if (node["initial_overlap"])
    c.initial_overlap = reader.choice(node["initial_overlap"], "contact.initial_overlap", {"offset", "keep"}) == "offset"
                            ? InitialOverlap::kOffset : InitialOverlap::kKeep;
  if (node["axis"]) {
    if (strand) reader.fail(node["axis"], "contact.axis", "strands use their own axis (z); 'axis' is for beam cases");
    const auto a = reader.numbers(node["axis"], "contact.axis", 3);
    c.strand_axis = Vec3(a[0], a[1], a[2]);
    if (!(c.strand_axis.norm() > 0)) reader.fail(node["axis"], "contact.axis", "expected a nonzero direction");
  }
  return c;
}

nlohmann::json resolved_contact_settings(const ContactSettings& k) {
  nlohmann::json resolved = {{"enabled", k.enabled}, {"friction", k.friction}, {"orthotropy_ratio", k.orthotropy_ratio},
                             {"friction_direction", to_string(k.friction_direction)},
                             {"normal_factor", k.normal_factor}, {"tangential_factor", k.tangential_factor},
                             {"normal_multiplier", k.normal_multiplier}, {"tangential_multiplier", k.tangential_multiplier},
                             {"tangential_penalty", k.tangential_penalty == TangentialPenalty::kPaper ? "paper" : "elastic_slip"},
                             {"elastic_slip", k.elastic_slip}, {"stick_augmentations", k.stick_augmentations}, {"stick_tolerance", k.stick_tolerance},
                             {"search_margin", k.search_margin}, {"pattern_margin", k.pattern_margin}, {"line_contact_angle", k.line_contact_angle},
                             {"line_points", k.line_points},
                             {"initial_overlap", k.initial_overlap == InitialOverlap::kOffset ? "offset" : "keep"}, {"touch_tolerance", k.touch_tolerance},
                             {"normal_smoothing", k.normal_smoothing ? nlohmann::json(*k.normal_smoothing) : nlohmann::json(nullptr)},
                             {"normal_onset_per_diameter", k.normal_smoothing ? nlohmann::json(nullptr) : nlohmann::json(kNormalOnsetPerDiameter)}, {"stabilization", k.stabilization},
                             {"zones", k.zone_friction.size()}};
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
