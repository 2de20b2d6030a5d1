#include "plot_scripts.hpp"

#include <cstdlib>
#include <filesystem>
#include <iostream>

namespace strandfem_app {
namespace {

namespace fs = std::filesystem;

std::string quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

fs::path scripts_folder() {
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);
  return (program.parent_path() / STRANDFEM_SCRIPTS_RELATIVE_DIR).lexically_normal();
}

std::string python() {
  if (const char* chosen = std::getenv("STRANDFEM_PYTHON"); chosen != nullptr && *chosen != '\0') return chosen;
  if (fs::exists("/usr/bin/python3")) return "/usr/bin/python3";
  return "python3";
}

}  // namespace

bool draw_figures(const std::string& script, const std::string& folder) {
  const fs::path path = scripts_folder() / script;
  if (!fs::exists(path)) {
    std::cerr << "warning: figures not drawn: " << path.string() << " is missing (install StrandFEM with cmake --install)\n";
    return false;
  }
  const std::string interpreter = python();
  if (std::system((quoted(interpreter) + " -c 'import matplotlib' > /dev/null 2>&1").c_str()) != 0) {
    std::cerr << "warning: figures not drawn: " << interpreter
              << " cannot import matplotlib (Debian: apt-get install python3-matplotlib; or set STRANDFEM_PYTHON to a "
                 "Python 3 that has it); the results are complete\n";
    return false;
  }
  const std::string command = quoted(interpreter) + " " + quoted(path.string()) + " " + quoted(folder) + " > /dev/null";
  if (std::system(command.c_str()) != 0) {
    std::cerr << "warning: plotting failed (" << command << "); the results are complete\n";
    return false;
  }
  return true;
}

}  // namespace strandfem_app
