// Writes a run's results folder: history.csv, displacements.csv, summary.json, result.pvd + .vtu files (and
// through its helpers contacts.csv and wires.csv).
#pragma once
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "strandfem/io/bending_writer.hpp"
#include "strandfem/io/case_file.hpp"
#include "strandfem/io/contact_writer.hpp"
#include "strandfem/io/output_file.hpp"
#include "strandfem/io/profile_writer.hpp"
#include "strandfem/io/wire_writer.hpp"
#include "strandfem/solver/static_analysis.hpp"

namespace strandfem {

// One row of history.csv, derived from a converged state.
struct HistoryRow {
  int step = 0, increment = 0;
  double load_factor = 0, axial_strain = 0, axial_force = 0, torque = 0, end_rotation = 0;
  double transverse_load = 0, midspan_deflection = 0;
  Vec3 monitor_displacement = Vec3::Zero();
  Vec3 monitor_force = Vec3::Zero();  // internal force at the monitor node: the reaction where it is driven
  int iterations = 0;
  double residual_norm = 0;
  int case_step = 0;        // 1-based step of the case file (cyclic steps expand into several ramps)
  int cycle = 0;            // 1-based cycle of a cyclic step, 0 otherwise
  bool returning = false;   // on the half of the cycle that goes back
};

HistoryRow history_row(const CaseDefinition& c, const StaticAnalysis& analysis, const IncrementReport& report);

// summary.json of a results folder; an empty object where there is none or it does not parse.
nlohmann::json read_summary(const std::filesystem::path& folder);

// True for the names of files a run writes (history.csv, summary.json, result_00012.vtu, their .tmp forms...):
// the only files a new run removes from its folder.
bool is_result_file_name(std::string name);

class ResultWriter {
 public:
  // Takes the folder over before the analysis starts: creates it, removes the result files an earlier run left
  // (StrandFEM's own names only, see is_result_file_name), writes summary.json with status "running" and the
  // history.csv header. Every write error, here and later, throws OutputError naming the file.
  // With `resuming`, the folder keeps its files (a resumed run continues them): restore_state then reopens the
  // appended files where the checkpoint stood.
  ResultWriter(std::filesystem::path directory, const CaseDefinition& c, nlohmann::json model_info, bool resuming = false);
  // Appends the history row (flushed, so a failed run keeps what converged) and, every n-th
  // increment, a ParaView file.
  void on_increment(const StaticAnalysis& analysis, const IncrementReport& report);
  // Final displacements, the last ParaView frame (if not written yet) and summary.json.
  void finish(const StaticAnalysis& analysis, const AnalysisStatus& status, double wall_seconds);
  // After --stop-after: summary.json says "stopped", with the wall time of this invocation and the results so far
  // (solver statistics, energies, contacts, the bending loops and checks of the peaks reached).
  void record_stop(const StaticAnalysis& analysis, double wall_seconds);
  // After an error that ends the run: summary.json with this status and message, if it can still be written.
  void record_failure(const std::string& status, const std::string& message) noexcept;
  const std::vector<HistoryRow>& rows() const { return rows_; }
  // Checkpoints: the appended files' lengths and what the writers keep in memory (rows, frames, loops so far).
  void save_state(ArchiveWriter& out) const;
  void restore_state(ArchiveReader& in);

 private:
  void write_vtu(const StaticAnalysis& analysis, double time);
  void write_pvd() const;
  // summary.json's content but its status: the model, this invocation's run and its derived results.
  nlohmann::json run_summary(const StaticAnalysis& analysis, double wall_seconds);
  void write_summary(const nlohmann::json& summary) const;

  std::filesystem::path directory_;
  const CaseDefinition& case_;
  nlohmann::json model_info_;
  AppendedFile history_;
  ContactWriter contacts_;
  WireWriter wires_;
  BendingWriter bending_;
  ProfileWriter profiles_;
  std::vector<HistoryRow> rows_;
  std::vector<std::pair<double, std::string>> frames_;
  int increments_seen_ = 0;
  bool last_written_ = false;
};

}  // namespace strandfem
