#include "strandfem/io/checkpoint.hpp"

#include <cstdint>
#include <fstream>
#include <iterator>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "strandfem/io/output_file.hpp"

namespace strandfem {
namespace {
constexpr const char* kMagic = "StrandFEM checkpoint";
// 2: cyclic strand cases add the bending profiles' state (ProfileWriter); other cases read version 1 alike.
// 3: the fingerprint leaves out the steps' cycle counts, which follow it, so that a resume may add cycles.
// 4: the same content; contacts.csv has three more columns (interface, mu1, mu2), so a run that writes it does
//    not continue one of an earlier version, whose rows have fewer.
// 5: the analysis statistics add the residual and commit times. The statistics of the earlier ones have another
//    layout.
// 6: the same content; deflection_curves.csv has one more column (eq32_ei_min_shear_mm), so a run that writes it
//    does not continue one of an earlier version.
// 7: the bending state adds each peak's check of the core's curve against eq. 3.2.
// 8: each peak's check adds the curve's rise from the load point, and deflection_curves.csv four columns.
// 9: the analysis adds the automatic stabilization's state. Only this version is read.
constexpr int kFormatVersion = 9;

std::string fnv1a_hex(const std::string& text) {
  std::uint64_t hash = 14695981039346656037ULL;
  for (const unsigned char byte : text) hash = (hash ^ byte) * 1099511628211ULL;
  return fmt::format("{:016x}", hash);
}

std::vector<int> step_cycles(const CaseDefinition& c) {
  std::vector<int> cycles;
  for (const LoadStep& step : c.model.steps) cycles.push_back(step.cycles);
  return cycles;
}

// A resume may raise the last step's cycle count (run more cycles after a finished or stopped run); any other
// change of the cycles would move load ramps that have already run.
void check_cycles(const std::vector<int>& saved, const std::vector<int>& now, const std::string& path) {
  if (saved.size() != now.size()) throw ArchiveError(path + " was written for another case: resume needs the same case");
  for (std::size_t i = 0; i < saved.size(); ++i) {
    if (saved[i] == now[i]) continue;
    const bool last = i + 1 == saved.size();
    if (last && now[i] > saved[i]) continue;
    throw ArchiveError(fmt::format("steps[{}].cycles is {} where the checkpoint in {} ran with {}: a resume may only add "
                                   "cycles to the last step",
                                   i, now[i], path, saved[i]));
  }
}
}  // namespace

// The case file's text as parsed (comments and layout do not count), without its solver and output blocks and
// without the steps' `cycles` (they follow it, so that a resume may add cycles).
std::string case_fingerprint(const CaseDefinition& c) {
  YAML::Node root = YAML::Load(c.resolved.value("case", std::string()));
  if (root.IsMap()) {
    root.remove("solver");
    root.remove("output");
    if (root["steps"] && root["steps"].IsSequence())
      for (YAML::Node step : root["steps"])
        if (step.IsMap()) step.remove("cycles");
  }
  YAML::Emitter emitter;
  emitter << root;
  return fnv1a_hex(emitter.c_str());
}

void write_checkpoint(const std::filesystem::path& directory, const CaseDefinition& c, const ResultWriter& writer,
                      const StaticAnalysis& analysis) {
  ArchiveWriter out;
  out.string(kMagic);
  out.value(kFormatVersion);
  out.string(case_fingerprint(c));
  out.vector(step_cycles(c));
  writer.save_state(out);
  analysis.save_state(out);
  WholeFile file(directory / kCheckpointFileName);
  file.stream().write(out.bytes().data(), static_cast<std::streamsize>(out.bytes().size()));
  file.commit();
}

ArchiveReader open_checkpoint(const std::filesystem::path& directory, const CaseDefinition& c) {
  const std::filesystem::path path = directory / kCheckpointFileName;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ArchiveError("nothing to resume: " + path.string() + " not found (a run writes it after each converged increment)");
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ArchiveReader reader(std::move(bytes));
  try {
    if (reader.string() != kMagic) throw ArchiveError("");
  } catch (const ArchiveError&) {
    throw ArchiveError(path.string() + " is not a StrandFEM checkpoint");
  }
  if (reader.value<int>() != kFormatVersion)
    throw ArchiveError(path.string() + " was written by another version of StrandFEM (checkpoint format differs)");
  const std::string another_case =
      path.string() + " was written for another case, or this case file changed since: resume needs the same case";
  if (reader.string() != case_fingerprint(c)) throw ArchiveError(another_case);
  check_cycles(reader.vector<int>(), step_cycles(c), path.string());
  return reader;
}

}  // namespace strandfem
