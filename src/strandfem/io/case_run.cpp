#include "strandfem/io/case_run.hpp"

#include <chrono>
#include <optional>

#include "strandfem/io/checkpoint.hpp"
#include "strandfem/io/output_file.hpp"
#include "strandfem/io/result_writer.hpp"

namespace strandfem {
namespace {
struct StopRequested {};  // unwinds the analysis after stop_after increments, as a signal would end the process
}  // namespace

CaseRunResult run_case(CaseDefinition& c, const std::filesystem::path& directory, nlohmann::json model_info,
                       const CaseRunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  // A checkpoint is checked against this case before anything in the folder changes.
  std::optional<ArchiveReader> checkpoint;
  if (options.resume) checkpoint = open_checkpoint(directory, c);
  model_info["resumed"] = options.resume;
  // The folder is taken over (old results removed, summary.json "running", history.csv header) before the
  // analysis is set up, so that a run stopped at any point leaves only its own files. A resumed run keeps them.
  ResultWriter writer(directory, c, model_info, options.resume);
  CaseRunResult result;
  try {
    StaticAnalysis analysis(c.model);
    if (checkpoint) {
      writer.restore_state(*checkpoint);
      analysis.restore_state(*checkpoint);
      if (options.on_resume) options.on_resume(static_cast<int>(writer.rows().size()));
    }
    int increments = 0;
    auto on_increment = [&](const IncrementReport& r) {
      writer.on_increment(analysis, r);
      if (c.output.checkpoint) write_checkpoint(directory, c, writer, analysis);
      if (options.on_increment) options.on_increment(r);
      if (options.stop_after > 0 && ++increments >= options.stop_after) throw StopRequested{};
      if (options.stop_requested && options.stop_requested()) throw StopRequested{};
    };
    std::function<void(const IncrementReport&)> on_progress = options.on_progress;
    if (options.stop_requested)
      on_progress = [&](const IncrementReport& r) {
        if (options.on_progress) options.on_progress(r);
        if (options.stop_requested()) throw StopRequested{};
      };
    try {
      result.status = analysis.run(on_increment, on_progress ? on_progress : nullptr);
    } catch (const StopRequested&) {
      result.stopped = true;
      result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      writer.record_stop(analysis, result.wall_seconds);
      return result;
    }
    result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    writer.finish(analysis, result.status, result.wall_seconds);
    return result;
  } catch (const OutputError& e) {
    writer.record_failure("output_error", e.what());
    throw;
  } catch (const std::exception& e) {
    writer.record_failure("failed", e.what());
    throw;
  }
}

}  // namespace strandfem
