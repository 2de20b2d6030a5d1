// Requirement (issue 10): bad input never passes silently and never crashes: huge sizes, integers of 2^31 and
// beyond, duplicate keys, contradictory or non-physical values and malformed files all end in exit code 2 with
// a message naming the key (or the file and line), before any result is written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <utility>
#include <vector>

#include "program_runner.hpp"

namespace strandfem::verification {
namespace {

std::string read_text(const std::string& relative) {
  std::ifstream in(case_path(relative), std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The case `base` with each `from` text replaced (first occurrence) by `to`, written to a temporary file.
std::string mutated(const std::string& base, const std::vector<std::pair<std::string, std::string>>& edits,
                    const std::string& name) {
  std::string text = read_text(base);
  for (const auto& [from, to] : edits) {
    const auto pos = text.find(from);
    EXPECT_NE(pos, std::string::npos) << name << ": '" << from << "' not in " << base;
    if (pos != std::string::npos) text.replace(pos, from.size(), to);
  }
  const std::string file = ::testing::TempDir() + "/input_" + name + ".yaml";
  std::ofstream(file, std::ios::binary) << text;
  return file;
}

struct Mutation {
  const char* name;
  const char* base;
  std::vector<std::pair<std::string, std::string>> edits;
  std::vector<std::string> message;  // every part must appear in the error message
};

const char* const kSeven = "cases/examples/seven_wire_axial.yaml";
const char* const kBeam = "cases/verification/cantilever_roll_up.yaml";

void expect_exit_2(const std::vector<Mutation>& mutations) {
  for (const Mutation& m : mutations) {
    const std::string file = mutated(m.base, m.edits, m.name);
    const ProgramRun r = run_program("info " + file, std::string("input_") + m.name);
    EXPECT_EQ(r.exit_code, 2) << m.name << ": " << r.stderr_text;
    for (const std::string& part : m.message)
      EXPECT_NE(r.stderr_text.find(part), std::string::npos) << m.name << ": expected '" << part << "' in: " << r.stderr_text;
  }
}

// Class 1: sizes are counted in 64 bits and checked against the model-size limit before anything is allocated.
TEST(InputChecks, HugeModelsAreRefusedNamingTheKeyAndTheLimit) {
  expect_exit_2({
      {"elements_per_wire_2e9", kSeven, {{"elements_per_wire: 24", "elements_per_wire: 2147483647"}}, {"mesh.elements_per_wire", "1..124999"}},
      {"elements_per_wire_1e5", kSeven, {{"elements_per_wire: 24", "elements_per_wire: 100000"}},
       {"mesh.elements_per_wire", "1400007 nodes", "model-size limit of 250000 nodes (1500000 DOFs)"}},
      {"element_length_1e-9", kSeven, {{"mesh: {elements_per_wire: 24}", "mesh: {element_length: 1.0e-9}"}},
       {"mesh.element_length", "model-size limit"}},
      {"length_1e11_default_mesh", kSeven, {{"mesh: {elements_per_wire: 24}", ""}, {"length: 200", "length: 1.0e11"}},
       {"strand.length", "model-size limit", "mesh.element_length"}},
      {"beam_elements_2e31", kBeam, {{"elements: 10", "elements: 2147483648"}}, {"beams[0].elements", "1..124999"}},
      {"beam_elements_over_limit", kBeam, {{"elements: 10", "elements: 124999"}, {"name: cantilever", "name: c2\n    material: steel\n    section: {diameter: 2.0}\n    shape: {type: straight, start: [0, 0, 0], end: [100, 0, 0]}\n    elements: 124999\n  - name: cantilever"}},
       {"beams[1].elements", "model-size limit"}},
  });
}

// Class 2: every integer key is range-checked in 64 bits: nothing wraps at 2^31 or 2^32.
TEST(InputChecks, IntegersBeyondTheirRangeAreRefusedNotWrapped) {
  expect_exit_2({
      {"wires_2e31", kSeven, {{"wires: 6", "wires: 2147483648"}}, {"strand.layers[1].wires", "expected an integer in 1..1000"}},
      {"core_wires_2e32", kSeven, {{"wires: 1", "wires: 4294967297"}}, {"strand.layers[0].wires", "expected an integer in"}},
      {"increments_2e32", kSeven, {{"increments: 10", "increments: 4294967298"}}, {"steps[0].increments", "1..1000000"}},
      {"max_cutbacks", kSeven, {{"steps:", "solver: {max_cutbacks: 4294967304}\nsteps:"}}, {"solver.max_cutbacks", "0..30"}},
      {"line_search_cuts", kSeven, {{"steps:", "solver: {line_search_cuts: 2147483648}\nsteps:"}}, {"solver.line_search_cuts", "0..20"}},
      {"threads", kSeven, {{"steps:", "solver: {threads: 4294967297}\nsteps:"}}, {"solver.threads"}},
      {"every", kSeven, {{"steps:", "output: {every: 2147483648}\nsteps:"}}, {"output.every"}},
      {"contacts_every", kSeven, {{"steps:", "output: {contacts_every: -4294967295}\nsteps:"}}, {"output.contacts_every"}},
      {"beyond_64_bits", kSeven, {{"increments: 10", "increments: 99999999999999999999999"}}, {"steps[0].increments"}},
      {"node_index", kBeam, {{"point: end}, moment", "node: 4294967296}, moment"}}, {"steps[0].forces[0].at.node"}},
  });
}

// The bending maps' clamp edge lies inside the strand's half length, and only strands have one.
TEST(InputChecks, ClampEdgeOffsetIsADistanceWithinHalfTheStrand) {
  expect_exit_2({
      {"offset_negative", kSeven, {{"steps:", "output: {clamp_edge_offset: -1}\nsteps:"}}, {"output.clamp_edge_offset", ">= 0"}},
      {"offset_half", kSeven, {{"steps:", "output: {clamp_edge_offset: 1000}\nsteps:"}}, {"output.clamp_edge_offset", "below half the strand length"}},
      {"offset_beam", kBeam, {{"output: {monitor:", "output: {clamp_edge_offset: 5, monitor:"}}, {"output.clamp_edge_offset", "only strands"}},
  });
}

// Clamps are shorter than half the strand, and a saddle needs its length, lies between the clamps and comes only
// with through: saddle.
TEST(InputChecks, ClampAndSaddleLengthsFitTheStrand) {
  const char* const saddle = "cases/verification/tensioned_core_saddle.yaml";
  const std::string loaded = "through: saddle, saddle_length: 40";
  expect_exit_2({
      {"clamp_half", saddle, {{"clamp_length: 20", "clamp_length: 100"}}, {"strand.clamp_length", "less than half"}},
      {"clamp_negative", saddle, {{"clamp_length: 20", "clamp_length: -1"}}, {"strand.clamp_length", ">= 0"}},
      {"saddle_missing", saddle, {{loaded, "through: saddle"}}, {"saddle_length"}},
      {"saddle_alone", saddle, {{loaded, "saddle_length: 40"}}, {"saddle_length", "only with through: saddle"}},
      {"saddle_long", saddle, {{loaded, "through: saddle, saddle_length: 160"}}, {"saddle_length", "reaches the clamps"}},
      {"saddle_zero", saddle, {{loaded, "through: saddle, saddle_length: 0"}}, {"saddle_length"}},
  });
}

// The steadiness tolerance of the loops is a fraction: 0.02 means 2 %, not 2.
TEST(InputChecks, SteadyToleranceIsAFractionBelowOne) {
  expect_exit_2({
      {"steady_zero", kSeven, {{"steps:", "output: {steady_tolerance: 0}\nsteps:"}}, {"output.steady_tolerance", "positive"}},
      {"steady_percent", kSeven, {{"steps:", "output: {steady_tolerance: 2}\nsteps:"}}, {"output.steady_tolerance", "in (0, 1)"}},
      {"steady_text", kSeven, {{"steps:", "output: {steady_tolerance: two}\nsteps:"}}, {"output.steady_tolerance"}},
  });
}

// Class 3: a key given twice in one mapping (YAML keeps one silently) names both lines.
TEST(InputChecks, DuplicateKeysNameBothLines) {
  expect_exit_2({
      {"duplicate_length", kSeven, {{"  length: 200", "  length: 40\n  length: -5"}}, {"strand.length", "duplicate key", "lines 7 and 8"}},
      {"duplicate_in_flow", kSeven, {{"E: 188000,", "E: 188000, E: 1,"}}, {"materials.steel.E", "duplicate key"}},
      {"duplicate_material", kSeven, {{"materials:\n", "materials:\n  steel: {E: 1, nu: 0.3}\n"}}, {"materials.steel", "duplicate key"}},
  });
}

// Class 4: values that are non-physical or contradict each other.
TEST(InputChecks, ContradictoryAndNonPhysicalValuesAreRefused) {
  expect_exit_2({
      {"stacked_wires", kSeven, {{"lay_angle: 11.8}", "lay_angle: 11.8, start_angles: [0, 0, 0, 0, 0, 0]}"}},
       {"strand.layers[1]", "overlap", "start_angles"}},
      {"two_wires_too_close", kSeven, {{"lay_angle: 11.8}", "lay_angle: 11.8, start_angles: [0, 50, 120, 180, 240, 300]}"}},
       {"strand.layers[1]", "overlap"}},
      {"strain_and_motion", kSeven, {{"axial_strain: 0.01}", "axial_strain: 0.01, motions: [{at: {core: end}, uz: 1}]}"}},
       {"steps[0].motions[0].uz", "steps[0].axial_strain", "twice"}},
      {"motion_then_force", kSeven, {{"axial_strain: 0.01}", "axial_strain: 0.01}\n  - {name: hold, increments: 1, axial_force: 100}"}},
       {"steps[1].axial_force", "steps[0].axial_strain"}},
      {"force_on_support", kBeam, {{"moment: [0, 0, 9869.604401089358]}", "moment: [0, 0, 1]}\n      - {at: {beam: cantilever, point: start}, force: [1, 0, 0]}"}},
       {"steps[0].forces[1].force", "supports[0]"}},
      {"core_and_core_z", kSeven, {{"axial_strain: 0.01}", "axial_strain: 0.01, forces: [{at: {core: end, core_z: 5}, force: [1, 0, 0]}]}"}},
       {"steps[0].forces[0].at", "core or core_z"}},
      {"point_and_node", kBeam, {{"point: end}, moment", "point: end, node: 3}, moment"}}, {"steps[0].forces[0].at", "point or node"}},
      {"element_length_1e-300", kSeven, {{"mesh: {elements_per_wire: 24}", "mesh: {element_length: 1.0e-300}"}}, {"mesh.element_length"}},
      {"length_1e-300", kSeven, {{"length: 200", "length: 1e-300"}}, {"strand.length"}},
      {"length_1e-11", kSeven, {{"length: 200", "length: 1e-11"}}, {"mesh.elements_per_wire", "round-off"}},
      {"tiny_beam", kBeam, {{"end: [100, 0, 0]", "end: [1.0e-9, 0, 0]"}}, {"beams[0].elements", "round-off"}},
      {"stabilization_above_one", kSeven, {{"steps:", "contact: {stabilization: 2}\nsteps:"}},
       {"contact.stabilization", "in [0, 1)"}},
      {"stabilization_negative", kSeven, {{"steps:", "contact: {stabilization: -1.0e-6}\nsteps:"}},
       {"contact.stabilization"}},
      {"contacts_unknown", kSeven,
       {{"steps:", "contact: {friction_zones: [{z: [0, 10], mu: 0.2, contacts: sideways}]}\nsteps:"}},
       {"contact.friction_zones[0].contacts", "lateral", "radial"}},
      {"pair_sets_nothing", kSeven,
       {{"steps:", "contact: {friction_pairs: [{materials: [steel, steel], contacts: radial}]}\nsteps:"}},
       {"contact.friction_pairs[0]", "orthotropy_ratio"}},
      {"friction_direction_unknown", kSeven, {{"steps:", "contact: {friction_direction: inner_wire}\nsteps:"}},
       {"contact.friction_direction", "strand_axis", "slave_wire"}},
      {"huge_modulus", kSeven, {{"E: 188000", "E: 1e300"}}, {"materials.steel.E", "1e15"}},
      {"infinite_force", kBeam, {{"9869.604401089358", ".inf"}}, {"steps[0].forces[0].moment[2]", "finite"}},
      {"stress_measure_nominal", "cases/paper/seven_wire_plastic_fixed.yaml",
       {{"stress_measure: true_stress", "stress_measure: nominal"}},
       {"materials.steel.plasticity.stress_measure", "true_stress", "engineering"}},
  });
}

// Class 5: malformed files and nodes of the wrong kind are bad input (exit 2), never an internal error.
TEST(InputChecks, MalformedFilesAreBadInputNotInternalErrors) {
  expect_exit_2({
      {"scalar_shape", kBeam, {{"shape: {type: straight, start: [0, 0, 0], end: [100, 0, 0], normal: [0, 1, 0]}", "shape: abc"}},
       {"beams[0].shape"}},
      {"scalar_mesh", kSeven, {{"mesh: {elements_per_wire: 24}", "mesh: abc"}}, {"mesh"}},
      {"sequence_key", kSeven, {{"  length: 200", "  length: 200\n  [1, 2]: 3"}}, {"strand", "mapping key"}},
      {"mapping_key", kSeven, {{"  length: 200", "  length: 200\n  ? {a: 1}\n  : 3"}}, {"strand", "mapping key"}},
      {"invalid_utf8_title", kSeven, {{"title: 7-wire", "title: \xff\xfe 7-wire"}}, {":3:8:", "UTF-8"}},
      {"invalid_utf8_material", kSeven, {{"steel: {E", "st\xc3\x28" "el: {E"}}, {"UTF-8"}},
      {"surrogate_escape", kSeven, {{"title: 7-wire strand, axial strain to 1 %, fixed ends, no contact", "title: \"\\udc80\""}}, {":3:"}},
      {"control_character", kSeven, {{"title: 7-wire", std::string("title: 7\x01-wire")}}, {":3:9:"}},
      {"truncated", kSeven, {{"  - {name: pull, increments: 10, axial_strain: 0.01}", "  - {name: pull, incre"}}, {"not valid YAML"}},
      {"self_alias", kSeven, {{"steps:", "description: &x [*x]\nsteps:"}}, {"nested deeper"}},
  });
  const ProgramRun directory = run_program("info " + case_path("cases"), "input_directory");
  EXPECT_EQ(directory.exit_code, 2) << directory.stderr_text;
  EXPECT_NE(directory.stderr_text.find("is a directory"), std::string::npos) << directory.stderr_text;
  const ProgramRun missing = run_program("info " + case_path("cases/no_such_case.yaml"), "input_missing");
  EXPECT_EQ(missing.exit_code, 2) << missing.stderr_text;
}

// Class 10: the key is named for a degenerate strand, and every case shipped under cases/ still reads (exit 0).
TEST(InputChecks, ShippedCasesStillRead) {
  int count = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(case_path("cases"))) {
    if (entry.path().extension() != ".yaml") continue;
    const ProgramRun r = run_program("info " + entry.path().string(), "input_shipped");
    EXPECT_EQ(r.exit_code, 0) << entry.path() << ": " << r.stderr_text;
    ++count;
  }
  EXPECT_GE(count, 30);  // the paper's cases, the verification cases and the examples
}

// Class 9: hub links are checked in O(n): a 100,000-element line tied to a hub reads in a fraction of a second;
// the quadratic check took 11 s (issue 10).
TEST(InputChecks, LongLineTiedToAHubReadsQuickly) {
  const std::string file = mutated(kBeam, {{"elements: 10", "elements: 100000"},
                                           {"supports:", "hubs:\n  - {name: plate, position: [0, 0, 0], links: [{beam: cantilever}]}\nsupports:"},
                                           {"{at: {beam: cantilever, point: start}, fix: all}", "{at: {hub: plate}, fix: [ux, uy, uz, rx, ry]}"},
                                           {"at: {beam: cantilever, point: end}", "at: {hub: plate}"}},
                                   "hub_line");
  const auto start = std::chrono::steady_clock::now();
  const ProgramRun r = run_program("info " + file, "input_hub_line");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(r.output / "stdout.txt"));
  EXPECT_EQ(j["rigid_ties"], 200001);
  EXPECT_LT(seconds, 3.0);
}

}  // namespace
}  // namespace strandfem::verification
