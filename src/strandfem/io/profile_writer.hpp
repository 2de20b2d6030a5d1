// Writes the bending profiles of cyclic strand cases at each cycle's peak load (post/bending_profiles.hpp):
// wire_profiles.csv (axial force F and its change since V = 0 at every wire node) and contact_profiles.csv
// (P, Q, slip, their changes and the status map at every contact point), and summarizes them per interface.
#pragma once
#include <filesystem>
#include <nlohmann/json.hpp>

#include "strandfem/core/archive.hpp"
#include "strandfem/io/case_file.hpp"
#include "strandfem/io/output_file.hpp"
#include "strandfem/post/bending_profiles.hpp"
#include "strandfem/solver/static_analysis.hpp"

namespace strandfem {

class ProfileWriter {
 public:
  // Active for strand cases with a cyclic step; otherwise every call does nothing.
  ProfileWriter(const std::filesystem::path& directory, const CaseDefinition& c, bool resuming = false);
  bool active() const { return active_; }
  void on_increment(const StaticAnalysis& analysis, const IncrementReport& report);
  // Per cycle and contact interface: map status counts and mean P, Q at the peak.
  nlohmann::json summary() const { return summary_; }
  void save_state(ArchiveWriter& out) const;
  void restore_state(ArchiveReader& in);

 private:
  void write(const BendingProfiles& profiles);

  std::filesystem::path directory_;
  const CaseDefinition& case_;
  bool active_ = false;
  double load_angle_degrees_ = 90;  // direction of the cyclic transverse load in the cross-section
  AppendedFile wires_, contacts_;
  LoadingHalfTracker tracker_;
  nlohmann::json summary_ = nlohmann::json::array();
};

}  // namespace strandfem
