// Runs the strandfem program on a case and reads its results (verification tests go through the program).
#pragma once
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace strandfem::verification {

struct ProgramRun {
  int exit_code = -1;
  std::string stderr_text;
  std::filesystem::path output;
};

inline std::string case_path(const std::string& relative) { return std::string(STRANDFEM_SOURCE_DIR) + "/" + relative; }

// `launcher` goes before the program (e.g. "mpiexec -np 2").
inline ProgramRun run_program(const std::string& arguments, const std::string& tag, const std::string& launcher = "") {
  ProgramRun r;
  r.output = std::filesystem::path(::testing::TempDir()) / ("strandfem_" + tag);
  std::filesystem::remove_all(r.output);
  std::filesystem::create_directories(r.output);
  const std::string err = (r.output / "stderr.txt").string();
  const std::string command = (launcher.empty() ? "" : launcher + " ") + STRANDFEM_BINARY + " " + arguments + " > " + (r.output / "stdout.txt").string() + " 2> " + err;
  const int status = std::system(command.c_str());
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(err);
  std::stringstream ss;
  ss << in.rdbuf();
  r.stderr_text = ss.str();
  return r;
}

#ifdef STRANDFEM_MPIEXEC
// Two processes, unbound (Open MPI binds each rank to one core by default, which would leave rank 0's element
// threads a single core), allowed where the tests run as root or on fewer cores.
inline const std::string kTwoProcesses = std::string("OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ") +
                                         STRANDFEM_MPIEXEC + " --bind-to none --oversubscribe -np 2";
#endif

inline ProgramRun run_case(const std::string& case_file, const std::string& tag, const std::string& extra = "") {
  // run_program() empties the folder strandfem_<tag>; the program writes its results folder inside it.
  const auto results = std::filesystem::path(::testing::TempDir()) / ("strandfem_" + tag) / "results";
  return run_program("run " + case_path(case_file) + " -q -o " + results.string() + " " + extra, tag);
}

// CSV as a list of rows keyed by column name; text fields (kind, status) read as NaN, see read_csv_text.
inline std::vector<std::map<std::string, double>> read_csv(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  std::vector<std::string> names;
  std::vector<std::map<std::string, double>> rows;
  if (!std::getline(in, line)) return rows;
  std::stringstream header(line);
  for (std::string name; std::getline(header, name, ',');) names.push_back(name);
  while (std::getline(in, line)) {
    std::stringstream fields(line);
    std::map<std::string, double> row;
    std::size_t k = 0;
    for (std::string v; std::getline(fields, v, ',') && k < names.size(); ++k) {
      char* end = nullptr;
      const double x = std::strtod(v.c_str(), &end);
      row[names[k]] = (end != v.c_str() && *end == '\0') ? x : std::nan("");
    }
    rows.push_back(row);
  }
  return rows;
}

// The history.csv increment at which the axial strain equals `strain` (-1: none).
inline int increment_at_strain(const std::vector<std::map<std::string, double>>& history, double strain) {
  for (const auto& r : history)
    if (std::abs(r.at("axial_strain") - strain) < 1e-9) return static_cast<int>(r.at("increment"));
  return -1;
}

// Mean line force on the core (wire_b 0) over 50 <= z <= 150 mm, away from the end planes, at an increment of
// contacts.csv: the paper's Table 2 quantity (N/mm); NaN when no such point is closed.
inline double core_wire_line_force(const std::vector<std::map<std::string, double>>& contacts, int increment) {
  double sum = 0;
  int count = 0;
  for (const auto& p : contacts)
    if (p.at("increment") == increment && p.at("wire_b") == 0 && p.at("z_mm") >= 50 && p.at("z_mm") <= 150)
      sum += p.at("normal_force"), ++count;
  return count > 0 ? sum / count : std::nan("");
}

// One text column of a CSV file, row by row.
inline std::vector<std::string> read_csv_text(const std::filesystem::path& file, const std::string& column) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  std::stringstream header(line);
  int index = -1, k = 0;
  for (std::string name; std::getline(header, name, ','); ++k)
    if (name == column) index = k;
  std::vector<std::string> values;
  while (index >= 0 && std::getline(in, line)) {
    std::stringstream fields(line);
    std::string v;
    for (int i = 0; i <= index; ++i) std::getline(fields, v, ',');
    values.push_back(v);
  }
  return values;
}

}  // namespace strandfem::verification
