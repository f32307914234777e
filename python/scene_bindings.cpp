// SPDX-License-Identifier: GPL-3.0-or-later
// hrspace.Scene and hrspace.Object: a scene file's data, readable and
// editable from Python, validated by the same reader as the command line.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "geometry/error.h"
#include "python/bindings.h"

namespace hrs::python {

void PyScene::validate() const {
  // The reader holds every rule of the format: a scene edited from Python
  // is valid exactly when its text reads back.
  (void)geometry::parse_scene(geometry::write_scene(scene), label);
}

geometry::Pose2 to_pose(const py::handle& value, const std::string& what) {
  std::vector<double> v;
  try {
    v = value.cast<std::vector<double>>();
  } catch (const py::cast_error&) {
    throw InputError(what + ": expected a pose (x, y, theta), got " +
                     std::string(py::str(py::repr(value))));
  }
  if (v.size() != 3)
    throw InputError(what + ": expected 3 numbers (x, y, theta), got " + std::to_string(v.size()));
  const char* names[] = {"x", "y", "theta"};
  const double caps[] = {geometry::limits::kCoordinate, geometry::limits::kCoordinate,
                         geometry::limits::kAngle};
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(v[i]) || std::abs(v[i]) > caps[i]) {
      std::ostringstream m;
      m << what << ": " << names[i] << " = " << v[i] << " is not finite or outside [-" << caps[i]
        << ", " << caps[i] << "]";
      throw InputError(m.str());
    }
  }
  return {v[0], v[1], v[2]};
}

py::tuple pose_tuple(const geometry::Pose2& p) { return py::make_tuple(p.x, p.y, p.theta); }

namespace {

py::array_t<double> polygon_array(const geometry::Polygon& polygon) {
  py::array_t<double> out({static_cast<py::ssize_t>(polygon.size()), py::ssize_t{2}});
  auto a = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    a(i, 0) = polygon[i].x;
    a(i, 1) = polygon[i].y;
  }
  return out;
}

//! One object of a Scene, by reference: edits change the scene.
struct ObjectRef {
  py::object owner;  //!< the Scene (kept alive)
  PyScene* scene;
  std::size_t index;
  geometry::Object& get() const { return scene->scene.objects.at(index); }
};

PyScene load(const std::string& path) { return {geometry::load_scene(path), path}; }

PyScene from_json(const std::string& text, const std::string& label) {
  return {geometry::parse_scene(text, label), label};
}

PyScene from_source(const py::object& source) {
  if (py::isinstance<py::str>(source)) {
    const std::string text = source.cast<std::string>();
    const auto first = text.find_first_not_of(" \t\r\n");
    if (first != std::string::npos && text[first] == '{') return from_json(text, "<string>");
    return load(text);
  }
  const py::object path = py::module_::import("os").attr("fspath")(source);
  return load(path.cast<std::string>());
}

py::dict weights_dict(const geometry::Weights& w) {
  py::dict d;
  d["path"] = py::make_tuple(w.path[0], w.path[1], w.path[2]);
  d["interior"] = py::make_tuple(w.interior[0], w.interior[1]);
  return d;
}

//! Every object's pose as an array of shape (N, 3).
py::array_t<double> poses_array(const PyScene& s) {
  const auto n = static_cast<py::ssize_t>(s.scene.objects.size());
  py::array_t<double> out({n, py::ssize_t{3}});
  auto a = out.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < n; ++i) {
    const auto& p = s.scene.objects[i].pose;
    a(i, 0) = p.x, a(i, 1) = p.y, a(i, 2) = p.theta;
  }
  return out;
}

//! Sets every object's pose from an array of shape (N, 3), all checked first.
void set_poses(PyScene& s,
               const py::array_t<double, py::array::c_style | py::array::forcecast>& a) {
  if (a.ndim() != 2 || a.shape(1) != 3 ||
      a.shape(0) != static_cast<py::ssize_t>(s.scene.objects.size()))
    throw InputError("poses: expected an array of shape (" +
                     std::to_string(s.scene.objects.size()) + ", 3)");
  std::vector<geometry::Pose2> poses;
  const auto r = a.unchecked<2>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i)
    poses.push_back(
        to_pose(py::make_tuple(r(i, 0), r(i, 1), r(i, 2)), "poses[" + std::to_string(i) + "]"));
  for (std::size_t i = 0; i < poses.size(); ++i) s.scene.objects[i].pose = poses[i];
}

