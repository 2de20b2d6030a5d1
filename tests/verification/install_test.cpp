// Requirement: `cmake --install` gives a prefix that works on its own: from there, away from the source tree, the
// program runs a shipped bending case and draws its figures with --plots; without matplotlib it says what to install.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "program_runner.hpp"

namespace strandfem::verification {
namespace {

namespace fs = std::filesystem;

// Installs the build into a fresh prefix of this name under the test's temporary folder (one per test: CTest runs
// them in parallel); empty when the installation failed.
fs::path installed_prefix(const std::string& name) {
  const fs::path prefix = fs::path(::testing::TempDir()) / name;
  fs::remove_all(prefix);
  const std::string command = std::string("'") + STRANDFEM_CMAKE_COMMAND + "' --install '" + STRANDFEM_BUILD_DIR + "' --prefix '" +
                              prefix.string() + "' > '" + prefix.string() + ".log' 2>&1";
  return std::system(command.c_str()) == 0 ? prefix : fs::path();
}

// Runs the installed program from an empty folder with a bare environment (no source tree on any path).
int run_installed(const fs::path& prefix, const std::string& arguments, const fs::path& folder, const std::string& environment = "") {
  fs::remove_all(folder);
  fs::create_directories(folder);
  const std::string command = "cd '" + folder.string() + "' && env -i PATH=/usr/bin:/bin HOME='" + folder.string() + "' " + environment +
                              " '" + (prefix / "bin" / "strandfem").string() + "' " + arguments + " > stdout.txt 2> stderr.txt";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string text_of(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(Install, InstalledProgramRunsAShippedBendingCaseAndDrawsItsFigures) {
  const fs::path prefix = installed_prefix("strandfem_prefix_plots");
  ASSERT_FALSE(prefix.empty()) << "cmake --install failed";
  const fs::path shipped = prefix / "share" / "strandfem" / "cases" / "verification" / "bending_cycles_frictionless.yaml";
  ASSERT_TRUE(fs::exists(shipped));
  ASSERT_TRUE(fs::exists(prefix / "share" / "strandfem" / "scripts" / "plot_bending.py"));
  const fs::path folder = fs::path(::testing::TempDir()) / "strandfem_installed_run";
  ASSERT_EQ(run_installed(prefix, "run '" + shipped.string() + "' -o out --plots", folder), 0) << text_of(folder / "stderr.txt");
  for (const char* figure : {"bending_hysteresis.png", "bending_deflection.png"})
    EXPECT_TRUE(fs::exists(folder / "out" / figure)) << figure << "\n" << text_of(folder / "stderr.txt");
  EXPECT_EQ(text_of(folder / "stderr.txt").find("warning: figures not drawn"), std::string::npos) << text_of(folder / "stderr.txt");
}

// The catalogue travels inside the program; its file is installed beside the cases, and the installed program reads
// it as a user's catalogue (every conductor then listed twice: the file's rows first).
TEST(Install, InstalledProgramListsTheConductorCatalogue) {
  const fs::path prefix = installed_prefix("strandfem_prefix_catalogue");
  ASSERT_FALSE(prefix.empty()) << "cmake --install failed";
  const fs::path catalogue = prefix / "share" / "strandfem" / "data" / "conductors.csv";
  ASSERT_TRUE(fs::exists(catalogue));
  const fs::path folder = fs::path(::testing::TempDir()) / "strandfem_installed_conductors";
  ASSERT_EQ(run_installed(prefix, "conductors --catalogue '" + catalogue.string() + "'", folder), 0) << text_of(folder / "stderr.txt");
  const std::string listed = text_of(folder / "stdout.txt");
  const std::size_t first = listed.find("\nDrake "), second = listed.find("\nDrake ", first + 1);
  EXPECT_NE(first, std::string::npos) << listed;
  EXPECT_NE(second, std::string::npos) << listed;
}

TEST(Install, PlotsWithoutMatplotlibSayWhatToInstallAndKeepTheResults) {
  const fs::path prefix = installed_prefix("strandfem_prefix_no_matplotlib");
  ASSERT_FALSE(prefix.empty()) << "cmake --install failed";
  const fs::path shipped = prefix / "share" / "strandfem" / "cases" / "verification" / "bending_cycles_frictionless.yaml";
  const fs::path folder = fs::path(::testing::TempDir()) / "strandfem_installed_no_matplotlib";
  ASSERT_EQ(run_installed(prefix, "run '" + shipped.string() + "' -q -o out --plots", folder, "STRANDFEM_PYTHON=/bin/false"), 0)
      << text_of(folder / "stderr.txt");
  EXPECT_NE(text_of(folder / "stderr.txt").find("cannot import matplotlib (Debian: apt-get install python3-matplotlib"), std::string::npos)
      << text_of(folder / "stderr.txt");
  EXPECT_TRUE(fs::exists(folder / "out" / "loops.csv"));
  EXPECT_FALSE(fs::exists(folder / "out" / "bending_hysteresis.png"));
}

}  // namespace
}  // namespace strandfem::verification
