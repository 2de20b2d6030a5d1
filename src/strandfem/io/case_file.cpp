#include "strandfem/io/case_file.hpp"

#include "strandfem/io/beam_keys.hpp"
#include "strandfem/io/case_keys.hpp"
#include "strandfem/io/conductor_catalogue.hpp"
#include "strandfem/io/contact_keys.hpp"
#include "strandfem/io/resolved_configuration.hpp"
#include "strandfem/io/load_keys.hpp"
#include "strandfem/io/model_keys.hpp"
#include "strandfem/io/output_keys.hpp"
#include "strandfem/io/solver_keys.hpp"
#include "strandfem/io/yaml_document.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <sstream>
#include <unordered_set>

#include "strandfem/analysis/strand_builder.hpp"
#include "strandfem/geometry/beam_line.hpp"

namespace strandfem {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

class CaseParser {
 public:
  CaseParser(const std::string& path, const std::string& catalogue, CaseDefinition& out) : reader_(path), catalogue_(catalogue), out_(out) {}

  void parse(const YAML::Node& root) {
    reader_.check_keys(root, "", allowed_keys(""));
    CaseHeading heading;
    read_setting_keys(reader_, root, "", case_heading_key_table(), heading);
    out_.title = heading.title;
    // A catalogue conductor brings its own materials; a case's `materials` may still replace them by name.
    if (root["materials"] || !(root["strand"].IsMap() && root["strand"]["conductor"])) parse_materials(reader_.require(root, "", "materials"));
    const bool has_strand = root["strand"].IsDefined(), has_beams = root["beams"].IsDefined();
    if (has_strand == has_beams) reader_.fail(root, "strand/beams", "expected exactly one of 'strand' or 'beams'");
    if (has_strand) parse_strand(root["strand"], root["mesh"]);
    else {
      if (root["mesh"]) reader_.fail(root["mesh"], "mesh", "only strands take 'mesh'; beams set 'elements' per line");
      parse_beams(root["beams"]);
      if (root["hubs"]) parse_hubs(root["hubs"]);
    }
    if (has_strand && root["hubs"]) reader_.fail(root["hubs"], "hubs", "strands have their rigid end planes built in");
    if (root["supports"]) loads_.parse_supports(root["supports"]);
    loads_.parse_steps(reader_.require(root, "", "steps"), out_.strand ? &strand_ : nullptr);
    if (root["solver"]) parse_solver_options(reader_, root["solver"], out_.model.options);
    if (root["contact"])
      out_.model.contact_settings = parse_contact_settings(reader_, root["contact"], materials_, out_.strand.has_value());
    if (root["output"]) parse_output(root["output"]);
    if (!out_.output.contacts_every_set) out_.output.contacts_every = out_.output.every;
    try {
      out_.model.options.validate();
    } catch (const std::invalid_argument& e) {
      reader_.fail(root["solver"], "solver", e.what());
    }
  }

 private:
  void parse_materials(const YAML::Node& node) {
    if (!node.IsMap() || node.size() == 0) reader_.fail(node, "materials", "expected a mapping name -> {E, nu, density}");
    for (const auto& entry : node) {
      const std::string name = entry.first.as<std::string>(), path = "materials." + name;
      reader_.check_keys(entry.second, path, allowed_keys("materials.<name>"));
      Material m;
      m.name = name;
      read_setting_keys(reader_, entry.second, path, material_key_table(), m);
      if (const YAML::Node p = entry.second["plasticity"]) {
        const std::string pp = path + ".plasticity";
        if (!p.IsMap()) reader_.fail(p, pp, "expected {yield_stress, tangent_modulus} in MPa");
        reader_.check_keys(p, pp, allowed_keys("materials.<name>.plasticity"));
        BilinearHardening law;
        read_setting_keys(reader_, p, pp, plasticity_key_table(), law);
        if (law.tangent_modulus >= m.youngs_modulus)
          reader_.fail(p["tangent_modulus"], pp + ".tangent_modulus", "expected a hardening modulus below E (" + std::to_string(m.youngs_modulus) + " MPa)");
        m.plasticity = law;
      }
      materials_[name] = m;
    }
  }

