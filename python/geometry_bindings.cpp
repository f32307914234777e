// SPDX-License-Identifier: GPL-3.0-or-later
// hrspace.CSpace (collision and clearance of many poses per call, the GIL
// released) and hrspace.rs (Reeds-Shepp shortest paths and sampling).

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <charconv>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <shared_mutex>
#include <string>
#include <vector>

#include "geometry/cspace.h"
#include "geometry/error.h"
#include "python/bindings.h"
#include "rs/reeds_shepp.h"

namespace hrs::python {

namespace {

using PoseArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::string number_text(double v) {
  char buf[64];
  auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, p) : std::string("nan");
}

//! The rows of an (N, 3) pose array (or one pose of shape (3,)), checked
//! like the command's CSV columns: finite, |x|, |y| <= 1000 m, |theta| <=
//! 1000 rad. Returns N; `single` is set for shape (3,).
py::ssize_t check_poses(const PoseArray& poses, bool& single) {
  single = poses.ndim() == 1;
  if (!((poses.ndim() == 2 && poses.shape(1) == 3) || (single && poses.shape(0) == 3)))
    throw InputError("poses: expected an array of shape (N, 3) (x, y, theta per row) or (3,)");
  const py::ssize_t n = single ? 1 : poses.shape(0);
  const double* d = poses.data();
  const char* names[] = {"x", "y", "theta"};
  const double caps[] = {geometry::limits::kCoordinate, geometry::limits::kCoordinate,
                         geometry::limits::kAngle};
  for (py::ssize_t i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) {
      const double v = d[3 * i + k];
      if (!(std::abs(v) <= caps[k]))
        throw InputError("poses[" + std::to_string(i) + "] (" + names[k] + "): " +
                         number_text(v) + " is not finite or outside [-" + number_text(caps[k]) +
                         ", " + number_text(caps[k]) + "]");
    }
  }
  return n;
}

//! A C-space with the ids of its objects (for move_object by id). Queries
//! run without the GIL, so Python threads may query at once; `mutex` keeps
//! move_object from changing the pieces under a running query.
struct PyCSpace {
  std::unique_ptr<geometry::CSpace> cspace;
  std::vector<std::string> ids;
  std::unique_ptr<std::shared_mutex> mutex = std::make_unique<std::shared_mutex>();

  int index_of(const py::object& key) const {
    if (py::isinstance<py::str>(key)) {
      const std::string id = key.cast<std::string>();
      for (std::size_t i = 0; i < ids.size(); ++i)
        if (ids[i] == id) return static_cast<int>(i);
      throw py::key_error("no object '" + id + "'");
    }
    const long i = key.cast<long>();
    if (i < 0 || i >= static_cast<long>(ids.size()))
      throw py::index_error("object index " + std::to_string(i) + " out of range");
    return static_cast<int>(i);
  }
};

//! An RS path with the pose it is driven from.
struct PyPath {
  geometry::Pose2 start;
  rs::Path path;
};

double checked_radius(double radius) {
  if (!(radius >= geometry::limits::kMinLength && radius <= geometry::limits::kLength))
    throw InputError("--radius: must be within [" + number_text(geometry::limits::kMinLength) +
                     ", " + number_text(geometry::limits::kLength) + "] m, got " +
                     number_text(radius));
  return radius;
}

rs::Segment to_segment(const py::handle& item) {
  const auto t = item.cast<py::tuple>();
  if (t.size() != 3) throw InputError("segment: expected (steer, gear, length)");
  const std::string steer = t[0].cast<std::string>();
  const int gear = t[1].cast<int>();
  const double length = t[2].cast<double>();
  if (steer != "L" && steer != "S" && steer != "R")
    throw InputError("segment: steer must be 'L', 'S' or 'R', got '" + steer + "'");
  if (gear != 1 && gear != -1) throw InputError("segment: gear must be 1 or -1");
  if (!(length >= 0.0 && length <= geometry::limits::kLength))
    throw InputError("segment: length must be within [0, 2000] m");
  return {static_cast<rs::Steer>(steer[0]), gear, length};
}

//! A C-space of the scene as it is now (validated first), built without the GIL.
PyCSpace make_cspace(const PyScene& scene, int slices) {
  scene.validate();
  if (slices < 4 || slices > 100000)
    throw InputError("--slices: " + std::to_string(slices) + " is outside [4, 100000]");
  PyCSpace c;
  for (const auto& o : scene.scene.objects) c.ids.push_back(o.id);
  geometry::CSpaceOptions options;
  options.slices = slices;
  py::gil_scoped_release release;
  c.cspace = std::make_unique<geometry::CSpace>(scene.scene, options);
  return c;
}

