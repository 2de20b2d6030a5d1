// Requirement (issue 10): a run owns its results folder (it removes what an earlier run left, only StrandFEM's
// own files, and summary.json says "running" until the end), write errors end the run with exit code 4 and a
// message naming the file, whole files are never seen half written, and summary.json records the threads used,
// the BLAS kernels that ran and the commit the program was built from.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "program_runner.hpp"
#include "strandfem/solver/blas_kernels.hpp"

namespace strandfem::verification {
namespace {

namespace fs = std::filesystem;

fs::path fresh_folder(const std::string& name) {
  const fs::path p = fs::path(::testing::TempDir()) / ("results_" + name);
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

void write(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }

std::string read(const fs::path& file) {
  std::ifstream in(file);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Runs a shell command line through bash; returns the exit status.
int bash(const std::string& script) {
  const std::string command = "/bin/bash -c '" + script + "'";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(ResultsFolder, ARunRemovesOnlyTheResultFilesAnEarlierRunLeft) {
  const fs::path dir = fresh_folder("owned");
  // An earlier run with contact and more frames, plus files that are not StrandFEM's.
  for (const char* stale : {"contacts.csv", "contacts.pvd", "contacts_00003.vtu", "result_00042.vtu", "displacements.csv", "summary.json.tmp"})
    write(dir / stale, "stale");
  write(dir / "summary.json", R"({"status": "converged"})");
  for (const char* kept : {"notes.txt", "my_result.vtu", "result.pvd.bak", "result_1.vtu", "history.csv.orig"}) write(dir / kept, "mine");
  const ProgramRun r = run_program("run " + case_path("cases/examples/seven_wire_axial.yaml") + " -q -o " + dir.string(), "owned");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  for (const char* stale : {"contacts.csv", "contacts.pvd", "contacts_00003.vtu", "result_00042.vtu", "summary.json.tmp"})
    EXPECT_EQ(names.count(stale), 0u) << stale;
  for (const char* kept : {"notes.txt", "my_result.vtu", "result.pvd.bak", "result_1.vtu", "history.csv.orig"}) {
    EXPECT_EQ(names.count(kept), 1u) << kept;
    EXPECT_EQ(read(dir / kept), "mine") << kept;
  }
  EXPECT_EQ(read_csv(dir / "history.csv").size(), 10u);
  EXPECT_EQ(read_csv(dir / "displacements.csv").size(), 343u);
  EXPECT_EQ(nlohmann::json::parse(read(dir / "summary.json"))["status"], "converged");
}

// A run killed during its first increment leaves its own summary.json ("running") and history.csv header, not
// the earlier run's converged results.
TEST(ResultsFolder, AKilledRunLeavesARunningSummaryAndTheHistoryHeader) {
  const fs::path dir = fresh_folder("killed");
  write(dir / "summary.json", R"({"status": "converged"})");
  write(dir / "displacements.csv", "node\n0\n");
  write(dir / "history.csv", "step\n1\n2\n");
  const fs::path err = dir.parent_path() / "killed_stderr.txt";
  const std::string run = std::string(STRANDFEM_BINARY) + " run " + case_path("cases/paper/wire_120.yaml") + " -v -o " + dir.string();
  // Kill -9 at the first Newton iteration line (from inside the first increment).
  const int status = bash(run + " 2> " + err.string() + " & pid=$!; for i in $(seq 6000); do grep -q \"iteration 0\" " + err.string() +
                          " && break; sleep 0.01; done; kill -9 $pid; wait $pid; exit 0");
  ASSERT_EQ(status, 0);
  ASSERT_NE(read(err).find("iteration 0"), std::string::npos) << read(err);
  const nlohmann::json summary = nlohmann::json::parse(read(dir / "summary.json"));
  EXPECT_EQ(summary["status"], "running");
  EXPECT_EQ(summary["nodes"], 5400);
  EXPECT_FALSE(fs::exists(dir / "displacements.csv"));
  const std::string history = read(dir / "history.csv");
  EXPECT_EQ(history.rfind("step,increment,load_factor,", 0), 0u) << history;
  EXPECT_EQ(std::count(history.begin(), history.end(), '\n'), 1) << history;  // the header, no row yet
}

// A disk that fills up (here: a 24 KiB file-size limit with SIGXFSZ ignored, so that writes fail with EFBIG):
// exit code 4 naming the file; every complete file is whole, and no temporary file is left.
TEST(ResultsFolder, AWriteErrorEndsTheRunWithExitCode4NamingTheFile) {
  const fs::path dir = fresh_folder("full");
  const fs::path err = dir.parent_path() / "full_stderr.txt";
  const int code = bash("ulimit -f 24; trap \"\" XFSZ; exec " + std::string(STRANDFEM_BINARY) + " run " +
                        case_path("cases/examples/seven_wire_axial.yaml") + " -q -o " + dir.string() + " 2> " + err.string());
  EXPECT_EQ(code, 4) << read(err);
  EXPECT_NE(read(err).find("cannot write " + dir.string() + "/"), std::string::npos) << read(err);
  const nlohmann::json summary = nlohmann::json::parse(read(dir / "summary.json"));  // whole JSON
  EXPECT_EQ(summary["status"], "output_error");
  EXPECT_NE(summary["message"].get<std::string>().find("cannot write"), std::string::npos);
  for (const auto& e : fs::directory_iterator(dir)) {
    EXPECT_NE(e.path().extension(), ".tmp") << e.path();
    if (e.path().extension() == ".vtu" || e.path().extension() == ".pvd")
      EXPECT_NE(read(e.path()).find("</VTKFile>"), std::string::npos) << e.path();
  }
  // Every frame result.pvd lists exists.
  const std::string pvd = fs::exists(dir / "result.pvd") ? read(dir / "result.pvd") : "";
  for (std::size_t at = pvd.find("file=\""); at != std::string::npos; at = pvd.find("file=\"", at + 1)) {
    const std::string frame = pvd.substr(at + 6, pvd.find('"', at + 6) - at - 6);
    EXPECT_TRUE(fs::exists(dir / frame)) << frame;
  }
  // A results folder that cannot be created.
  const ProgramRun r = run_program("run " + case_path("cases/examples/seven_wire_axial.yaml") + " -q -o /dev/null/results", "full_folder");
  EXPECT_EQ(r.exit_code, 4) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("/dev/null/results"), std::string::npos) << r.stderr_text;
}

TEST(ResultsFolder, SummaryRecordsTheThreadsUsedAndCapsThemAtTheMachine) {
  const ProgramRun one = run_case("cases/examples/seven_wire_axial.yaml", "threads_one", "-t 1");
  ASSERT_EQ(one.exit_code, 0) << one.stderr_text;
  const nlohmann::json s1 = nlohmann::json::parse(read(one.output / "results" / "summary.json"));
  EXPECT_EQ(s1["threads"], 1);
  EXPECT_EQ(s1["configuration"]["solver"]["threads"], 1);
  const ProgramRun many = run_case("cases/examples/seven_wire_axial.yaml", "threads_many", "-t 100000");
  ASSERT_EQ(many.exit_code, 0) << many.stderr_text;
  EXPECT_NE(many.stderr_text.find("warning: -t asks for 100000 threads"), std::string::npos) << many.stderr_text;
  const nlohmann::json s2 = nlohmann::json::parse(read(many.output / "results" / "summary.json"));
  EXPECT_GE(s2["threads"].get<int>(), 1);
  EXPECT_LT(s2["threads"].get<int>(), 100000);
  const ProgramRun huge = run_case("cases/examples/seven_wire_axial.yaml", "threads_huge", "-t 99999999999");
  EXPECT_EQ(huge.exit_code, 2) << huge.stderr_text;
}

// Determinism (developers' guide): the same case gives the same numbers whatever the thread count. Element and
// contact evaluations are independent per element and point, and the parallel scatter adds each value's terms
// in a fixed order, so the histories agree to the last digit written. A frictional, elastoplastic strand with
// tied end planes under load cycles exercises every path of the assembly.
TEST(ResultsFolder, SameNumbersWhateverTheThreadCount) {
  const ProgramRun one = run_case("cases/verification/resume_axial_cycles.yaml", "determinism_one", "-t 1");
  ASSERT_EQ(one.exit_code, 0) << one.stderr_text;
  const ProgramRun two = run_case("cases/verification/resume_axial_cycles.yaml", "determinism_two", "-t 2");
  ASSERT_EQ(two.exit_code, 0) << two.stderr_text;
  for (const char* file : {"history.csv", "wires.csv", "contacts.csv"}) {
    const std::string first = read(one.output / "results" / file), second = read(two.output / "results" / file);
    EXPECT_FALSE(first.empty()) << file;
    EXPECT_EQ(first, second) << file << " differs between 1 and 2 threads";
  }
}

// The source tree's short commit hash, or "" where git cannot tell (a source tree without its history).
std::string source_revision() {
  const std::string command = std::string("git -C \"") + STRANDFEM_SOURCE_DIR + "\" rev-parse --short HEAD 2>/dev/null";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return "";
  std::string text;
  char buffer[128];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) text += buffer;
  if (pclose(pipe) != 0) return "";
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  return text;
}

// The program names the commit it was built from, read at build time (cmake/GitRevision.cmake), not when the
// build folder was configured: after a commit without a rebuild this fails.
TEST(ResultsFolder, SummaryRecordsTheCommitItWasBuiltFrom) {
  const ProgramRun run = run_case("cases/examples/seven_wire_axial.yaml", "git_revision", "-t 1");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  const nlohmann::json summary = nlohmann::json::parse(read(run.output / "results" / "summary.json"));
  const std::string built_from = summary["build"]["git_revision"].get<std::string>();
  const std::string head = source_revision();
  if (head.empty()) EXPECT_EQ(built_from, "unknown");
  else EXPECT_EQ(built_from.substr(0, built_from.find('-')), head);  // "-dirty": tracked files had changed
}

// The BLAS kernels the factorizations ran on are read back into summary.json. On AVX-512 CPUs that OpenBLAS takes
// for Haswell or Zen the program restarts itself on the SkylakeX kernels; a core type the user set is kept.
TEST(ResultsFolder, SummaryRecordsTheBlasKernelsThatRan) {
  const std::string loaded = blas_core_name();  // this test process, as OpenBLAS chose on its own (or as the user set)
  const std::string preferred =
      preferred_openblas_core(loaded, cpu_has_skylakex_instructions(), std::getenv("OPENBLAS_CORETYPE") != nullptr);
  const ProgramRun run = run_case("cases/examples/seven_wire_axial.yaml", "blas_default", "-t 1");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  const nlohmann::json summary = nlohmann::json::parse(read(run.output / "results" / "summary.json"));
  EXPECT_EQ(summary["solver_statistics"]["blas_kernels"], preferred.empty() ? loaded : preferred);
  if (loaded == "not OpenBLAS") return;
  const char* user_core = std::getenv("OPENBLAS_CORETYPE");
  const std::string saved = user_core ? user_core : "";
  setenv("OPENBLAS_CORETYPE", "Haswell", 1);  // every x86-64 OpenBLAS with dynamic kernels has them
  const ProgramRun chosen = run_case("cases/examples/seven_wire_axial.yaml", "blas_chosen", "-t 1");
  if (user_core) setenv("OPENBLAS_CORETYPE", saved.c_str(), 1); else unsetenv("OPENBLAS_CORETYPE");
  ASSERT_EQ(chosen.exit_code, 0) << chosen.stderr_text;
  const nlohmann::json chosen_summary = nlohmann::json::parse(read(chosen.output / "results" / "summary.json"));
  EXPECT_EQ(chosen_summary["solver_statistics"]["blas_kernels"], "Haswell");
}

}  // namespace
}  // namespace strandfem::verification
