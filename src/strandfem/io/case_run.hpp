// A case solved into its results folder: the writers, the analysis and the checkpoints driven together, as the
// command-line program and the tests (and later the Python API) run them.
#pragma once
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>

#include "strandfem/io/case_file.hpp"
#include "strandfem/solver/static_analysis.hpp"

namespace strandfem {

struct CaseRunOptions {
  bool resume = false;  // continue from DIR/checkpoint.bin (ArchiveError when there is none, or not this case's)
  std::function<void(const IncrementReport&)> on_increment;  // after each converged increment is written
  std::function<void(const IncrementReport&)> on_progress;   // after each Newton iteration (none: not reported)
  std::function<void(int converged_increments)> on_resume;   // once the checkpoint has been restored
  // Stops after this many converged increments of this invocation (0: never), leaving the folder as a signal
  // would: results and checkpoint of the last converged increment, summary.json "running". For tests of resume.
  int stop_after = 0;
  // Polled after each Newton iteration and increment: true stops the run as stop_after does (Ctrl-C in Python).
  std::function<bool()> stop_requested;
};

struct CaseRunResult {
  AnalysisStatus status;
  double wall_seconds = 0;  // this invocation's
  bool stopped = false;     // by stop_after or stop_requested
};

// Solves `c` into `directory` (taken over, or continued with resume). `model_info` heads summary.json. Errors:
// OutputError (results not written), ArchiveError (nothing to resume), others from the analysis; summary.json
// records them when it can.
CaseRunResult run_case(CaseDefinition& c, const std::filesystem::path& directory, nlohmann::json model_info,
                       const CaseRunOptions& options);

}  // namespace strandfem
