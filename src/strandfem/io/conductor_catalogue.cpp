#include "strandfem/io/conductor_catalogue.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "strandfem/io/yaml_reader.hpp"
#include "strandfem/post/analytic.hpp"

namespace strandfem {

extern const char* const kShippedConductorCatalogue;  // data/conductors/conductors.csv, generated into the build

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
const std::vector<std::string> kColumns = {"conductor", "layer", "wires", "diameter_mm", "material", "kind", "E_MPa", "nu", "density_t_m3", "lay_angle_deg"};

std::string name_key(const std::string& name) {
  std::string key;
  for (char ch : name)
    if (ch != ' ' && ch != '-' && ch != '_') key += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return key;
}

std::vector<std::string> split_row(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) {
    const auto first = cell.find_first_not_of(" \t\r"), last = cell.find_last_not_of(" \t\r");
    cells.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
  }
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

class CatalogueReader {
 public:
  explicit CatalogueReader(std::string source) : source_(std::move(source)) {}

  std::vector<CatalogueConductor> read(const std::string& text) {
    std::istringstream in(text);
    std::string line;
    bool header_seen = false;
    while (std::getline(in, line)) {
      ++line_;
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (line.find_first_not_of(" \t") == std::string::npos || line[line.find_first_not_of(" \t")] == '#') continue;
      const std::vector<std::string> cells = split_row(line);
      if (!header_seen) {
        if (cells != kColumns) fail(1, "expected the columns " + join(kColumns));
        header_seen = true;
        continue;
      }
      if (cells.size() != kColumns.size()) fail(1, fmt::format("expected {} columns, found {}", kColumns.size(), cells.size()));
      add_row(cells, line);
    }
    if (!header_seen) fail(1, "no header row: expected the columns " + join(kColumns));
    for (const CatalogueConductor& c : conductors_)
      if (c.layers.front().wires != 1) throw CaseError(c.origin + ": " + c.name + ": the core (layer 0) must have exactly 1 wire");
    return std::move(conductors_);
  }

 private:
  static std::string join(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& n : names) text += (text.empty() ? "" : ",") + n;
    return text;
  }
  [[noreturn]] void fail(std::size_t column, const std::string& what) const {
    throw CaseError(fmt::format("{}:{}:{}: {}", source_, line_, column, what));
  }
  std::size_t column_of(const std::string& line, std::size_t cell) const {
    std::size_t pos = 0;
    for (std::size_t i = 0; i < cell; ++i) pos = line.find(',', pos) + 1;
    return pos + 1;
  }
  double number(const std::vector<std::string>& cells, const std::string& line, std::size_t cell, bool positive) const {
    try {
      std::size_t used = 0;
      const double v = std::stod(cells[cell], &used);
      if (used == cells[cell].size() && std::isfinite(v) && (!positive || v > 0)) return v;
    } catch (const std::exception&) {
    }
    fail(column_of(line, cell), fmt::format("{}: expected {}, got '{}'", kColumns[cell], positive ? "a number > 0" : "a number", cells[cell]));
  }

