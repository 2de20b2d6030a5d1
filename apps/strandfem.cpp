// strandfem: command-line front end (run a case, or print its model sizes and analytic references).
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <fstream>
#include <iostream>
#include <sstream>
#include <new>
#include <omp.h>
#include <malloc.h>
#include <unistd.h>

#include "strandfem/io/case_file.hpp"
#include "strandfem/io/conductor_catalogue.hpp"
#include "strandfem/io/case_keys.hpp"
#include "strandfem/core/archive.hpp"
#include "strandfem/io/case_run.hpp"
#include "strandfem/io/case_sweep.hpp"
#include "strandfem/io/output_file.hpp"
#include "plot_scripts.hpp"
#include "strandfem/analysis/load_protocol.hpp"
#include "strandfem/post/model_report.hpp"
#include "strandfem/post/run_report.hpp"
#include "strandfem/solver/blas_kernels.hpp"
#include "strandfem/solver/mumps_processes.hpp"
#include "strandfem/solver/process_queue.hpp"
#include "strandfem/io/result_writer.hpp"

#include "strandfem_git_revision.hpp"  // generated at build time (cmake/GitRevision.cmake)

namespace {

// Exit codes (README): 0 done, 1 internal error (a bug), 2 bad input, 3 not converged, 4 results not written,
// 5 stopped on request (--stop-after; --resume continues).
constexpr int kExitInternalError = 1;
constexpr int kExitBadInput = 2;
constexpr int kExitNotConverged = 3;
constexpr int kExitOutputError = 4;
constexpr int kExitStopped = 5;

nlohmann::json build_info() {
  return {{"git_revision", STRANDFEM_GIT_REVISION}, {"compiler", __VERSION__}, {"instruction_set", STRANDFEM_INSTRUCTION_SET},
          {"version", STRANDFEM_VERSION}};
}

// Threads for element evaluation: -t over solver.threads, 0 meaning OpenMP's default. More than the machine's
// processors only contend (and thousands fail to start): such a count is capped there, with a warning.
int resolve_threads(int asked, const std::string& source) {
  const int processors = omp_get_num_procs();
  if (asked > processors) {
    std::cerr << "warning: " << source << " asks for " << asked << " threads; this machine has " << processors
              << " processors, using " << processors << "\n";
    return processors;
  }
  return asked > 0 ? asked : omp_get_max_threads();
}

// ", 1/4 of the nominal increment after 2 cut-backs" for an increment smaller than the step's nominal one.
std::string increment_size_note(const strandfem::IncrementReport& r) {
  const std::string searched = std::string(r.searched_recovery ? ", with line search" : "") + (r.stabilized ? ", stabilized" : "");
  if (r.relative_size > 1 - 1e-9) return searched;
  const double inverse = 1 / r.relative_size;
  char size[32];
  if (std::abs(inverse - std::round(inverse)) < 1e-6) std::snprintf(size, sizeof size, "1/%.0f", inverse);
  else std::snprintf(size, sizeof size, "%.3g", r.relative_size);
  std::string note = std::string(", ") + size + " of the nominal increment";
  if (r.cutbacks > 0) note += " after " + std::to_string(r.cutbacks) + (r.cutbacks == 1 ? " cut-back" : " cut-backs");
  return note + searched;
}

// The verbose line of one Newton iteration: its residual and what preceded it (a correction, cut or whole, or a
// round of contact changes or stick offsets), or why the attempt gave up.
std::string iteration_line(const strandfem::IncrementReport& r) {
  std::ostringstream line;
  line << "  step " << r.step + 1 << " increment " << r.increment;
  if (r.failure != strandfem::AttemptFailure::kNone) {
    line << ": attempt at fraction " << r.step_fraction << " gave up after " << r.corrections << " corrections: "
         << strandfem::describe(r.failure)
         << (r.kept_converged_round ? "; the increment keeps its iterate before the last stick augmentation round" : "");
    return line.str();
  }
  line << " iteration " << r.iterations << ": relative residual " << r.residual_norm;
  if (r.state_changes > 0) return line.str() + " after a contact round (" + std::to_string(r.state_changes) + " state changes)";
  if (r.augmented_points > 0)
    return line.str() + " after a stick augmentation round (" + std::to_string(r.augmented_points) + " points)";
  line << ", correction / increment motion " << r.correction_ratio;
  if (r.step_length < 1) line << ", step length " << r.step_length << (r.step_limited ? " (contact step control)" : " (line search)");
  return line.str();
}

// How far a run is through its load protocol, in nominal increments, and an estimate of the time left from the
// pace since the first increment this invocation converged.
class RunProgress {
 public:
  explicit RunProgress(const std::vector<strandfem::LoadStep>& steps) {
    for (const strandfem::LoadRamp& ramp : strandfem::expand_load_steps(steps)) {
      ramp_start_.push_back(total_);
      ramp_size_.push_back(ramp.increments);
      total_ += ramp.increments;
    }
  }
  std::string note(const strandfem::IncrementReport& r) {
    const auto now = std::chrono::steady_clock::now();
    const std::size_t k = static_cast<std::size_t>(r.step);
    const double done = k < ramp_size_.size() && total_ > 0 ? (ramp_start_[k] + r.step_fraction * ramp_size_[k]) / total_ : 1.0;
    if (!first_) {
      first_ = true;
      first_done_ = done;
      first_time_ = now;
    }
    std::string text = fmt::format("; {:.0f} % of the run", 100 * done);
    const double seconds = std::chrono::duration<double>(now - first_time_).count();
    if (done > first_done_ && done < 1) {
      const double left = seconds * (1 - done) / (done - first_done_);
      text += left < 90 ? fmt::format(", about {:.0f} s left", left) : fmt::format(", about {:.0f} min left", left / 60);
    }
    return text;
  }

