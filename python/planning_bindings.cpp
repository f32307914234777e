// SPDX-License-Identifier: GPL-3.0-or-later
// hrspace.plan and hrspace.tour: one leg and one tour in a scene's layout,
// through the same code as `hrspace plan` and `hrspace tour`
// (api/operations.h), returned as the command's JSON object parsed.

#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "api/operations.h"
#include "geometry/error.h"
#include "python/bindings.h"

namespace hrs::python {

namespace {

//! The command's integer-option check: "--NAME: V is outside [MIN, MAX]".
long long in_range(const std::string& name, long long v, long long min, long long max) {
  if (v < min || v > max)
    throw InputError("--" + name + ": " + std::to_string(v) + " is outside [" +
                     std::to_string(min) + ", " + std::to_string(max) + "]");
  return v;
}

}  // namespace

void bind_planning(py::module_& m) {
  m.def(
      "plan",
      [](const PyScene& scene, const py::object& start, const py::object& goal, long long seed,
         const std::string& planner, std::optional<std::string> reuse, long long iterations,
         double step) {
        scene.validate();
        const geometry::Pose2 from = to_pose(start, "start"), to = to_pose(goal, "goal");
        api::LegSettings settings;
        settings.seed = static_cast<std::uint64_t>(in_range("seed", seed, 0, 0x7fffffffffffffffLL));
        settings.iterations = static_cast<int>(in_range("iterations", iterations, 1, 100000000));
        settings.step = step;
        settings.reuse = api::choose_planner(planner, reuse, api::kPlanReuse);
        std::string json;
        {
          py::gil_scoped_release release;
          json = api::plan_leg_json(scene.scene, from, to, settings);
        }
        return json_loads(json);
      },
      py::arg("scene"), py::arg("start"), py::arg("goal"), py::kw_only(), py::arg("seed") = 1,
      py::arg("planner") = "baseline", py::arg("reuse") = py::none(),
      py::arg("iterations") = 3000, py::arg("step") = 0.25,
      "Plans one wheelchair leg from `start` to `goal` (x, y, theta) in the scene's layout, "
      "as `hrspace plan` does, and returns its JSON object as a dict: found, from, to, radius, "
      "length, segments, waypoints, iterations, tree_nodes, collision_checks, time_ms, "
      "impossible. planner: 'baseline' or 'proposed' (reuse: 'samples', 'steering' or both). "
      "ValueError (the command's message) when start or goal is not certified free.");
  m.def(
      "tour",
      [](const PyScene& scene, const py::object& sequence, long long seed,
         const std::string& planner, std::optional<std::string> reuse) {
        scene.validate();
        std::vector<std::string> ids;
        if (py::isinstance<py::str>(sequence))
          ids = api::split_sequence(sequence.cast<std::string>());
        else
          ids = sequence.cast<std::vector<std::string>>();
        api::check_sequence(scene.scene, ids);
        const auto s = static_cast<std::uint64_t>(in_range("seed", seed, 0, 0x7fffffffffffffffLL));
        const auto choice = api::choose_planner(planner, reuse, api::kTourReuse);
        std::string json;
        {
          py::gil_scoped_release release;
          json = api::plan_tour_json(scene.scene, ids, s, choice);
        }
        return json_loads(json);
      },
      py::arg("scene"), py::arg("sequence"), py::kw_only(), py::arg("seed") = 1,
      py::arg("planner") = "baseline", py::arg("reuse") = py::none(),
      "Plans one tour of `sequence` (['door', 'bed', ...] or 'door,bed,...') in the scene's "
      "layout, as `hrspace tour` does, and returns its JSON object as a dict: sequence, found, "
      "legs, metrics, stats.");
}

}  // namespace hrs::python