//! Sets the path and/or interior weights from {'path': (3), 'interior': (2)}:
//! any other key, a count other than 3 or 2, or a value outside
//! [0, limits::kWeight] (NaN included) is a ValueError naming it.
void set_weights(PyScene& s, const py::dict& d) {
  geometry::Weights w = s.scene.weights;
  for (const auto& [key, value] : d) {
    const std::string k = py::str(key);
    if (k != "path" && k != "interior")
      throw InputError("weights: unknown key '" + k + "' (expected 'path' and/or 'interior')");
  }
  const auto values = [&](const char* key, std::size_t n) {
    const auto v = d[key].cast<std::vector<double>>();
    const std::string at = std::string("weights['") + key + "']";
    if (v.size() != n)
      throw InputError(at + ": expected " + std::to_string(n) + " numbers, got " +
                       std::to_string(v.size()));
    for (std::size_t i = 0; i < n; ++i)
      if (!(v[i] >= 0.0 && v[i] <= geometry::limits::kWeight))
        throw InputError(at + "[" + std::to_string(i) + "]: must be within [0, 1e6], got " +
                         (std::isnan(v[i]) ? std::string("NaN") : std::to_string(v[i])));
    return v;
  };
  if (d.contains("path")) {
    const auto v = values("path", 3);
    w.path = {v[0], v[1], v[2]};
  }
  if (d.contains("interior")) {
    const auto v = values("interior", 2);
    w.interior = {v[0], v[1]};
  }
  s.scene.weights = w;
}

//! hrspace.Object: a view of one object of a Scene.
void bind_object(py::module_& m) {
  py::class_<ObjectRef>(m, "Object",
                        "One piece of furniture of a Scene (a view: edits change the scene).")
      .def_property_readonly(
          "id", [](const ObjectRef& o) { return o.get().id; }, "The object's id (str).")
      .def_property(
          "pose", [](const ObjectRef& o) { return pose_tuple(o.get().pose); },
          [](ObjectRef& o, const py::object& pose) { o.get().pose = to_pose(pose, "pose"); },
          "Position and heading (x, y, theta) in metres and radians; settable.")
      .def_property(
          "fixed", [](const ObjectRef& o) { return o.get().fixed; },
          [](ObjectRef& o, bool fixed) { o.get().fixed = fixed; },
          "True when the optimizer never moves the object; settable.")
      .def_property_readonly(
          "footprint", [](const ObjectRef& o) { return polygon_array(o.get().footprint); },
          "The outline in the object's own frame, counter-clockwise: array of shape (V, 2).")
      .def_property_readonly(
          "world_footprint",
          [](const ObjectRef& o) { return polygon_array(geometry::world_footprint(o.get())); },
          "The outline placed at the object's pose: array of shape (V, 2).")
      .def("__repr__", [](const ObjectRef& o) {
        const auto& p = o.get().pose;
        std::ostringstream s;
        s << "Object('" << o.get().id << "', pose=(" << p.x << ", " << p.y << ", " << p.theta
          << ")" << (o.get().fixed ? ", fixed" : "") << ")";
        return s.str();
      });
}

//! Scene: reading, writing, validating, copying and comparing.
void add_scene_io(py::class_<PyScene>& scene) {
  scene
      .def(py::init(&from_source), py::arg("source"),
           "Reads a scene from a file path (str or os.PathLike) or from JSON text (a str "
           "starting with '{'). Raises ValueError with the command line's message when the "
           "scene breaks a rule of the format.")
      .def_static("load", &load, py::arg("path"),
                  "Reads and validates a scene file; ValueError('FILE: /pointer: problem').")
      .def_static("from_json", &from_json, py::arg("text"), py::arg("label") = "<string>",
                  "Parses and validates scene JSON text; `label` names it in error messages.")
      .def("to_json", [](const PyScene& s) { return geometry::write_scene(s.scene); },
           "The scene as hrspace-scene/1 JSON text (what layout.json holds).")
      .def("validate", &PyScene::validate,
           "Checks the scene as it is now (after edits) against every rule of the format; "
           "raises ValueError with the reader's message, returns None when valid.")
      .def("copy", [](const PyScene& s) { return s; }, "An independent copy.")
      .def("__copy__", [](const PyScene& s) { return s; }, "An independent copy.")
      .def("__deepcopy__", [](const PyScene& s, py::dict) { return s; }, py::arg("memo"),
           "An independent copy.")
      .def("__eq__", [](const PyScene& a, const PyScene& b) { return a.scene == b.scene; },
           py::is_operator(), "Equal data (labels are not compared).");
}