  const Material& material(const YAML::Node& node, const std::string& path) {
    const std::string name = reader_.text(node, path);
    const auto it = materials_.find(name);
    if (it == materials_.end()) reader_.fail(node, path, "unknown material '" + name + "' (define it under 'materials')");
    return it->second;
  }

  // Elements from `first_element` on must be long enough for their geometry to survive round-off.
  void check_resolution(std::size_t first_element, const YAML::Node& key_node, const std::string& key_path) {
    const ElementResolution r = element_resolution(out_.model.mesh, first_element);
    if (r.resolvable()) return;
    std::ostringstream msg;
    msg << "elements " << r.shortest << " mm long: below " << kMinElementLength << " mm or " << kMinElementLengthRatio
        << " of the coordinates' magnitude (" << r.coordinate_scale << " mm), round-off would swamp their geometry";
    reader_.fail(key_node, key_path, msg.str());
  }

  void parse_strand(const YAML::Node& node, const YAML::Node& mesh) {
    reader_.check_keys(node, "strand", allowed_keys("strand"));
    StrandSettings strand;
    read_setting_keys(reader_, node, "strand", strand_key_table(), strand);
    StrandSpec spec;
    const YAML::Node layers = node["layers"];
    if (!strand.conductor.empty()) {
      if (layers) reader_.fail(layers, "strand.layers", "give strand.conductor or strand.layers, not both");
      spec = conductor_spec(node, strand);
    } else {
      for (const char* key : {"lay_ratios", "lay_angles"})
        if (node[key]) reader_.fail(node[key], std::string("strand.") + key, "only with strand.conductor (the layers set their own lay_angle)");
      spec = layer_spec(reader_.require(node, "strand", "layers"));
    }
    spec.length = strand.length;
    // Nominal overlaps: warn for small ones (real strands have them), refuse large ones.
    for (std::size_t i = 1; i < spec.layers.size(); ++i) {
      const double clearance = lateral_clearance(spec, static_cast<int>(i));
      if (std::isnan(clearance) || clearance >= 0) continue;
      const double radius = 0.5 * spec.layers[i].wire_diameter;
      std::ostringstream msg;
      msg << "layer " << i << ": neighbouring wires overlap by " << -clearance << " mm at the nominal radius of eq. 2.1";
      const YAML::Node where = layers ? layers[i] : node["conductor"];
      const std::string path = layers ? list_item("strand.layers", i) : "strand.conductor";
      if (-clearance > 0.25 * radius)
        reader_.fail(where, path, msg.str() + ", more than 25 % of the wire radius: check wires, diameter and lay_angle" +
                                      (spec.layers[i].wire_start_angles.empty() ? "" : " (and start_angles: the closest two wires count)"));
      out_.warnings.push_back(msg.str());
    }
    build_strand(node, mesh, strand, spec);
  }

  // The strand of a catalogue conductor, its materials added to the case's (which replace them by name).
  StrandSpec conductor_spec(const YAML::Node& node, const StrandSettings& strand) {
    if (!catalogue_.empty() && user_catalogue_.empty()) {
      try {
        user_catalogue_ = read_conductor_catalogue_file(catalogue_);
      } catch (const CaseError& e) {
        reader_.fail(node["conductor"], "strand.conductor", std::string("in the catalogue given with --catalogue: ") + e.what());
      }
    }
    const CatalogueConductor* c = find_conductor(user_catalogue_, strand.conductor);
    if (!c) reader_.fail(node["conductor"], "strand.conductor", "unknown conductor '" + strand.conductor + "' (`strandfem conductors` lists the catalogue)");
    if (node["lay_ratios"] && node["lay_angles"]) reader_.fail(node, "strand", "give lay_ratios or lay_angles, not both");
    ConductorStrand s;
    try {
      s = conductor_strand(*c, strand.lay_ratios, strand.lay_angles);
    } catch (const std::invalid_argument& e) {
      const char* key = node["lay_ratios"] ? "lay_ratios" : node["lay_angles"] ? "lay_angles" : "conductor";
      reader_.fail(node[key], std::string("strand.") + key, e.what());
    }
    for (const auto& [name, m] : s.strand.materials) materials_.emplace(name, m);
    s.strand.materials = materials_;
    for (const std::string& w : s.warnings) out_.warnings.push_back(w);
    out_.conductor = c->name;
    out_.conductor_origin = c->origin;
    return s.strand;
  }

