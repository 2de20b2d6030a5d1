// Section results along the wires: DIR/wires.csv, one row per wire node per selected increment.
#pragma once
#include <filesystem>
#include <fstream>

#include "strandfem/core/archive.hpp"
#include "strandfem/io/case_file.hpp"
#include "strandfem/io/output_file.hpp"
#include "strandfem/solver/static_analysis.hpp"

namespace strandfem {

class WireWriter {
 public:
  // resuming: the file is left alone until restore_state reopens it where the checkpoint stood.
  WireWriter(const std::filesystem::path& directory, const CaseDefinition& c, bool resuming = false);
  // Rows for this converged increment when selected (every output.contacts_every-th, and the last of each step).
  void on_increment(const StaticAnalysis& analysis, const IncrementReport& report, int increment_count, double load_factor);
  void save_state(ArchiveWriter& out) const;
  void restore_state(ArchiveReader& in);

 private:
  std::filesystem::path directory_;
  const CaseDefinition& case_;
  AppendedFile csv_;
};

}  // namespace strandfem