//! Scene: its name and label, and its objects (as views, by id, their poses).
void add_scene_objects(py::class_<PyScene>& scene) {
  scene
      .def_property(
          "name", [](const PyScene& s) { return s.scene.name; },
          [](PyScene& s, const std::string& n) { s.scene.name = n; }, "The scene's name; settable.")
      .def_property_readonly(
          "label", [](const PyScene& s) { return s.label; },
          "Where the scene came from (its path or '<string>'), as error messages name it.")
      .def_property_readonly(
          "objects",
          [](py::object self) {
            auto& s = self.cast<PyScene&>();
            py::list out;
            for (std::size_t i = 0; i < s.scene.objects.size(); ++i)
              out.append(py::cast(ObjectRef{self, &s, i}));
            return out;
          },
          "The objects, in file order, as views (editing one edits the scene).")
      .def(
          "object",
          [](py::object self, const std::string& id) {
            auto& s = self.cast<PyScene&>();
            const int i = s.scene.find_object(id);
            if (i < 0) throw py::key_error("no object '" + id + "' in " + s.label);
            return ObjectRef{self, &s, static_cast<std::size_t>(i)};
          },
          py::arg("id"), "The object with this id (a view); KeyError when there is none.")
      .def_property_readonly(
          "object_ids",
          [](const PyScene& s) {
            std::vector<std::string> ids;
            for (const auto& o : s.scene.objects) ids.push_back(o.id);
            return ids;
          },
          "The objects' ids, in file order.")
      .def_property(
          "poses", &poses_array, &set_poses,
          "Every object's (x, y, theta): array of shape (N, 3) in object order; settable.");
}

//! Scene: the room, the door, the start pose and the wheelchair.
void add_scene_room(py::class_<PyScene>& scene) {
  scene
      .def_property_readonly(
          "room", [](const PyScene& s) { return polygon_array(s.scene.room.polygon); },
          "The room's inner wall outline, counter-clockwise: array of shape (V, 2).")
      .def_property_readonly(
          "door",
          [](const PyScene& s) {
            py::dict d;
            d["center"] = py::make_tuple(s.scene.door.center.x, s.scene.door.center.y);
            d["width"] = s.scene.door.width;
            d["clear_depth"] = s.scene.door.clear_depth;
            d["clear_zone"] = polygon_array(geometry::door_clear_zone(s.scene));
            return d;
          },
          "The door: center (x, y), width, clear_depth and clear_zone (the rectangle kept free, "
          "shape (4, 2)).")
      .def_property_readonly(
          "start_pose", [](const PyScene& s) { return pose_tuple(geometry::door_start_pose(s.scene)); },
          "The wheelchair's start pose (x, y, theta) at the door.")
      .def_property_readonly(
          "wheelchair",
          [](const PyScene& s) {
            py::dict d;
            d["length"] = s.scene.wheelchair.length;
            d["width"] = s.scene.wheelchair.width;
            d["turning_radius"] = s.scene.wheelchair.turning_radius;
            return d;
          },
          "The wheelchair: length, width, turning_radius (metres).");
}

//! Scene: the cost weights and the activity (AO) graph.
void add_scene_preferences(py::class_<PyScene>& scene) {
  scene
      .def_property(
          "weights", [](const PyScene& s) { return weights_dict(s.scene.weights); },
          &set_weights,
          "Cost weights: {'path': (length, rotation, clearance), 'interior': (distance, "
          "angle)}; settable (like the command's --weights; validate() checks the values).")
      .def_property_readonly(
          "activity",
          [](const PyScene& s) {
            py::dict d;
            d["transitions"] = s.scene.activity.transitions;
            d["sequences"] = s.scene.activity.sequences;
            d["visits"] = s.scene.activity.visits;
            return d;
          },
          "The activity (AO) graph: transitions {from: {to: probability}}, sequences (M), "
          "visits.");
}

}  // namespace

void bind_scene(py::module_& m) {
  bind_object(m);
  py::class_<PyScene> scene(m, "Scene",
                            "A scene (hrspace-scene/1): room, door, wheelchair, furniture, "
                            "interior-design preferences and the activity graph.");
  add_scene_io(scene);
  add_scene_objects(scene);
  add_scene_room(scene);
  add_scene_preferences(scene);
  scene.def("__repr__", [](const PyScene& s) {
    return "Scene('" + s.scene.name + "', " + std::to_string(s.scene.objects.size()) +
           " objects, from " + s.label + ")";
  });
}

}  // namespace hrs::python