  // The strand of the case's own `layers`.
  StrandSpec layer_spec(const YAML::Node& layers) {
    StrandSpec spec;
    spec.materials = materials_;
    if (!layers.IsSequence() || layers.size() == 0) reader_.fail(layers, "strand.layers", "expected a list of layers, core first");
    const std::vector<int> default_directions = default_lay_directions(static_cast<int>(layers.size()));
    static const std::vector<SettingKey<LayerSpec>> core_keys = [] {
      std::vector<SettingKey<LayerSpec>> keys;
      for (const auto& key : layer_key_table())
        if (key.name != "lay_angle" && key.name != "lay_direction") keys.push_back(key);
      return keys;
    }();
    for (std::size_t i = 0; i < layers.size(); ++i) {
      const YAML::Node l = layers[i];
      const std::string path = list_item("strand.layers", i);
      reader_.check_keys(l, path, allowed_keys("strand.layers[i]"));
      if (i == 0 && (l["lay_angle"] || l["lay_direction"])) reader_.fail(l, path, "the core is straight: no lay_angle or lay_direction");
      if (l["start_angle"] && l["start_angles"]) reader_.fail(l, path, "give start_angle or start_angles, not both");
      LayerSpec layer;
      layer.lay_direction = default_directions[i];
      read_setting_keys(reader_, l, path, i == 0 ? core_keys : layer_key_table(), layer);
      material(l["material"], path + ".material");
      if (i == 0 && layer.wires != 1) reader_.fail(l["wires"], path + ".wires", "the core (first layer) must have exactly 1 wire");
      spec.layers.push_back(layer);
    }
    return spec;
  }

  // The mesh, end planes and clamps of the strand `spec`.
  void build_strand(const YAML::Node& node, const YAML::Node& mesh, const StrandSettings& strand, const StrandSpec& spec) {
    out_.end_type = strand.ends;
    if (mesh) {
      reader_.check_keys(mesh, "mesh", allowed_keys("mesh"));
      if (mesh["element_length"] && mesh["elements_per_wire"])
        reader_.fail(mesh, "mesh", "give either element_length or elements_per_wire, not both");
      read_setting_keys(reader_, mesh, "mesh", mesh_key_table(), out_.mesh_spec);
    }
    // The mesh's size and element length, checked before anything is allocated, against the key that set them.
    const char* mesh_key = mesh && mesh["element_length"] ? "element_length" : mesh && mesh["elements_per_wire"] ? "elements_per_wire" : nullptr;
    const YAML::Node mesh_node = mesh_key ? mesh[mesh_key] : node["length"];
    const std::string mesh_path = mesh_key ? std::string("mesh.") + mesh_key : "strand.length";
    const std::int64_t node_count = strand_node_count(spec, out_.mesh_spec);
    if (node_count > kMaxModelNodes)
      reader_.fail(mesh_node, mesh_path, "the strand mesh would have " + std::to_string(node_count) + " nodes (or more), beyond the model-size limit of " +
                                             std::to_string(kMaxModelNodes) + " nodes (" + std::to_string(6 * kMaxModelNodes) + " DOFs)" +
                                             (mesh_key ? "" : " with the default 10 mm elements: set mesh.element_length"));
    strand_ = build_strand_model(spec, out_.mesh_spec, out_.end_type == "free");
    out_.model.mesh = std::move(strand_.mesh);
    out_.model.ties = std::move(strand_.ties);
    if (node["clamp_length"]) {
      const double c = strand.clamp_length;
      if (!(c < 0.5 * spec.length)) reader_.fail(node["clamp_length"], "strand.clamp_length", "expected less than half the strand length");
      if (c > 0) {
        add_rigid_block(out_.model.mesh, strand_.start_node, -1.0, c, out_.model.ties);
        add_rigid_block(out_.model.mesh, strand_.end_node, spec.length - c, spec.length + 1.0, out_.model.ties);
      }
      out_.clamp_length = c;
    }
    out_.model.supports = std::move(strand_.supports);
    check_resolution(0, mesh_node, mesh_path);
    out_.start_node = strand_.start_node;
    out_.end_node = strand_.end_node;
    out_.axial_length = spec.length;
    out_.monitor_node = strand_.monitor_node;
    for (const Support& s : out_.model.supports) loads_.hold(s, s.node == out_.start_node ? "the clamp at z = 0" : "strand.ends");
    out_.strand = spec;
  }

