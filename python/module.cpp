// SPDX-License-Identifier: GPL-3.0-or-later
// hrspace._core: the extension behind `import hrspace` (docs/python.md).
// Errors: hrs::InputError becomes ValueError with the command line's
// one-line message, hrs::OutputError becomes OSError.

#include <pybind11/pybind11.h>

#include "geometry/error.h"
#include "geometry/version.h"
#include "python/bindings.h"

namespace hrs::python {

py::object json_loads(const std::string& text) {
  // Kept for the life of the process (never destroyed after the interpreter).
  static py::object* loads = new py::object(py::module_::import("json").attr("loads"));
  return (*loads)(py::str(text));
}

}  // namespace hrs::python

PYBIND11_MODULE(_core, m) {
  namespace py = pybind11;
  m.doc() =
      "hrspace: room layouts shared by people and a self-driving wheelchair (extension module; "
      "import hrspace instead).";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const hrs::InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const hrs::OutputError& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    }
  });
  m.attr("__version__") = hrs::version();
  m.attr("__commit__") = hrs::commit();
  hrs::python::bind_scene(m);
  hrs::python::bind_geometry(m);
  auto rs = m.def_submodule("rs", "Reeds-Shepp curves: shortest paths and sampling.");
  hrs::python::bind_rs(rs);
  hrs::python::bind_planning(m);
  hrs::python::bind_design(m);
}