  void add_row(const std::vector<std::string>& cells, const std::string& line) {
    const std::string& name = cells[0];
    if (name.empty()) fail(1, "conductor: expected a name");
    const double layer = number(cells, line, 1, false), wires = number(cells, line, 2, true);
    if (layer != std::floor(layer) || wires != std::floor(wires)) fail(column_of(line, 1), "layer and wires: expected whole numbers");
    CatalogueConductor* c = conductors_.empty() || name_key(conductors_.back().name) != name_key(name) ? nullptr : &conductors_.back();
    if (!c) {
      for (const CatalogueConductor& other : conductors_)
        if (name_key(other.name) == name_key(name)) fail(1, "conductor '" + name + "': its rows must follow each other (also " + other.origin + ")");
      conductors_.push_back({name, fmt::format("{}:{}", source_, line_), {}, {}});
      c = &conductors_.back();
    }
    if (static_cast<std::size_t>(layer) != c->layers.size())
      fail(column_of(line, 1), fmt::format("layer: expected {} (layers count from the core, 0, outward)", c->layers.size()));
    CatalogueLayer l;
    l.wires = static_cast<int>(wires);
    l.wire_diameter = number(cells, line, 3, true);
    l.material = cells[4];
    if (l.material.empty()) fail(column_of(line, 4), "material: expected a name");
    const auto kind = wire_kind_from_name(cells[5]);
    if (!kind) fail(column_of(line, 5), "kind: expected steel, aluminium or alloy, got '" + cells[5] + "'");
    l.kind = *kind;
    Material m;
    m.name = l.material;
    m.youngs_modulus = number(cells, line, 6, true);
    m.poisson_ratio = number(cells, line, 7, false);
    if (!(m.poisson_ratio > -1 && m.poisson_ratio < 0.5)) fail(column_of(line, 7), "nu: expected a value in (-1, 0.5)");
    m.density = number(cells, line, 8, true) * 1e-9;  // t/m³ to t/mm³
    if (!cells[9].empty()) {
      if (layer == 0) fail(column_of(line, 9), "lay_angle_deg: the core is straight, leave it empty");
      const double angle = number(cells, line, 9, true);
      if (!(angle < 90)) fail(column_of(line, 9), "lay_angle_deg: expected an angle in (0, 90) degrees");
      l.lay_angle = angle * kDegree;
    }
    const auto known = c->materials.find(m.name);
    if (known == c->materials.end()) c->materials[m.name] = m;
    else if (known->second.youngs_modulus != m.youngs_modulus || known->second.poisson_ratio != m.poisson_ratio || known->second.density != m.density)
      fail(column_of(line, 4), "material '" + m.name + "': E_MPa, nu and density_t_m3 differ from its earlier row of this conductor");
    c->layers.push_back(l);
  }

  std::string source_;
  std::size_t line_ = 0;
  std::vector<CatalogueConductor> conductors_;
};

}  // namespace

std::string CatalogueConductor::type() const {
  bool steel = false, aluminium = false, alloy = false;
  for (const CatalogueLayer& l : layers) {
    steel |= l.kind == WireKind::kSteel;
    aluminium |= l.kind == WireKind::kAluminium;
    alloy |= l.kind == WireKind::kAlloy;
  }
  if (steel && !aluminium && !alloy) return "steel strand";
  if (aluminium && alloy) return "mixed";
  if (steel) return aluminium ? "ACSR" : "AACSR";
  return aluminium ? "AAC" : "AAAC";
}

int CatalogueConductor::wire_count() const {
  int n = 0;
  for (const CatalogueLayer& l : layers) n += l.wires;
  return n;
}

std::vector<CatalogueConductor> read_conductor_catalogue(const std::string& text, const std::string& source) {
  return CatalogueReader(source).read(text);
}

std::vector<CatalogueConductor> read_conductor_catalogue_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw CaseError(path + ": cannot read the conductor catalogue");
  std::stringstream text;
  text << in.rdbuf();
  return read_conductor_catalogue(text.str(), path);
}

const std::vector<CatalogueConductor>& shipped_conductor_catalogue() {
  static const std::vector<CatalogueConductor> catalogue = read_conductor_catalogue(kShippedConductorCatalogue, "data/conductors/conductors.csv");
  return catalogue;
}

const CatalogueConductor* find_conductor(const std::vector<CatalogueConductor>& user, const std::string& name) {
  for (const auto* catalogue : {&user, &shipped_conductor_catalogue()})
    for (const CatalogueConductor& c : *catalogue)
      if (name_key(c.name) == name_key(name)) return &c;
  return nullptr;
}

