// Requirement: a case names a conductor of the catalogue and gets its layers, wire materials and lay angles (from the
// catalogue, from lay ratios, or from the middle of EN 50182's ranges); the paper's strands come out as the paper's
// case files build them; a user's catalogue is searched first, and bad catalogues and names are refused with file,
// line and column.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <regex>

#include "strandfem/io/case_file.hpp"
#include "strandfem/io/conductor_catalogue.hpp"
#include "strandfem/post/analytic.hpp"
#include "strandfem/post/model_report.hpp"

namespace strandfem {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
const std::string kSource = STRANDFEM_SOURCE_DIR;

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// A 300 mm tension case of the conductor, with `extra` lines in its strand mapping.
std::string conductor_case(const std::string& name, const std::string& extra = "") {
  return "title: t\nstrand: {conductor: " + name + ", length: 300" + extra + "}\nsteps:\n  - {name: pull, increments: 1, axial_force: 1000}\n";
}

std::string case_error(const std::string& text, const std::string& catalogue = "") {
  try {
    load_case_text(text, "case.yaml", catalogue);
  } catch (const CaseError& e) {
    return e.what();
  }
  return "";
}

TEST(LayRatio, AngleAndRatioFollowTheHelixOfTheWireCentres) {
  // Drake's steel layer: wires of 3.45 mm at R = 3.45 mm, lay ratio 21 of the layer's 10.35 mm outer diameter:
  // lay length 217.35 mm, tan(alpha) = 2 pi R / lay length.
  const double angle = lay_angle_from_ratio(3.45, 3.45, 21.0);
  EXPECT_NEAR(angle, std::atan(2 * std::numbers::pi * 3.45 / 217.35), 1e-12);
  EXPECT_NEAR(angle / kDegree, 5.695, 5e-4);
  EXPECT_NEAR(lay_ratio_from_angle(3.45, 3.45, angle), 21.0, 1e-12);
}

TEST(LayRatio, EN50182RangesByLayerKindAndCore) {
  using K = WireKind;
  // ACSR 26/7 (Drake): a 7-wire steel core, two aluminium layers.
  const std::vector<LayerKind> drake = {{K::kSteel, 1}, {K::kSteel, 6}, {K::kAluminium, 10}, {K::kAluminium, 16}};
  EXPECT_FALSE(en50182_lay_ratio_range(drake, 0));
  EXPECT_EQ(en50182_lay_ratio_range(drake, 1)->lowest, 16);
  EXPECT_EQ(en50182_lay_ratio_range(drake, 1)->highest, 26);
  EXPECT_EQ(en50182_lay_ratio_range(drake, 2)->highest, 16);  // inner aluminium 10-16
  EXPECT_EQ(en50182_lay_ratio_range(drake, 3)->highest, 14);  // outer aluminium 10-14
  const std::vector<LayerKind> core19 = {{K::kSteel, 1}, {K::kSteel, 6}, {K::kSteel, 12}, {K::kAluminium, 18}};
  EXPECT_EQ(en50182_lay_ratio_range(core19, 1)->lowest, 16);
  EXPECT_EQ(en50182_lay_ratio_range(core19, 2)->lowest, 14);
  EXPECT_EQ(en50182_lay_ratio_range(core19, 2)->highest, 22);
  const std::vector<LayerKind> core37 = {{K::kSteel, 1}, {K::kSteel, 6}, {K::kSteel, 12}, {K::kSteel, 18}, {K::kAluminium, 24}};
  EXPECT_EQ(en50182_lay_ratio_range(core37, 1)->lowest, 17);
  EXPECT_EQ(en50182_lay_ratio_range(core37, 2)->lowest, 16);
  EXPECT_EQ(en50182_lay_ratio_range(core37, 3)->lowest, 14);
  EXPECT_EQ(en50182_lay_ratio_range(core37, 3)->highest, 18);
  const std::vector<LayerKind> steel_strand = {{K::kSteel, 1}, {K::kSteel, 6}};  // not a conductor: no EN 50182 range
  EXPECT_FALSE(en50182_lay_ratio_range(steel_strand, 1));
}

TEST(ConductorCatalogue, EveryShippedConductorBuildsAStrandOnItsDefaultLayAngles) {
  const auto& catalogue = shipped_conductor_catalogue();
  ASSERT_GE(catalogue.size(), 37u);
  for (const CatalogueConductor& c : catalogue) {
    SCOPED_TRACE(c.name);
    CaseDefinition d;
    ASSERT_NO_THROW(d = load_case_text(conductor_case("\"" + c.name + "\""), "case.yaml"));
    ASSERT_TRUE(d.strand);
    EXPECT_EQ(d.conductor, c.name);
    ASSERT_EQ(d.strand->layers.size(), c.layers.size());
    int wires = 0;
    for (const LayerSpec& l : d.strand->layers) wires += l.wires;
    EXPECT_EQ(wires, c.wire_count());
    const ConductorStrand s = conductor_strand(c, {}, {});
    for (std::size_t i = 1; i < c.layers.size(); ++i) {
      if (c.layers[i].lay_angle) continue;
      ASSERT_TRUE(s.ranges[i]);  // a layer without a catalogue angle takes the middle of its range
      EXPECT_NEAR(*s.lay_ratios[i], s.ranges[i]->middle(), 1e-9 * s.ranges[i]->middle());
    }
    EXPECT_TRUE(s.warnings.empty());
    EXPECT_EQ(model_report(d)["conductor"], c.name);
  }
}

// The paper's strands as the catalogue holds them build the same model as the paper's case files.
TEST(ConductorCatalogue, PaperEntriesBuildThePapersModels) {
  const std::vector<std::pair<std::string, std::string>> entries = {
      {"paper-cardinal", "cases/paper/cardinal.yaml"}, {"paper-s32", "cases/paper/s32.yaml"},
      {"paper-120-wire", "cases/paper/wire_120.yaml"}, {"paper-7-wire", "cases/paper/seven_wire_fixed.yaml"}};
  for (const auto& [name, file] : entries) {
    SCOPED_TRACE(name);
    const std::string text = read_text(kSource + "/" + file);
    // The case's `materials` and `strand.layers` replaced by the conductor; everything else kept.
    const std::regex materials(R"(\nmaterials:\n(  .*\n)+)"), layers(R"(\n  layers:\n(    .*\n)+)");
    std::string named = std::regex_replace(text, materials, "\n");
    named = std::regex_replace(named, layers, "\n  conductor: " + name + "\n");
    ASSERT_NE(named.find("conductor: " + name), std::string::npos);
    ASSERT_EQ(named.find("layers:"), std::string::npos);
    const CaseDefinition by_name = load_case_text(named, name + ".yaml"), by_layers = load_case_text(text, file);
    nlohmann::json a = model_report(by_name), b = model_report(by_layers);
    EXPECT_EQ(a["conductor"], name);
    a.erase("conductor");
    b.erase("conductor");
    EXPECT_EQ(a, b);
    EXPECT_EQ(by_name.resolved["materials"], by_layers.resolved["materials"]);
  }
}

TEST(ConductorCatalogue, NamesMatchIgnoringCaseSpacesAndHyphens) {
  for (const char* name : {"Aster 570", "aster570", "ASTER-570", "aster_570"}) {
    const CatalogueConductor* c = find_conductor({}, name);
    ASSERT_NE(c, nullptr) << name;
    EXPECT_EQ(c->name, "Aster 570");
    EXPECT_EQ(c->type(), "AAAC");
  }
  EXPECT_EQ(find_conductor({}, "drake")->type(), "ACSR");
  EXPECT_EQ(find_conductor({}, "Orchid")->type(), "AAC");
  EXPECT_EQ(find_conductor({}, "paper-s32")->type(), "steel strand");
  EXPECT_EQ(find_conductor({}, "Drak"), nullptr);
}

TEST(ConductorCatalogue, LayRatiosAndLayAnglesOverrideAndRatiosOutsideTheRangeWarn) {
  const CaseDefinition ratios = load_case_text(conductor_case("Drake", ", lay_ratios: [20, 12, 11]"), "case.yaml");
  const StrandSpec& s = *ratios.strand;
  EXPECT_NEAR(s.layers[2].lay_angle, lay_angle_from_ratio(layer_radius(s, 2), 4.44, 12.0), 1e-12);
  EXPECT_TRUE(ratios.warnings.empty() || ratios.warnings.front().find("overlap") != std::string::npos);
  EXPECT_EQ(ratios.resolved["strand"]["lay_ratios"][1], 12.0);
  EXPECT_EQ(ratios.resolved["strand"]["conductor"], "Drake");
  const CaseDefinition angles = load_case_text(conductor_case("Drake", ", lay_angles: [6, 11, 13]"), "case.yaml");
  EXPECT_NEAR(angles.strand->layers[3].lay_angle, 13 * kDegree, 1e-12);
  const CaseDefinition outside = load_case_text(conductor_case("Drake", ", lay_ratios: [20, 12, 15]"), "case.yaml");
  bool warned = false;
  for (const std::string& w : outside.warnings) warned |= w.find("Drake layer 3: lay ratio 15 outside EN 50182's 10-14") != std::string::npos;
  EXPECT_TRUE(warned);
  // Directions alternate with the outer layer right-hand.
  EXPECT_EQ(s.layers[3].lay_direction, 1);
  EXPECT_EQ(s.layers[2].lay_direction, -1);
  EXPECT_EQ(s.layers[1].lay_direction, 1);
}

TEST(ConductorCatalogue, ACaseMaterialReplacesTheCataloguesOfTheSameName) {
  const std::string text = "materials:\n  AL1: {E: 55000, nu: 0.33, density: 2.7e-9}\n" + conductor_case("Drake");
  const CaseDefinition d = load_case_text(text, "case.yaml");
  EXPECT_EQ(d.strand->materials.at("AL1").youngs_modulus, 55000);
  EXPECT_EQ(d.strand->materials.at("ST6C").youngs_modulus, 207000);
}

TEST(ConductorCatalogue, BadNamesAndKeysNameTheKeyAndWhere) {
  EXPECT_NE(case_error(conductor_case("Drak")).find("case.yaml:2:21: strand.conductor: unknown conductor 'Drak'"), std::string::npos)
      << case_error(conductor_case("Drak"));
  EXPECT_NE(case_error(conductor_case("Drake", ", lay_ratios: [20, 12]")).find("strand.lay_ratios: expected 3 lay ratios"), std::string::npos);
  EXPECT_NE(case_error(conductor_case("Drake", ", lay_ratios: [20, 12, 11], lay_angles: [6, 11, 13]")).find("not both"), std::string::npos);
  EXPECT_NE(case_error(conductor_case("Drake", ", layers: []")).find("give strand.conductor or strand.layers, not both"), std::string::npos);
  const std::string own_layers = "title: t\nmaterials: {s: {E: 1, nu: 0.3}}\nstrand: {length: 30, lay_ratios: [12], layers: [{wires: 1, diameter: 1, material: s}]}\n"
                                 "steps:\n  - {name: pull, increments: 1, axial_force: 1}\n";
  EXPECT_NE(case_error(own_layers).find("strand.lay_ratios: only with strand.conductor"), std::string::npos) << case_error(own_layers);
  const std::string no_materials = "title: t\nstrand: {length: 30, layers: [{wires: 1, diameter: 1, material: s}]}\nsteps: []\n";
  EXPECT_NE(case_error(no_materials).find("materials"), std::string::npos);
}

TEST(ConductorCatalogue, AUserCatalogueIsSearchedFirstAndCheckedRowByRow) {
  const std::string header = "conductor,layer,wires,diameter_mm,material,kind,E_MPa,nu,density_t_m3,lay_angle_deg\n";
  const auto path = std::filesystem::temp_directory_path() / "strandfem_user_catalogue.csv";
  {
    std::ofstream out(path);
    out << "# a user's catalogue\n" << header << "Drake,0,1,3,st,steel,200000,0.3,7.8,\nDrake,1,6,3,st,steel,200000,0.3,7.8,10\n";
  }
  const CaseDefinition d = load_case_text(conductor_case("Drake"), "case.yaml", path.string());
  EXPECT_EQ(d.strand->layers.size(), 2u);
  EXPECT_NEAR(d.strand->layers[1].lay_angle, 10 * kDegree, 1e-12);
  EXPECT_EQ(d.conductor_origin, path.string() + ":3");
  EXPECT_EQ(load_case_text(conductor_case("Cardinal"), "case.yaml", path.string()).conductor, "Cardinal");  // the shipped one next
  std::filesystem::remove(path);
  const auto error = [&](const std::string& rows) {
    try {
      read_conductor_catalogue(header + rows, "my.csv");
    } catch (const CaseError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error("A,0,1,x,st,steel,1,0.3,7.8,\n"), "my.csv:2:7: diameter_mm: expected a number > 0, got 'x'");
  EXPECT_EQ(error("A,1,1,3,st,steel,1,0.3,7.8,\n"), "my.csv:2:3: layer: expected 0 (layers count from the core, 0, outward)");
  EXPECT_EQ(error("A,0,1,3,st,wood,1,0.3,7.8,\n"), "my.csv:2:12: kind: expected steel, aluminium or alloy, got 'wood'");
  EXPECT_EQ(error("A,0,1,3,st,steel,1,0.3,7.8,5\n"), "my.csv:2:28: lay_angle_deg: the core is straight, leave it empty");
  EXPECT_NE(error("A,0,1,3,st,steel,1,0.3,7.8,\nA,1,6,3,st,steel,2,0.3,7.8,\n").find("my.csv:3:9: material 'st'"), std::string::npos);
  EXPECT_NE(error("A,0,1,3,st,steel,1,0.3,7.8\n").find("my.csv:2:1: expected 10 columns, found 9"), std::string::npos);
  EXPECT_NE(error("A,0,3,3,st,steel,1,0.3,7.8,\n").find("the core (layer 0) must have exactly 1 wire"), std::string::npos);
  try {
    read_conductor_catalogue("conductor,layer\n", "my.csv");
    ADD_FAILURE();
  } catch (const CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("my.csv:1:1: expected the columns conductor,layer,wires"), std::string::npos);
  }
}

// Poffenberger–Swart's K = E d p² / (4 (e^(-p xb) - 1 + p xb)) tends to a cantilever's E d / (2 xb²) without tension
// and to E d p² / (4 (p xb - 1)) once p xb is large.
TEST(PoffenbergerSwart, StressTendsToItsLimitsOfNoAndHighTension) {
  const double E = 68000, d = 4.44, xb = kPoffenbergerSwartDistance, ei = 43.06e6;
  EXPECT_NEAR(poffenberger_swart_stress(1.0, 1e-9, ei, E, d, xb), E * d / (2 * xb * xb), 1e-6 * E * d / (xb * xb));  // p xb = 4e-7
  const double T = 1e9, p = std::sqrt(T / ei);
  EXPECT_NEAR(poffenberger_swart_stress(1.0, T, ei, E, d, xb), E * d * p * p / (4 * (p * xb - 1)), 1e-9 * E * d * p * p / (p * xb));
  EXPECT_NEAR(poffenberger_swart_stress(0.5, 28000, ei, E, d, xb), 0.5 * poffenberger_swart_stress(1.0, 28000, ei, E, d, xb), 1e-12);
  // Drake at 28 kN by hand: p = 0.025501 /mm, p xb = 2.2696, K = 35.75 MPa/mm.
  EXPECT_NEAR(poffenberger_swart_stress(1.0, 28000, ei, E, d, xb), 35.75, 0.01);
  const nlohmann::json report = poffenberger_swart_report(*load_case_text(conductor_case("Drake"), "case.yaml").strand, 28000, 0.5);
  EXPECT_EQ(report["outer_wire_diameter_mm"], 4.44);
  EXPECT_EQ(report["outer_wire_E_MPa"], 68000);
  EXPECT_NEAR(report["stress_amplitude_MPa"].get<double>(), 0.5 * report["K_MPa_per_mm"].get<double>(), 1e-12);
}

}  // namespace
}  // namespace strandfem