//! is_free(): a bool per pose (one bool for a single pose).
py::object cspace_is_free(const PyCSpace& c, const PoseArray& poses) {
  bool single = false;
  const py::ssize_t n = check_poses(poses, single);
  py::array_t<bool> out(n);
  bool* o = out.mutable_data();
  const double* d = poses.data();
  {
    py::gil_scoped_release release;
    const std::shared_lock lock(*c.mutex);
    const geometry::CSpace& cs = *c.cspace;
    for (py::ssize_t i = 0; i < n; ++i)
      o[i] = cs.is_free({d[3 * i], d[3 * i + 1], d[3 * i + 2]});
  }
  if (single) return py::bool_(o[0]);
  return out;
}

//! clearance(): (left, right) per pose (one pair for a single pose).
py::array_t<double> cspace_clearance(const PyCSpace& c, const PoseArray& poses) {
  bool single = false;
  const py::ssize_t n = check_poses(poses, single);
  py::array_t<double> out({n, py::ssize_t{2}});
  double* o = out.mutable_data();
  const double* d = poses.data();
  {
    py::gil_scoped_release release;
    const std::shared_lock lock(*c.mutex);
    const geometry::CSpace& cs = *c.cspace;
    for (py::ssize_t i = 0; i < n; ++i) {
      const geometry::Clearance cl = cs.clearance({d[3 * i], d[3 * i + 1], d[3 * i + 2]});
      o[2 * i] = cl.left;
      o[2 * i + 1] = cl.right;
    }
  }
  if (single) out.resize({py::ssize_t{2}});
  return out;
}

//! rs.sample(): poses along a path at most `step` apart, shape (N, 3).
py::array_t<double> sample_path(const PyPath& p, double step) {
  if (!(step > 0.0) || !std::isfinite(step))
    throw InputError("step: must be a finite number > 0, got " + number_text(step));
  std::vector<geometry::Pose2> poses;
  {
    py::gil_scoped_release release;
    poses = rs::sample(p.start, p.path, step);
  }
  py::array_t<double> out({static_cast<py::ssize_t>(poses.size()), py::ssize_t{3}});
  auto a = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < poses.size(); ++i)
    a(i, 0) = poses[i].x, a(i, 1) = poses[i].y, a(i, 2) = poses[i].theta;
  return out;
}

//! CSpace: which poses are free and how much room they have.
void add_cspace_queries(py::class_<PyCSpace>& cspace) {
  cspace
      .def("is_free", &cspace_is_free, py::arg("poses"),
           "For poses of shape (N, 3) (x, y, theta per row), a bool array of shape (N,): True "
           "only when the chair there is certainly inside the room and clear of all furniture "
           "(hrspace collide's `free`). A single pose of shape (3,) gives one bool.")
      .def("clearance", &cspace_clearance, py::arg("poses"),
           "For poses of shape (N, 3), an array of shape (N, 2): the distance (metres) to the "
           "nearest wall or furniture outline on the left and on the right of each pose's "
           "heading (hrspace collide's clear_left, clear_right). Shape (3,) gives shape (2,).");
}

//! CSpace: moving one object and reading its pose.
void add_cspace_objects(py::class_<PyCSpace>& cspace) {
  cspace
      .def(
          "move_object",
          [](PyCSpace& c, const py::object& key, const py::object& pose) {
            const int i = c.index_of(key);
            const geometry::Pose2 p = to_pose(pose, "pose");
            py::gil_scoped_release release;
            const std::unique_lock lock(*c.mutex);
            c.cspace->move_object(i, p);
          },
          py::arg("object"), py::arg("pose"),
          "Moves one object (by id or index) to pose (x, y, theta); only its own pieces are "
          "rebuilt. The Scene the C-space was built from is not changed.")
      .def(
          "object_pose",
          [](const PyCSpace& c, const py::object& key) {
            const int i = c.index_of(key);
            geometry::Pose2 p;
            {
              py::gil_scoped_release release;
              const std::shared_lock lock(*c.mutex);
              p = c.cspace->object_pose(i);
            }
            return pose_tuple(p);
          },
          py::arg("object"), "The pose (x, y, theta) of one object (by id or index).");
}

