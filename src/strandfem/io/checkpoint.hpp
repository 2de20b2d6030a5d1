// Checkpoints of a run: DIR/checkpoint.bin, the converged state after the last increment and the results writers'
// bookkeeping, from which `strandfem run --resume` continues as if the run had never stopped.
#pragma once
#include <filesystem>
#include <string>

#include "strandfem/core/archive.hpp"
#include "strandfem/io/case_file.hpp"
#include "strandfem/io/result_writer.hpp"
#include "strandfem/solver/static_analysis.hpp"

namespace strandfem {

inline constexpr const char* kCheckpointFileName = "checkpoint.bin";

// What a checkpoint must match: the case file as parsed (comments and layout aside), less its solver and output
// blocks, which may change between invocations (threads; tolerances or cut-backs to get past an increment that did
// not converge), and less the steps' cycle counts, which the checkpoint keeps beside it: the last step's may grow
// (more cycles after a run ended). FNV-1a of that text, in hex.
std::string case_fingerprint(const CaseDefinition& c);

// Writes DIR/checkpoint.bin whole (temporary file, then rename): a run killed while writing keeps the previous one.
void write_checkpoint(const std::filesystem::path& directory, const CaseDefinition& c, const ResultWriter& writer,
                      const StaticAnalysis& analysis);

// Opens DIR/checkpoint.bin and checks that it is one, of this format, for this case. The reader is left at the
// writers' state: ResultWriter::restore_state, then StaticAnalysis::restore_state. ArchiveError says what is wrong.
ArchiveReader open_checkpoint(const std::filesystem::path& directory, const CaseDefinition& c);

}  // namespace strandfem