 private:
  std::vector<double> ramp_start_, ramp_size_;
  double total_ = 0, first_done_ = 0;
  bool first_ = false;
  std::chrono::steady_clock::time_point first_time_;
};

// A results folder's summary.json; an empty object where there is none or it cannot be read.
// The end-of-run report on stdout, from the summary.json the run has just written.
void print_report(const std::string& output_dir) {
  const nlohmann::json summary = strandfem::read_summary(output_dir);
  if (summary.empty()) return;
  std::cout << strandfem::end_of_run_report(summary) << "results in " << output_dir << "\n";
}

int run_case_file(const std::string& case_path, const std::string& catalogue, const std::string& output_dir, int threads, bool quiet,
                  bool verbose, bool plots, bool resume, int stop_after, int dump_tangent = 0) {
  strandfem::CaseDefinition c = strandfem::load_case(case_path, catalogue);
  if (dump_tangent > 0) {
    c.model.options.dump_tangent_factorization = dump_tangent;
    c.model.options.dump_tangent_path = (std::filesystem::path(output_dir) / ("tangent_" + std::to_string(dump_tangent) + ".bin")).string();
  }
  for (const auto& w : c.warnings) std::cerr << "warning: " << w << "\n";
  const bool from_command_line = threads > 0;
  c.model.options.threads = resolve_threads(from_command_line ? threads : c.model.options.threads,
                                            from_command_line ? "-t" : "solver.threads");
  c.resolved["solver"]["threads"] = c.model.options.threads;  // the count used, whatever asked for it
  nlohmann::json info = strandfem::model_report(c);
  info["build"] = build_info();
  info["threads"] = c.model.options.threads;
  const int step_count = static_cast<int>(c.model.steps.size());
  strandfem::CaseRunOptions options;
  options.resume = resume;
  options.stop_after = stop_after;
  options.on_resume = [&](int increments) {
    if (!quiet) std::cerr << "resuming after increment " << increments << " from " << output_dir << "\n";
  };
  RunProgress progress(c.model.steps);
  options.on_increment = [&](const strandfem::IncrementReport& r) {
    if (!quiet)
      std::cerr << "step " << r.origin.step + 1 << "/" << step_count << " '" << r.step_name << "' increment " << r.increment
                << " (fraction " << r.step_fraction << increment_size_note(r) << "): " << r.iterations << " iterations, residual "
                << r.residual_norm << progress.note(r) << "\n";
  };
  if (verbose)
    options.on_progress = [&](const strandfem::IncrementReport& r) { std::cerr << iteration_line(r) << "\n"; };
  const strandfem::CaseRunResult result = strandfem::run_case(c, output_dir, info, options);
  if (result.stopped) {
    if (!quiet) std::cerr << "stopped after " << stop_after << " increments as asked; --resume continues from " << output_dir << "\n";
    return kExitStopped;
  }
  if (plots) strandfem_app::draw_figures("plot_bending.py", output_dir);
  if (!quiet) print_report(output_dir);
  if (!result.status.converged) {
    std::cerr << "error: " << result.status.message << "\nconverged results so far are in " << output_dir << "\n";
    return kExitNotConverged;
  }
  return 0;
}

// strandfem sweep: the variants through run_case_file, then (rank 0) their curves on one plot.
int run_sweep_command(const strandfem::SweepDefinition& sweep, int threads, bool quiet) {
  namespace fs = std::filesystem;
  const auto variants = strandfem::run_sweep(
      sweep,
      [&](const strandfem::SweepVariant& v) {
        return run_case_file(v.case_file, sweep.catalogue, (fs::path(sweep.output_dir) / v.name).string(), threads, true, false, false, false, 0);
      },
      [&](const std::string& line) {
        if (!quiet) std::cerr << line << "\n";
      });
  if (strandfem::process_rank() == 0) {
    strandfem_app::draw_figures("plot_sweep.py", sweep.output_dir);
    if (!quiet) std::cerr << "sweep of " << variants.size() << " cases in " << sweep.output_dir << " (sweep.csv, sweep.png)\n";
  }
  return strandfem::sweep_exit_code(variants);
}

// strandfem conductors: a table of the catalogue (a user's file first), one conductor per row.
int list_conductors(const std::string& catalogue) {
  const std::vector<std::vector<std::string>> rows = strandfem::conductor_summary_table(catalogue);
  std::vector<std::size_t> widths(rows.front().size(), 0);
  for (const auto& row : rows)
    for (std::size_t i = 0; i < row.size(); ++i) widths[i] = std::max(widths[i], row[i].size());
  for (const auto& row : rows) {
    for (std::size_t i = 0; i < row.size(); ++i)
      std::cout << (i == 0 ? "" : "  ") << (i < 2 ? std::left : std::right) << std::setw(static_cast<int>(widths[i])) << row[i];
    std::cout << "\n";
  }
  return std::cout ? 0 : kExitOutputError;
}

// OpenBLAS chooses its kernels once, when it loads: to use faster ones than it picked, the program restarts itself
// once with OPENBLAS_CORETYPE set (which stops a second restart). exec returns only on failure, and the run then
// goes on with the kernels that loaded.
void use_faster_blas_kernels(char** argv) {
  const std::string core = strandfem::preferred_openblas_core(strandfem::blas_core_name(),
                                                              strandfem::cpu_has_skylakex_instructions(),
                                                              std::getenv("OPENBLAS_CORETYPE") != nullptr);
  if (core.empty()) return;
  setenv("OPENBLAS_CORETYPE", core.c_str(), 1);
  execv("/proc/self/exe", argv);
}

// MUMPS allocates its fronts and factors (hundreds of MB for a strand's tangent) at every factorization and frees
// them after it. glibc serves blocks that large with mmap and gives them back with munmap, so every factorization
// would fault in and zero all of that memory again, a quarter of a 1 m bending run's CPU time in the kernel
// (docs/performance.md, "Memory"). From the heap, and never trimmed back,
// the same memory serves the next factorization; the price is that the resident size stays at its peak.
void keep_freed_memory() {
  mallopt(M_MMAP_MAX, 0);            // no block of its own mapping: everything from the heap
  mallopt(M_TRIM_THRESHOLD, -1);     // never give the heap's top back to the system
  mallopt(M_TOP_PAD, 64 << 20);      // grow the heap 64 MB at a time
}

}  // namespace