  void parse_beams(const YAML::Node& node) {
    if (!node.IsSequence() || node.size() == 0) reader_.fail(node, "beams", "expected a list of beam lines");
    for (std::size_t i = 0; i < node.size(); ++i) {
      const YAML::Node b = node[i];
      const std::string path = list_item("beams", i);
      reader_.check_keys(b, path, allowed_keys("beams[i]"));
      BeamKeys keys;
      read_setting_keys(reader_, b, path, beam_key_table(), keys);
      BeamLineSpec line;
      line.name = keys.name;
      for (const MeshWire& w : out_.model.mesh.wires)
        if (w.name == line.name) reader_.fail(b["name"], path + ".name", "duplicate beam name '" + line.name + "'");
      const Material& mat = material(b["material"], path + ".material");
      const YAML::Node s = reader_.require(b, path, "section");
      const std::string sp = path + ".section";
      reader_.check_keys(s, sp, allowed_keys("beams[i].section"));
      SectionKeys section;
      read_setting_keys(reader_, s, sp, section_key_table(), section);
      SectionGeometry geometry;
      if (section.diameter) {
        if (s.size() != 1) reader_.fail(s, sp, "a circular section takes only 'diameter'");
        geometry = SectionGeometry::circle(*section.diameter, mat.poisson_ratio);
      } else {
        for (const char* key : {"area", "inertia_2", "inertia_3", "torsion_constant", "shear_factor"}) reader_.require(s, sp, key);
        geometry.area = section.area;
        geometry.inertia_2 = section.inertia_2;
        geometry.inertia_3 = section.inertia_3;
        geometry.torsion_constant = section.torsion_constant;
        geometry.shear_factor = section.shear_factor;
      }
      line.elements = keys.elements;
      parse_shape(reader_.require(b, path, "shape"), path + ".shape", line);
      Mesh& m = out_.model.mesh;
      if (mat.plasticity && !s["diameter"])
        reader_.fail(s, path + ".section", "material '" + mat.name + "' has plasticity: give the wire 'diameter' (fibre section)");
      if (static_cast<std::int64_t>(m.nodes.size()) + 2 * static_cast<std::int64_t>(line.elements) + 1 > kMaxModelNodes)
        reader_.fail(b["elements"], path + ".elements", "the beam lines would have more than the model-size limit of " +
                                                            std::to_string(kMaxModelNodes) + " nodes (" + std::to_string(6 * kMaxModelNodes) + " DOFs)");
      m.sections.push_back(make_section(geometry, mat));
      const std::size_t first_element = m.elements.size();
      add_beam_line(m, line, static_cast<int>(m.sections.size()) - 1);
      check_resolution(first_element, b["elements"], path + ".elements");
    }
    const MeshWire& first = out_.model.mesh.wires[0];
    out_.start_node = first.nodes.front();
    out_.monitor_node = first.nodes.back();
  }

