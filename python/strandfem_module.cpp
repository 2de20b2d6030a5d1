// strandfem._core: the library's case reader and run driver for Python (the package strandfem wraps it).
#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <omp.h>

#include <memory>

#include "strandfem/io/case_file.hpp"
#include "strandfem/io/case_run.hpp"
#include "strandfem/io/case_variant.hpp"
#include "strandfem/io/conductor_catalogue.hpp"
#include "strandfem/post/analytic.hpp"
#include "strandfem/post/bending.hpp"
#include "strandfem/post/model_report.hpp"
#include "strandfem/post/run_report.hpp"
#include "strandfem/solver/mumps_processes.hpp"
#include "strandfem_git_revision.hpp"  // generated at build time (cmake/GitRevision.cmake)

namespace py = pybind11;

namespace {

// A read and checked case. A run changes the model it solves, so each run reads the case again: the same text for a
// case built from data, the file for a case read from one.
struct CaseHandle {
  std::function<strandfem::CaseDefinition()> read;
  std::shared_ptr<const strandfem::CaseDefinition> definition;
  explicit CaseHandle(std::function<strandfem::CaseDefinition()> reader)
      : read(std::move(reader)), definition(std::make_shared<const strandfem::CaseDefinition>(read())) {}
};

py::object json_to_python(const nlohmann::json& value) { return py::module_::import("json").attr("loads")(value.dump()); }

nlohmann::json build_info() {
  return {{"git_revision", STRANDFEM_GIT_REVISION}, {"compiler", __VERSION__}, {"instruction_set", STRANDFEM_INSTRUCTION_SET},
          {"version", STRANDFEM_VERSION}, {"front_end", "python"}};
}

py::dict increment_dict(const strandfem::IncrementReport& r) {
  py::dict d;
  d["step"] = r.origin.step + 1;
  d["step_name"] = r.step_name;
  d["increment"] = r.increment;
  d["step_fraction"] = r.step_fraction;
  d["relative_size"] = r.relative_size;
  d["cutbacks"] = r.cutbacks;
  d["iterations"] = r.iterations;
  d["residual"] = r.residual_norm;
  return d;
}

// Solves the case into `directory`. Ctrl-C, or an exception in the progress callback, stops it after the current Newton
// iteration with the converged increments written (summary status "stopped"), and the exception is raised after.
py::dict run(const CaseHandle& handle, const std::string& directory, int threads, bool resume, const py::object& progress) {
  strandfem::CaseDefinition c = handle.read();
  c.model.options.threads = threads > 0 ? threads : (c.model.options.threads > 0 ? c.model.options.threads : omp_get_max_threads());
  c.resolved["solver"]["threads"] = c.model.options.threads;
  nlohmann::json info = strandfem::model_report(c);
  info["build"] = build_info();
  info["threads"] = c.model.options.threads;
  strandfem::CaseRunOptions options;
  options.resume = resume;
  // Set when Ctrl-C arrives or the progress callback raises; the Python exception stays pending until run() returns.
  bool interrupted = false;
  options.stop_requested = [&] {
    if (interrupted) return true;
    py::gil_scoped_acquire gil;
    interrupted = PyErr_CheckSignals() != 0;
    return interrupted;
  };
  if (!progress.is_none())
    options.on_increment = [&](const strandfem::IncrementReport& r) {
      py::gil_scoped_acquire gil;
      try {
        progress(increment_dict(r));
      } catch (py::error_already_set& e) {
        e.restore();
        interrupted = true;
      }
    };
  strandfem::CaseRunResult result;
  {
    py::gil_scoped_release release;
    result = strandfem::run_case(c, directory, info, options);
  }
  if (interrupted) throw py::error_already_set();
  py::dict out;
  out["converged"] = result.status.converged && !result.stopped;
  out["stopped"] = result.stopped;
  out["message"] = result.status.message;
  out["wall_seconds"] = result.wall_seconds;
  return out;
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "StrandFEM's library: case files read and checked, cases run into results folders";
  m.attr("__version__") = STRANDFEM_VERSION;
  m.def("build_info", [] { return json_to_python(build_info()); }, "Version, git revision, compiler and instruction set");
  m.def("mumps_build", &strandfem::mumps_build, "Which MUMPS the library was built on");
  py::register_exception<strandfem::CaseError>(m, "CaseError", PyExc_ValueError);
  py::class_<CaseHandle>(m, "CaseHandle")
      .def_property_readonly("title", [](const CaseHandle& h) { return h.definition->title; })
      .def_property_readonly("path", [](const CaseHandle& h) { return h.definition->path; })
      .def_property_readonly("warnings", [](const CaseHandle& h) { return py::cast(h.definition->warnings); })
      .def("info", [](const CaseHandle& h) { return json_to_python(strandfem::model_report(*h.definition)); })
      .def("resolved", [](const CaseHandle& h) { return json_to_python(h.definition->resolved); });
  m.def("load_case", [](const std::string& path) { return CaseHandle([path] { return strandfem::load_case(path); }); },
        py::arg("path"));
  m.def("load_case_text",
        [](const std::string& text, const std::string& name) {
          return CaseHandle([text, name] { return strandfem::load_case_text(text, name); });
        },
        py::arg("text"), py::arg("name"));
  m.def("conductor_table", &strandfem::conductor_summary_table, py::arg("catalogue") = "");
  m.def("poffenberger_swart_stress", &strandfem::poffenberger_swart_stress, py::arg("yb"), py::arg("tension"), py::arg("ei_min"),
        py::arg("wire_modulus"), py::arg("wire_diameter"), py::arg("xb"));
  m.def("set_case_key", &strandfem::set_case_key, py::arg("case_text"), py::arg("key_path"), py::arg("value"));
  m.def("sweep_result_header", &strandfem::sweep_result_header);
  m.def("sweep_result_fields", [](const std::string& summary) { return strandfem::sweep_result_fields(nlohmann::json::parse(summary)); },
        py::arg("summary_json"));
  m.def("variant_folder_name", &strandfem::variant_folder_name, py::arg("key_path"), py::arg("value"));
  m.def("tensioned_beam_deflection", &strandfem::tensioned_beam_deflection, py::arg("load"), py::arg("tension"),
        py::arg("bending_stiffness"), py::arg("span"), py::arg("x"));
  m.def("tensioned_timoshenko_deflection", &strandfem::tensioned_timoshenko_deflection, py::arg("load"), py::arg("tension"),
        py::arg("bending_stiffness"), py::arg("shear_stiffness"), py::arg("span"), py::arg("x"));
  m.def("tensioned_beam_midspan_deflection", &strandfem::tensioned_beam_midspan_deflection, py::arg("load"), py::arg("tension"),
        py::arg("bending_stiffness"), py::arg("span"));
  m.def("equivalent_bending_stiffness", &strandfem::equivalent_bending_stiffness, py::arg("compliance"), py::arg("tension"),
        py::arg("span"));
  // A sweep's variants may run on MPI ranks (mpi4py) that each solve their own model.
  strandfem::factor_within_this_process();
  m.def("run", &run, py::arg("case"), py::arg("directory"), py::arg("threads") = 0, py::arg("resume") = false,
        py::arg("progress") = py::none());
}