int main(int argc, char** argv) {
  use_faster_blas_kernels(argv);
  keep_freed_memory();
  // Under `mpirun -np N` (MPI build of MUMPS) ranks above 0 only take part in rank 0's factorizations and solves.
  // `mpiexec -n N strandfem sweep`: every process runs variants of its own instead.
  const bool sweep_command = argc > 1 && std::string(argv[1]) == "sweep";
  strandfem::MumpsProcesses processes(argc, argv, sweep_command);
  if (processes.serving() && processes.rank() > 0) return processes.serve();
  CLI::App app{"StrandFEM: finite elements for multilayered helical wire strands"};
  app.set_version_flag("--version", STRANDFEM_VERSION);
  app.require_subcommand(1);
  std::string case_path, output_dir = "results", catalogue;
  const char* catalogue_help = "A conductor catalogue (CSV, the columns of share/strandfem/data/conductors.csv) searched before the shipped one";
  int threads = 0, stop_after = 0, dump_tangent = 0;
  bool quiet = false, verbose = false, plots = false, resume = false;
  auto* run = app.add_subcommand("run", "Solve a case and write its results folder");
  run->add_option("case", case_path, "Case file (YAML)")->required();
  run->add_option("-o,--output", output_dir, "Results folder (created if needed)");
  run->add_option("-t,--threads", threads, "OpenMP threads for element evaluation (0: default)")->check(CLI::NonNegativeNumber);
  run->add_flag("-q,--quiet", quiet, "No progress lines and no end-of-run report");
  run->add_flag("-v,--verbose", verbose, "A progress line per Newton iteration");
  run->add_flag("--resume", resume, "Continue the run in the results folder from its last converged increment (its checkpoint.bin)");
  run->add_option("--stop-after", stop_after,
                  "Stop after this many converged increments (of this invocation), exit code 5; --resume continues")
      ->check(CLI::Range(1, 1000000000));  // PositiveNumber's message prints the double's range, 300 digits
  run->add_option("--dump-tangent", dump_tangent,
                  "Write the tangent of this invocation's K-th factorization to OUTPUT/tangent_K.bin (for bench/tangent_bench)")
      ->check(CLI::Range(1, 1000000000));
  run->add_option("--catalogue", catalogue, catalogue_help)->check(CLI::ExistingFile);
  run->add_flag("--plots", plots, "Draw the results' figures (PNG, into the results folder; needs python3-matplotlib)");
  std::vector<std::string> sweep_cases, sweep_values, sweep_settings;
  std::string sweep_key;
  auto* sweep = app.add_subcommand("sweep", "Run a family of cases (case files, or one case with one key over values) and plot their curves together");
  sweep->add_option("cases", sweep_cases, "Case files (YAML); with --key, exactly one")->required();
  sweep->add_option("-o,--output", output_dir, "Folder of the sweep: a results folder per case, sweep.csv, sweep.png");
  sweep->add_option("--key", sweep_key, "Key to vary, dot-separated (e.g. contact.friction, strand.layers.1.lay_angle)");
  sweep->add_option("--values", sweep_values, "Values of the key, comma-separated (e.g. 0.5,0.7,0.9)")->delimiter(',');
  sweep->add_option("--set", sweep_settings, "KEY=VALUE set in every variant (repeatable), e.g. contact.friction_direction=slave_wire");
  sweep->add_option("-t,--threads", threads, "OpenMP threads for element evaluation (0: default)")->check(CLI::NonNegativeNumber);
  sweep->add_flag("-q,--quiet", quiet, "No progress lines");
  sweep->add_option("--catalogue", catalogue, catalogue_help)->check(CLI::ExistingFile);
  auto* info = app.add_subcommand("info", "Print model sizes and analytic references as JSON, without solving");
  info->add_option("case", case_path, "Case file (YAML)")->required();
  info->add_option("--catalogue", catalogue, catalogue_help)->check(CLI::ExistingFile);
  double ps_tension = 0, ps_yb = 0;
  auto* ps_tension_option = info->add_option("--tension", ps_tension, "With --yb: the tension (N) of the Poffenberger–Swart stress")
                                ->check(CLI::PositiveNumber);
  auto* ps_yb_option = info->add_option("--yb", ps_yb, "Peak-to-peak bending amplitude (mm) at 89 mm from the last point of contact: adds the Poffenberger–Swart "
                                  "stress of the outer wires (`poffenberger_swart`)")
      ->check(CLI::PositiveNumber)
      ->needs(ps_tension_option);
  ps_tension_option->needs(ps_yb_option);
  auto* conductors = app.add_subcommand("conductors", "List the conductor catalogue: construction, area, mass, EImax and EImin of each conductor");
  conductors->add_option("--catalogue", catalogue, catalogue_help + std::string(" (listed before it)"))->check(CLI::ExistingFile);
  auto* keys = app.add_subcommand("keys", "Print every case-file key with type, range, default and meaning (the rows of docs/case-files.md)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : kExitBadInput;
  }
  try {
    if (info->parsed()) {
      const strandfem::CaseDefinition c = strandfem::load_case(case_path, catalogue);
      for (const auto& w : c.warnings) std::cerr << "warning: " << w << "\n";
      nlohmann::json report = strandfem::model_report(c);
      if (ps_yb > 0) {
        if (!c.strand) throw strandfem::CaseError(case_path + ": --yb needs a strand case");
        report["poffenberger_swart"] = strandfem::poffenberger_swart_report(*c.strand, ps_tension, ps_yb);
      }
      std::cout << report.dump(2) << "\n" << std::flush;
      if (!std::cout) {
        std::cerr << "error: cannot write the report to standard output\n";
        return kExitOutputError;
      }
      return 0;
    }
    if (conductors->parsed()) return list_conductors(catalogue);
    if (keys->parsed()) {
      std::cout << "| key | type, unit, range | default | meaning |\n|---|---|---|---|\n";
      for (const std::string& row : strandfem::setting_key_rows(strandfem::KeySection::kPhysics)) std::cout << row << "\n";
      std::cout << "\n| key | type, unit, range | default | meaning | when to touch |\n|---|---|---|---|---|\n";
      for (const std::string& row : strandfem::setting_key_rows(strandfem::KeySection::kAdvanced)) std::cout << row << "\n";
      return std::cout ? 0 : kExitOutputError;
    }
    if (sweep->parsed()) return run_sweep_command({sweep_cases, sweep_key, sweep_values, sweep_settings, output_dir, catalogue}, threads, quiet);
    return run_case_file(case_path, catalogue, output_dir, threads, quiet, verbose, plots, resume, stop_after, dump_tangent);
  } catch (const strandfem::CaseError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::invalid_argument& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const strandfem::OutputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitOutputError;
  } catch (const strandfem::ArchiveError& e) {
    std::cerr << "error: cannot resume: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::bad_alloc&) {
    std::cerr << "error: out of memory\n";
    return kExitInternalError;
  } catch (const std::exception& e) {
    std::cerr << "internal error: " << e.what() << "\n";
    return kExitInternalError;
  }
}