  // Hubs: standalone nodes (rigid plates) to which beam nodes are tied by exact rigid-body kinematics.
  void parse_hubs(const YAML::Node& node) {
    if (!node.IsSequence()) reader_.fail(node, "hubs", "expected a list of {name, position, links}");
    Mesh& m = out_.model.mesh;
    for (std::size_t i = 0; i < node.size(); ++i) {
      const std::string path = list_item("hubs", i);
      reader_.check_keys(node[i], path, allowed_keys("hubs[i]"));
      HubKeys keys;
      read_setting_keys(reader_, node[i], path, hub_key_table(), keys);
      const std::string& name = keys.name;
      if (hubs_.count(name)) reader_.fail(node[i]["name"], path + ".name", "duplicate hub name '" + name + "'");
      MeshNode hub;
      hub.reference.position = keys.position;
      const int hub_node = static_cast<int>(m.nodes.size());
      m.nodes.push_back(hub);
      hubs_[name] = hub_node;
      const YAML::Node links = keys.links;
      if (!links.IsSequence() || links.size() == 0) reader_.fail(links, path + ".links", "expected a list of beam node selectors");
      for (std::size_t k = 0; k < links.size(); ++k) {
        // {beam: name} alone links every node of the line (a rigid line); otherwise one node selector.
        std::vector<int> slaves;
        if (links[k].IsMap() && links[k].size() == 1 && links[k]["beam"]) {
          const std::string beam = reader_.text(links[k]["beam"], list_item(path + ".links", k) + ".beam");
          for (const MeshWire& w : m.wires)
            if (w.name == beam) slaves = w.nodes;
          if (slaves.empty()) reader_.fail(links[k]["beam"], list_item(path + ".links", k) + ".beam", "no beam named '" + beam + "'");
        } else {
          slaves.push_back(node_at(links[k], list_item(path + ".links", k)));
        }
        for (const int slave : slaves) {
          if (!hub_linked_.insert(slave).second) reader_.fail(links[k], list_item(path + ".links", k), "node already linked to a hub");
          out_.model.ties.push_back(make_rigid_tie(slave, hub_node, m.nodes[slave].reference, m.nodes[hub_node].reference));
        }
      }
    }
  }

  void parse_shape(const YAML::Node& s, const std::string& path, BeamLineSpec& line) {
    const std::string type = reader_.choice(reader_.require(s, path, "type"), path + ".type", {"straight", "arc", "helix"});
    for (const ShapeKind& kind : shape_kinds()) {
      if (type != kind.type) continue;
      reader_.check_keys(s, path, allowed_keys(std::string("beams[i].shape (") + kind.type + ")"));
      for (const char* key : kind.required) reader_.require(s, path, key);
    }
    read_setting_keys(reader_, s, path, shape_key_table(), line);
    if (line.shape == BeamLineSpec::kStraight && (line.end - line.start).norm() <= 0) reader_.fail(s, path, "start and end coincide");
    if (line.shape == BeamLineSpec::kArc && line.start_angle == line.end_angle) reader_.fail(s, path, "start_angle equals end_angle");
  }

  // Node selectors: {core: start|end}, {core_z: z} for strands; {beam: name, point: start|middle|end} or
  // {beam: name, node: k} for beam lines.
  int node_at(const YAML::Node& n, const std::string& path) {
    const Mesh& m = out_.model.mesh;
    SelectorKeys selector;
    if (out_.strand) {
      reader_.check_keys(n, path, allowed_keys("selector (strands)"));
      if (n["core"] && n["core_z"]) reader_.fail(n, path, "give core or core_z, not both");
      read_setting_keys(reader_, n, path, strand_selector_key_table(), selector);
      const MeshWire& core = m.wires[0];
      if (!selector.core.empty()) return selector.core == "start" ? core.nodes.front() : core.nodes.back();
      reader_.require(n, path, "core_z");
      const double z = *selector.core_z;
      if (z < 0 || z > out_.strand->length) reader_.fail(n["core_z"], path + ".core_z", "expected a position within the strand length");
      int best = core.nodes.front();
      for (const int node : core.nodes)
        if (std::abs(m.nodes[node].reference.position.z() - z) < std::abs(m.nodes[best].reference.position.z() - z)) best = node;
      return best;
    }
    reader_.check_keys(n, path, allowed_keys("selector (beams)"));
    read_setting_keys(reader_, n, path, beam_selector_key_table(), selector);
    if (!selector.hub.empty()) {
      if (!hubs_.count(selector.hub)) reader_.fail(n["hub"], path + ".hub", "no hub named '" + selector.hub + "'");
      if (n.size() != 1) reader_.fail(n, path, "a hub selector takes only 'hub'");
      return hubs_.at(selector.hub);
    }
    reader_.require(n, path, "beam");
    if (n["node"] && n["point"]) reader_.fail(n, path, "give point or node, not both");
    for (const MeshWire& w : m.wires) {
      if (w.name != selector.beam) continue;
      if (selector.node) {
        if (*selector.node >= static_cast<int>(w.nodes.size()))
          reader_.fail(n["node"], path + ".node", "beyond the line's last node " + std::to_string(w.nodes.size() - 1));
        return w.nodes[*selector.node];
      }
      reader_.require(n, path, "point");
      return selector.point == "start" ? w.nodes.front() : selector.point == "end" ? w.nodes.back() : w.nodes[w.nodes.size() / 2];
    }
    reader_.fail(n["beam"], path + ".beam", "no beam named '" + selector.beam + "'");
  }