ConductorStrand conductor_strand(const CatalogueConductor& c, const std::vector<double>& lay_ratios, const std::vector<double>& lay_angles) {
  const std::size_t n = c.layers.size();
  if (!lay_ratios.empty() && lay_ratios.size() + 1 != n) throw std::invalid_argument(fmt::format("expected {} lay ratios, one per layer around the core", n - 1));
  if (!lay_angles.empty() && lay_angles.size() + 1 != n) throw std::invalid_argument(fmt::format("expected {} lay angles, one per layer around the core", n - 1));
  ConductorStrand out;
  out.strand.materials = c.materials;
  std::vector<LayerKind> kinds;
  for (const CatalogueLayer& l : c.layers) kinds.push_back({l.kind, l.wires});
  const std::vector<int> directions = default_lay_directions(static_cast<int>(n));
  for (std::size_t i = 0; i < n; ++i) {
    LayerSpec layer;
    layer.wires = c.layers[i].wires;
    layer.wire_diameter = c.layers[i].wire_diameter;
    layer.material = c.layers[i].material;
    layer.lay_direction = directions[i];
    out.strand.layers.push_back(layer);
  }
  for (std::size_t i = 0; i < n; ++i) {
    out.ranges.push_back(en50182_lay_ratio_range(kinds, static_cast<int>(i)));
    if (i == 0) {
      out.lay_ratios.emplace_back();
      continue;
    }
    LayerSpec& layer = out.strand.layers[i];
    const double radius = layer_radius(out.strand, static_cast<int>(i));
    const std::optional<LayRatioRange>& range = out.ranges.back();
    if (!lay_angles.empty()) layer.lay_angle = lay_angles[i - 1];
    else if (!lay_ratios.empty()) layer.lay_angle = lay_angle_from_ratio(radius, layer.wire_diameter, lay_ratios[i - 1]);
    else if (c.layers[i].lay_angle) layer.lay_angle = *c.layers[i].lay_angle;
    else if (range) layer.lay_angle = lay_angle_from_ratio(radius, layer.wire_diameter, range->middle());
    else
      throw std::invalid_argument(fmt::format("{}: layer {} ({} {} wires) has no lay angle in the catalogue and no EN 50182 lay-ratio range: give "
                                              "strand.lay_ratios or strand.lay_angles", c.name, i, layer.wires, wire_kind_name(c.layers[i].kind)));
    const double ratio = lay_ratio_from_angle(radius, layer.wire_diameter, layer.lay_angle);
    out.lay_ratios.push_back(ratio);
    if (range && !range->contains(ratio * (1 + 1e-9)) && !range->contains(ratio * (1 - 1e-9)))
      out.warnings.push_back(fmt::format("{} layer {}: lay ratio {:.3g} outside EN 50182's {:g}-{:g} for this layer", c.name, i, ratio, range->lowest,
                                         range->highest));
  }
  return out;
}

std::vector<std::string> conductor_summary_header() {
  return {"conductor", "type", "wires", "diameter_mm", "area_mm2", "mass_kg_m", "EI_max_Nm2", "EI_min_Nm2"};
}

std::vector<std::string> conductor_summary_row(const CatalogueConductor& c) {
  const ConductorStrand s = conductor_strand(c, {}, {});
  const int outer = static_cast<int>(s.strand.layers.size()) - 1;
  const double diameter = 2 * layer_radius(s.strand, outer) + s.strand.layers.back().wire_diameter;
  const StrandProperties p = strand_properties(s.strand);
  const BendingStiffnessBounds ei = bending_stiffness_bounds(s.strand);
  return {c.name, c.type(), std::to_string(c.wire_count()), fmt::format("{:.2f}", diameter), fmt::format("{:.1f}", p.metallic_area),
          fmt::format("{:.3f}", p.mass_per_length), fmt::format("{:.1f}", ei.ei_max * 1e-6), fmt::format("{:.2f}", ei.ei_min * 1e-6)};
}

std::vector<std::vector<std::string>> conductor_summary_table(const std::string& catalogue) {
  std::vector<CatalogueConductor> conductors;
  if (!catalogue.empty()) conductors = read_conductor_catalogue_file(catalogue);
  const auto& shipped = shipped_conductor_catalogue();
  conductors.insert(conductors.end(), shipped.begin(), shipped.end());
  std::vector<std::vector<std::string>> rows = {conductor_summary_header()};
  for (const CatalogueConductor& c : conductors) rows.push_back(conductor_summary_row(c));
  return rows;
}

}  // namespace strandfem
