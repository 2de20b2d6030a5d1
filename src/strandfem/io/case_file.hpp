// Case files (YAML): strands or free beam lines, supports, load steps, solver and output options.
#pragma once
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "strandfem/io/yaml_reader.hpp"
#include "strandfem/mesh/mesh.hpp"
#include "strandfem/solver/model.hpp"

namespace strandfem {

struct OutputOptions {
  int every = 1;      // write ParaView files every n-th converged increment (the last one always)
  bool vtu = true;
  bool contacts = true;          // DIR/contacts.csv and contact point files, when contact is on
  int contacts_every = 1;        // contact rows every n-th converged increment (the last of each step always)
  bool contacts_every_set = false;
  bool wires = true;             // DIR/wires.csv: section results along every wire, at the contact rows' increments
  bool checkpoint = true;        // DIR/checkpoint.bin after every converged increment (strandfem run --resume)
  // Bending status maps start this far (mm) inside the strand from each restrained end, where the paper
  // (section 4.1) places the clamp edge: 22 mm for the Cardinal conductor.
  double clamp_edge_offset = 0;
  // A cycle's loop is steady when its area and peak deflection are within this fraction of the previous cycle's.
  double steady_tolerance = 0.02;
};

// A parsed, validated case: the model plus what the outputs need to know about it.
struct CaseDefinition {
  std::string title;
  std::string path;
  std::optional<StrandSpec> strand;   // present for strand cases
  std::string end_type;               // strand: fixed | free
  std::string conductor;              // strand: the catalogue conductor it was built from (empty: its own layers)
  std::string conductor_origin;       // and the catalogue row (file:line) that conductor starts at
  MeshSpec mesh_spec;
  Model model;
  OutputOptions output;
  // Result probes. Strands: core end nodes. Beams: first beam's start and the monitor node.
  int start_node = -1;
  int end_node = -1;
  int monitor_node = -1;              // strand: core node nearest mid-length
  double axial_length = 0;            // strand length (for the axial strain)
  double clamp_length = 0;            // strand: length held rigid at each end (strand.clamp_length)
  double saddle_length = 0;           // strand: length held rigid under a transverse load (through: saddle)
  std::vector<std::string> warnings;  // e.g. nominal overlaps of neighbouring wires
  nlohmann::json resolved;            // the fully resolved configuration, written with the results
};

// Reads and validates a case file; throws CaseError naming the key and the expected value. `catalogue`: a conductor
// catalogue file searched before the shipped one for `strand.conductor` (empty: the shipped one alone).
CaseDefinition load_case(const std::string& path, const std::string& catalogue = {});
// The same from case-file text in memory (the Python API's Case.from_dict); `name` stands for the file in messages.
CaseDefinition load_case_text(const std::string& text, const std::string& name, const std::string& catalogue = {});

// A strand bent in cycles: a strand case with a cyclic step (its bending results and profiles are written).
bool has_cyclic_strand_step(const CaseDefinition& c);

}  // namespace strandfem
