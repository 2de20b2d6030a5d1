// Contact results: DIR/contacts.csv (one row per closed contact point per selected increment) and ParaView
// point files (contacts_NNNNN.vtu, contacts.pvd) with the contact forces, slip and status as point data.
#pragma once
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "strandfem/core/archive.hpp"
#include "strandfem/io/case_file.hpp"
#include "strandfem/io/output_file.hpp"
#include "strandfem/solver/static_analysis.hpp"

namespace strandfem {

class ContactWriter {
 public:
  // resuming: the files are left alone until restore_state reopens them where the checkpoint stood.
  ContactWriter(std::filesystem::path directory, const CaseDefinition& c, bool resuming = false);
  // Rows for this converged increment when selected (every n-th, and the last of each step).
  void on_increment(const StaticAnalysis& analysis, const IncrementReport& report, int increment_count, double load_factor);
  // A ParaView file of the contact points at the current (deformed) positions.
  void write_vtu(const StaticAnalysis& analysis, const std::string& name, double time);
  // Counts for summary.json: lateral pairs, radial crossings, closed/slipping points now.
  static nlohmann::json summary(const StaticAnalysis& analysis);
  void save_state(ArchiveWriter& out) const;
  void restore_state(ArchiveReader& in);

 private:
  std::filesystem::path directory_;
  const CaseDefinition& case_;
  AppendedFile csv_;
  std::vector<std::pair<double, std::string>> frames_;
};

}  // namespace strandfem