//! hrspace.rs.Path: a Reeds-Shepp path and what it measures.
void bind_path(py::module_& m) {
  py::class_<PyPath>(m, "Path",
                     "A Reeds-Shepp path: segments driven in order from `start` with turning "
                     "radius `radius`.")
      .def(py::init([](const py::object& start, const py::iterable& segments, double radius) {
             PyPath p;
             p.start = to_pose(start, "start");
             p.path.radius = checked_radius(radius);
             for (const auto& s : segments) p.path.segments.push_back(to_segment(s));
             return p;
           }),
           py::arg("start"), py::arg("segments"), py::arg("radius"),
           "A path from `start` (x, y, theta) of `segments` [(steer 'L'|'S'|'R', gear 1|-1, "
           "length in metres), ...] with turning radius `radius`.")
      .def_property_readonly(
          "start", [](const PyPath& p) { return pose_tuple(p.start); }, "Start pose (x, y, theta).")
      .def_property_readonly(
          "end", [](const PyPath& p) { return pose_tuple(rs::end_pose(p.start, p.path)); },
          "Pose (x, y, theta) reached at the end.")
      .def_property_readonly(
          "radius", [](const PyPath& p) { return p.path.radius; }, "Turning radius, metres.")
      .def_property_readonly(
          "length", [](const PyPath& p) { return p.path.length(); },
          "Total length, metres (hrspace rs's `length`).")
      .def_property_readonly(
          "word", [](const PyPath& p) { return p.path.word(); },
          "Steering letter and gear sign per segment, e.g. 'L+S+R-' (hrspace rs's `word`).")
      .def_property_readonly(
          "segments",
          [](const PyPath& p) {
            py::list out;
            for (const auto& s : p.path.segments)
              out.append(py::make_tuple(std::string(1, static_cast<char>(s.steer)), s.gear,
                                        s.length));
            return out;
          },
          "[(steer, gear, length), ...]: steer 'L', 'S' or 'R', gear 1 (forward) or -1, length "
          "in metres.")
      .def_property_readonly(
          "signed_lengths",
          [](const PyPath& p) {
            std::vector<double> out;
            for (const auto& s : p.path.segments) out.push_back(s.gear * s.length);
            return out;
          },
          "Segment lengths signed by gear (hrspace rs's `segments` column).")
      .def("__repr__", [](const PyPath& p) {
        return "Path(word='" + p.path.word() + "', length=" + number_text(p.path.length()) + ")";
      });
}

//! CSpace: its slices and pieces, and its repr.
void add_cspace_info(py::class_<PyCSpace>& cspace) {
  cspace
      .def_property_readonly(
          "slices", [](const PyCSpace& c) { return c.cspace->slices(); },
          "Number of orientation slices.")
      .def_property_readonly(
          "piece_count", [](const PyCSpace& c) { return c.cspace->piece_count(); },
          "Convex C-obstacle pieces over all slices.")
      .def("__repr__", [](const PyCSpace& c) {
        return "CSpace(" + std::to_string(c.ids.size()) + " objects, " +
               std::to_string(c.cspace->slices()) + " slices)";
      });
}

}  // namespace

void bind_geometry(py::module_& m) {
  py::class_<PyCSpace> cspace(m, "CSpace",
                              "The wheelchair's exact, conservative configuration space in a "
                              "scene's layout: 'free' answers are certified (docs/geometry.md).");
  cspace.def(py::init(&make_cspace), py::arg("scene"), py::arg("slices") = 72,
             "Builds the C-space of the scene's room, chair and current object poses, with "
             "`slices` orientation slices (as hrspace collide --slices).");
  add_cspace_queries(cspace);
  add_cspace_objects(cspace);
  add_cspace_info(cspace);
}

void bind_rs(py::module_& m) {
  bind_path(m);
  m.def(
      "shortest",
      [](const py::object& a, const py::object& b, double radius) {
        const geometry::Pose2 from = to_pose(a, "a"), to = to_pose(b, "b");
        PyPath p{from, rs::shortest_path(from, to, checked_radius(radius))};
        return p;
      },
      py::arg("a"), py::arg("b"), py::arg("radius"),
      "The exact shortest Reeds-Shepp path from pose a to pose b (x, y, theta) with turning "
      "radius `radius` (metres, 0.001 to 2000): a Path with length, word and segments, as "
      "hrspace rs computes them.");
  m.def("sample", &sample_path, py::arg("path"), py::arg("step"),
        "Poses along `path` from its start to its end, at most `step` metres apart, both ends "
        "included: array of shape (N, 3).");
}

}  // namespace hrs::python
