// Figures drawn by the plotting scripts that come with the program, run by a Python 3 with matplotlib found at
// run time.
#pragma once
#include <string>

namespace strandfem_app {

// Runs SCRIPT (plot_bending.py, plot_sweep.py) on a results folder. The scripts lie in ../share/strandfem/scripts
// beside the program's own folder, in the build tree as in an installed prefix. The Python is $STRANDFEM_PYTHON,
// else /usr/bin/python3 (Debian's, with python3-matplotlib), else python3 on the PATH. A missing script, Python
// or matplotlib, or a failing script, is a warning naming what to install: the results themselves are complete.
bool draw_figures(const std::string& script, const std::string& folder);

}  // namespace strandfem_app
