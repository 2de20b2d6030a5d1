// The conductor catalogue: overhead conductors and the paper's strands by name, layer by layer with their wire
// materials (data/conductors/conductors.csv, compiled in; a user's file of the same columns is searched first).
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "strandfem/beam/material.hpp"
#include "strandfem/geometry/lay_ratio.hpp"
#include "strandfem/geometry/strand.hpp"

namespace strandfem {

struct CatalogueLayer {
  int wires = 1;
  double wire_diameter = 0;         // mm
  std::string material;             // key into CatalogueConductor::materials
  WireKind kind = WireKind::kSteel;
  std::optional<double> lay_angle;  // rad; none: from the middle of the layer's EN 50182 lay-ratio range
};

struct CatalogueConductor {
  std::string name;
  std::string origin;  // file:line of its first row
  std::vector<CatalogueLayer> layers;  // the core first
  std::map<std::string, Material> materials;
  // ACSR (steel and aluminium), AACSR (steel and alloy), AAC, AAAC, or steel strand.
  std::string type() const;
  int wire_count() const;
};

// Reads a catalogue (CSV, '#' comment lines, the header of data/conductors/conductors.csv); `source` names it in
// errors (CaseError with source:line:column).
std::vector<CatalogueConductor> read_conductor_catalogue(const std::string& text, const std::string& source);
std::vector<CatalogueConductor> read_conductor_catalogue_file(const std::string& path);
const std::vector<CatalogueConductor>& shipped_conductor_catalogue();

// The conductor of that name (ignoring case, spaces, hyphens and underscores), first in `user` then in the shipped
// catalogue; nullptr when neither has it.
const CatalogueConductor* find_conductor(const std::vector<CatalogueConductor>& user, const std::string& name);

// A conductor's layers as a strand: lay angles from the catalogue, from `lay_ratios` or `lay_angles` (rad) when
// given (one per layer around the core), else from the middle of EN 50182's range; directions alternating with the
// outer layer right-hand. `warnings` gets a line per lay ratio outside its range.
struct ConductorStrand {
  StrandSpec strand;  // length 0: the case sets it
  std::vector<std::optional<double>> lay_ratios;  // per layer, the core's none
  std::vector<std::optional<LayRatioRange>> ranges;
  std::vector<std::string> warnings;
};
ConductorStrand conductor_strand(const CatalogueConductor& c, const std::vector<double>& lay_ratios, const std::vector<double>& lay_angles);

// The row `strandfem conductors` prints for it: name, type, wires, outer diameter (mm), metallic area (mm²), mass
// per length (kg/m), EImax and EImin (N m²), on the catalogue's lay angles.
std::vector<std::string> conductor_summary_header();
std::vector<std::string> conductor_summary_row(const CatalogueConductor& c);
// The header, then a row per conductor: those of the file `catalogue` (when not empty), then the shipped ones.
std::vector<std::vector<std::string>> conductor_summary_table(const std::string& catalogue);

}  // namespace strandfem