  void parse_output(const YAML::Node& node) {
    reader_.check_keys(node, "output", allowed_keys("output"));
    read_setting_keys(reader_, node, "output", output_key_table(), out_.output);
    if (const YAML::Node offset = node["clamp_edge_offset"]) {
      if (!out_.strand) reader_.fail(offset, "output.clamp_edge_offset", "only strands have clamps");
      if (out_.output.clamp_edge_offset >= 0.5 * out_.axial_length)
        reader_.fail(offset, "output.clamp_edge_offset",
                     fmt::format("expected a distance below half the strand length ({} mm)", 0.5 * out_.axial_length));
    }
    MonitorKey monitor;
    read_setting_keys(reader_, node, "output", monitor_key_table(), monitor);
    if (node["monitor"]) out_.monitor_node = node_at(monitor.monitor, "output.monitor");
  }

  YamlReader reader_;
  std::string catalogue_;  // --catalogue: searched before the shipped catalogue
  std::vector<CatalogueConductor> user_catalogue_;
  CaseDefinition& out_;
  StrandModelParts strand_;  // strands: the built parts' node numbers (the mesh, ties and supports move to out_.model)
  std::map<std::string, Material> materials_;
  std::map<std::string, int> hubs_;
  std::unordered_set<int> hub_linked_;  // nodes already tied to a hub (checked per link in O(1))
  LoadKeys loads_{reader_, out_, [this](const YAML::Node& n, const std::string& path) { return node_at(n, path); }};
};

}  // namespace

bool has_cyclic_strand_step(const CaseDefinition& c) {
  if (!c.strand) return false;
  for (const LoadStep& s : c.model.steps)
    if (s.cycles > 0) return true;
  return false;
}

namespace {
CaseDefinition parse_case(const YAML::Node& root, const std::string& path, const std::string& catalogue) {
  if (!root.IsMap()) throw CaseError(path + ": expected a YAML mapping at the top level");
  CaseDefinition c;
  c.path = path;
  try {
    CaseParser(path, catalogue, c).parse(root);
  } catch (const YAML::Exception& e) {
    // A node used as what it is not (a scalar indexed as a mapping...) that no check above caught: still bad input.
    std::string where = path;
    if (e.mark.line >= 0) where += ":" + std::to_string(e.mark.line + 1) + ":" + std::to_string(e.mark.column + 1);
    throw CaseError(where + ": " + e.msg);
  } catch (const ModelSizeError& e) {
    throw CaseError(path + ": " + e.what());
  }
  // Elements (with their section-point state: fibre histories of elastoplastic wires) are built by the analysis
  // that uses them, not here: `info` and the checks below need the mesh only, and an elastoplastic strand at
  // the size limit would otherwise take gigabytes just to be read.
  try {
    build_dof_map(c.model);  // supports or loads on tied nodes, doubly tied nodes: refused before any run starts
  } catch (const std::invalid_argument& e) {
    throw CaseError(path + ": " + e.what());
  }
  std::stringstream yaml_text;
  yaml_text << root;
  c.resolved["case_file"] = path;
  c.resolved["case"] = yaml_text.str();
  c.resolved["solver"] = resolved_solver_options(c.model.options);
  c.resolved["contact"] = resolved_contact_settings(c.model.contact_settings);
  add_resolved_model(c, c.resolved);
  return c;
}
}  // namespace

CaseDefinition load_case(const std::string& path, const std::string& catalogue) {
  return parse_case(load_yaml_document(path), path, catalogue);
}

CaseDefinition load_case_text(const std::string& text, const std::string& name, const std::string& catalogue) {
  return parse_case(parse_yaml_document(text, name), name, catalogue);
}

}  // namespace strandfem
