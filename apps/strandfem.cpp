// strandfem: command-line front end (run a case, or print its model sizes and analytic references).
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <iostream>
#include <new>
#include <omp.h>

#include "strandfem/io/case_file.hpp"
#include "strandfem/core/archive.hpp"
#include "strandfem/io/case_run.hpp"
#include "strandfem/io/output_file.hpp"
#include "strandfem/post/model_report.hpp"

#ifndef STRANDFEM_GIT_REVISION
#define STRANDFEM_GIT_REVISION "unknown"
#endif

namespace {

// Exit codes (README): 0 done, 1 internal error (a bug), 2 bad input, 3 not converged, 4 results not written,
// 5 stopped on request (--stop-after; --resume continues).
constexpr int kExitInternalError = 1;
constexpr int kExitBadInput = 2;
constexpr int kExitNotConverged = 3;
constexpr int kExitOutputError = 4;
constexpr int kExitStopped = 5;

nlohmann::json build_info() {
  return {{"git_revision", STRANDFEM_GIT_REVISION}, {"compiler", __VERSION__}, {"version", "0.1.0"}};
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

// --plots: the figures of a results folder, drawn by the plotting scripts of the source tree (Debian's /usr/bin/python3 with
// matplotlib). A missing or failing plotter is a warning: the results themselves are complete.
void draw_plots(const std::string& output_dir) {
  const std::string command = std::string("/usr/bin/python3 '") + STRANDFEM_SCRIPTS_DIR + "/plot_bending.py' '" +
                              output_dir + "' > /dev/null";
  if (std::system(command.c_str()) != 0) std::cerr << "warning: plotting failed (" << command << ")\n";
}

int run_case_file(const std::string& case_path, const std::string& output_dir, int threads, bool quiet, bool verbose,
             bool plots, bool resume, int stop_after) {
  strandfem::CaseDefinition c = strandfem::load_case(case_path);
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
  options.on_increment = [&](const strandfem::IncrementReport& r) {
    if (!quiet)
      std::cerr << "step " << r.origin.step + 1 << "/" << step_count << " '" << r.step_name << "' increment " << r.increment
                << " (fraction " << r.step_fraction << "): " << r.iterations << " iterations, residual " << r.residual_norm
                << "\n";
  };
  if (verbose)
    options.on_progress = [&](const strandfem::IncrementReport& r) {
      std::cerr << "  step " << r.step + 1 << " increment " << r.increment << " iteration " << r.iterations
                << ": relative residual " << r.residual_norm << ", correction / increment motion " << r.correction_ratio
                << "\n";
    };
  const strandfem::CaseRunResult result = strandfem::run_case(c, output_dir, info, options);
  if (result.stopped) {
    if (!quiet) std::cerr << "stopped after " << stop_after << " increments as asked; --resume continues from " << output_dir << "\n";
    return kExitStopped;
  }
  if (plots) draw_plots(output_dir);
  if (!result.status.converged) {
    std::cerr << "error: " << result.status.message << "\nconverged results so far are in " << output_dir << "\n";
    return kExitNotConverged;
  }
  if (!quiet) std::cerr << "done in " << result.wall_seconds << " s; results in " << output_dir << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"StrandFEM: finite elements for multilayered helical wire strands"};
  app.require_subcommand(1);
  std::string case_path, output_dir = "results";
  int threads = 0, stop_after = 0;
  bool quiet = false, verbose = false, plots = false, resume = false;
  auto* run = app.add_subcommand("run", "Solve a case and write its results folder");
  run->add_option("case", case_path, "Case file (YAML)")->required();
  run->add_option("-o,--output", output_dir, "Results folder (created if needed)");
  run->add_option("-t,--threads", threads, "OpenMP threads for element evaluation (0: default)")->check(CLI::NonNegativeNumber);
  run->add_flag("-q,--quiet", quiet, "No progress lines");
  run->add_flag("-v,--verbose", verbose, "A progress line per Newton iteration");
  run->add_flag("--resume", resume, "Continue the run in the results folder from its last converged increment (its checkpoint.bin)");
  run->add_option("--stop-after", stop_after,
                  "Stop after this many converged increments (of this session), exit code 5; --resume continues")
      ->check(CLI::PositiveNumber);
  run->add_flag("--plots", plots, "Draw the results' figures (PNG, into the results folder; needs python3-matplotlib)");
  auto* info = app.add_subcommand("info", "Print model sizes and analytic references as JSON, without solving");
  info->add_option("case", case_path, "Case file (YAML)")->required();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : kExitBadInput;
  }
  try {
    if (info->parsed()) {
      const strandfem::CaseDefinition c = strandfem::load_case(case_path);
      for (const auto& w : c.warnings) std::cerr << "warning: " << w << "\n";
      std::cout << strandfem::model_report(c).dump(2) << "\n" << std::flush;
      if (!std::cout) {
        std::cerr << "error: cannot write the report to standard output\n";
        return kExitOutputError;
      }
      return 0;
    }
    return run_case_file(case_path, output_dir, threads, quiet, verbose, plots, resume, stop_after);
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
