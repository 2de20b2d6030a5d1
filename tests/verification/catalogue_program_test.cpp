// Requirement: conductors of the catalogue, of five constructions, run a tension and one bending cycle on 300 mm on
// the default settings, in at most 1.5 times their nominal increments, their peak deflection between eq. 3.1's
// bounds (EImax and EImin).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "program_runner.hpp"

namespace strandfem::verification {
namespace {

struct CatalogueRun {
  const char* conductor;
  const char* construction;
  double tension;  // N, about 60 MPa on the metallic area
  double load;     // N, 2 % of the tension
};

TEST(CatalogueProgram, FiveConstructionsRunATensionAndABendingCycleOnTheDefaults) {
  const std::vector<CatalogueRun> runs = {{"Drake", "ACSR 26/7, two aluminium layers", 28000, 560},
                                          {"Cardinal", "ACSR 54/7, three aluminium layers", 32000, 640},
                                          {"Orchid", "AAC 37", 19000, 380},
                                          {"AAAC 823", "AAAC 37", 25000, 500},
                                          {"Aster 570", "Aster 61", 34000, 680}};
  const int nominal_increments = 4 + 2 * 4;
  for (const CatalogueRun& run : runs) {
    SCOPED_TRACE(std::string(run.conductor) + " (" + run.construction + ")");
    const std::string tag = std::string("catalogue_") + std::to_string(&run - runs.data());
    const std::string file = ::testing::TempDir() + "/" + tag + ".yaml";
    std::ofstream(file) << "title: t\nstrand: {conductor: " << run.conductor << ", length: 300}\ncontact: {friction: 0.5}\nsteps:\n"
                        << "  - {name: tension, increments: 4, axial_force: " << run.tension << "}\n"
                        << "  - {name: bend, increments: 4, cycles: 1, transverse_force: {value: " << run.load
                        << ", z: 150, direction: [0, 1, 0]}}\noutput: {vtu: false, contacts: false, wires: false}\n";
    const auto out = std::filesystem::path(::testing::TempDir()) / (tag + "_out");
    const ProgramRun r = run_program("run " + file + " -q -t 1 -o " + out.string(), tag);
    ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
    const auto history = read_csv(out / "history.csv");
    EXPECT_LE(history.size(), 1.5 * nominal_increments);
    EXPECT_NEAR(history.at(3).at("axial_force_N"), run.tension, 1e-3 * run.tension);
    const auto summary = nlohmann::json::parse(std::ifstream(out / "summary.json"));
    EXPECT_EQ(summary["configuration"]["strand"]["conductor"], run.conductor);
    const auto& loop = summary["bending"]["loops"].at(0);
    EXPECT_NEAR(loop["peak_load_N"].get<double>(), run.load, 1e-3 * run.load);
    EXPECT_GT(loop["peak_deflection_mm"].get<double>(), loop["eq31_ei_max_mm"].get<double>());
    EXPECT_LT(loop["peak_deflection_mm"].get<double>(), loop["eq31_ei_min_mm"].get<double>());
  }
}

}  // namespace
}  // namespace strandfem::verification
