// A sweep: a family of cases (case files, or one case with one key over values) each run into its own results
// folder under one folder, and sweep.csv with one row per variant.
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace strandfem {

struct SweepDefinition {
  std::vector<std::string> cases;     // case files; with `key`, exactly one
  std::string key;                    // the key varied (dot-separated), or empty
  std::vector<std::string> values;    // its values
  std::vector<std::string> settings;  // KEY=VALUE set in every variant
  std::string output_dir;
  std::string catalogue;              // --catalogue: a conductor catalogue searched before the shipped one
};

struct SweepVariant {
  std::string name;       // its results folder under output_dir
  std::string value;      // of the key, or empty
  std::string case_file;  // the file it runs (under output_dir/cases where the sweep wrote it)
  int exit_code = -1;
};

// Every variant is read and checked before any runs (CaseError otherwise). Under mpiexec the processes take the
// variants from one queue, and rank 0 writes the case files and sweep.csv; the folder must be shared.
// run_variant solves one variant into output_dir/<name> and returns its exit code; `progress` gets a line as each
// variant starts and ends. Returns the variants with their exit codes (on every rank).
std::vector<SweepVariant> run_sweep(const SweepDefinition& sweep, const std::function<int(const SweepVariant&)>& run_variant,
                                    const std::function<void(const std::string&)>& progress);

// 0 when every variant converged, else the first failure's exit code.
int sweep_exit_code(const std::vector<SweepVariant>& variants);

}  // namespace strandfem
