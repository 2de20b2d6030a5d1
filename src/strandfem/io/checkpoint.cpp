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
constexpr int kFormatVersion = 2;
}  // namespace

std::string case_fingerprint(const CaseDefinition& c) {
  // The case file's text as parsed (comments and layout do not count), without its solver and output blocks.
  YAML::Node root = YAML::Load(c.resolved.value("case", std::string()));
  if (root.IsMap()) {
    root.remove("solver");
    root.remove("output");
  }
  YAML::Emitter emitter;
  emitter << root;
  const std::string text = emitter.c_str();
  std::uint64_t hash = 14695981039346656037ULL;
  for (const unsigned char byte : text) hash = (hash ^ byte) * 1099511628211ULL;
  return fmt::format("{:016x}", hash);
}

void write_checkpoint(const std::filesystem::path& directory, const CaseDefinition& c, const ResultWriter& writer,
                      const StaticAnalysis& analysis) {
  ArchiveWriter out;
  out.string(kMagic);
  out.value(kFormatVersion);
  out.string(case_fingerprint(c));
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
  const int version = reader.value<int>();
  if (version != kFormatVersion && !(version == 1 && !has_cyclic_strand_step(c)))
    throw ArchiveError(path.string() + " was written by another version of StrandFEM (checkpoint format differs)");
  if (reader.string() != case_fingerprint(c))
    throw ArchiveError(path.string() + " was written for another case, or this case file changed since: resume needs the same case");
  return reader;
}

}  // namespace strandfem
