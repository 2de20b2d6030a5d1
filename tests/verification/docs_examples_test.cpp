// Requirement: every case-file example in README.md and docs/ is a valid case (`strandfem info` accepts it), and
// the program reports the project's version.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "program_runner.hpp"

namespace strandfem::verification {
namespace {

struct Example {
  std::string file;
  int line = 0;
  std::string yaml;
};

// The ```yaml blocks of a Markdown file, with the line each starts on.
std::vector<Example> yaml_blocks(const std::filesystem::path& file) {
  std::vector<Example> blocks;
  std::ifstream in(file);
  std::string line;
  int number = 0;
  Example* open = nullptr;
  while (std::getline(in, line)) {
    ++number;
    if (open == nullptr && line.rfind("```yaml", 0) == 0) {
      blocks.push_back({file.filename().string(), number, ""});
      open = &blocks.back();
    } else if (open != nullptr && line.rfind("```", 0) == 0) {
      open = nullptr;
    } else if (open != nullptr) {
      open->yaml += line + "\n";
    }
  }
  return blocks;
}

TEST(DocsExamples, EveryCaseFileExampleInTheDocsIsAValidCase) {
  const std::filesystem::path root(STRANDFEM_SOURCE_DIR);
  std::vector<std::filesystem::path> pages = {root / "README.md"};
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root / "docs"))
    if (entry.path().extension() == ".md") pages.push_back(entry.path());
  int readme_examples = 0, guide_examples = 0, k = 0;
  for (const auto& page : pages)
    for (const Example& example : yaml_blocks(page)) {
      readme_examples += example.file == "README.md";
      guide_examples += example.file == "user-guide.md";
      const std::string tag = "docs_example_" + std::to_string(++k);
      const auto folder = std::filesystem::path(::testing::TempDir()) / tag;
      std::filesystem::create_directories(folder);
      const auto case_file = folder / "case.yaml";
      std::ofstream(case_file) << example.yaml;
      const ProgramRun r = run_program("info " + case_file.string(), tag);
      EXPECT_EQ(r.exit_code, 0) << example.file << ":" << example.line << ": " << r.stderr_text;
    }
  EXPECT_GE(readme_examples, 1);
  EXPECT_GE(guide_examples, 1);
}

TEST(DocsExamples, VersionIsTheProjects) {
  const ProgramRun r = run_program("--version", "version");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  std::ifstream in(r.output / "stdout.txt");
  std::string printed;
  std::getline(in, printed);
  EXPECT_EQ(printed, STRANDFEM_VERSION);
}

}  // namespace
}  // namespace strandfem::verification
