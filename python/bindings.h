// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Shared pieces of the Python module's binding files (python/*.cpp): the
// Scene wrapper, pose conversion, JSON text to Python objects. Each
// bind_* function adds one part of the API to the module.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

#include "geometry/pose.h"
#include "geometry/scene.h"

namespace hrs::python {

namespace py = pybind11;

//! A scene as Python sees it: the data plus the label that error messages
//! name (the file it came from, or "<string>").
struct PyScene {
  geometry::Scene scene;
  std::string label;
  //! InputError with the reader's message when the scene, as it is now
  //! (after any edits from Python), breaks a rule of the format.
  void validate() const;
};

//! A pose from any sequence of three numbers; ValueError naming `what`
//! when it is not three finite numbers within the format's limits.
geometry::Pose2 to_pose(const py::handle& value, const std::string& what);
//! (x, y, theta) as a Python tuple.
py::tuple pose_tuple(const geometry::Pose2& pose);
//! json.loads(text).
py::object json_loads(const std::string& text);

void bind_scene(py::module_& m);
void bind_geometry(py::module_& m);
void bind_rs(py::module_& m);
void bind_planning(py::module_& m);
void bind_design(py::module_& m);

}  // namespace hrs::python
