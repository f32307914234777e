// SPDX-License-Identifier: GPL-3.0-or-later
// hrspace.design and hrspace.Design: the layout optimizer of `hrspace design`
// (optimize::design with api::design_options), its results as Python
// objects and save() writing the command's four files through the same
// writer (optimize::write_design), so the bytes match.
//
// The GIL is released while the design runs. After every iteration the
// design thread takes the GIL, lets Python run its signal handlers
// (PyErr_CheckSignals) and calls `progress`; an exception there (Ctrl-C's
// KeyboardInterrupt, or one raised by `progress`) stops the run at the end
// of that iteration and is raised once the best design so far is built, with
// that Design as the exception's `design` attribute.

#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <atomic>
#include <cmath>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>

#include "access/accessibility.h"
#include "api/design_request.h"
#include "api/operations.h"
#include "geometry/error.h"
#include "optimize/design.h"
#include "optimize/design_io.h"
#include "python/bindings.h"

namespace hrs::python {

namespace {

struct PyDesign {
  optimize::DesignResult result;
  optimize::RunInfo info;
  api::DesignExtras extras;  //!< accessibility.json's and design.html's text
  std::string label;
  py::object tours, report;  //!< parsed once
};

//! One iteration as progress() gets it: the fields of report.json's trace.
py::dict step_dict(const optimize::DesignStep& s, const geometry::Scene& scene, int iterations) {
  const auto finite_or_none = [](double v) -> py::object {
    return std::isfinite(v) ? py::object(py::float_(v)) : py::object(py::none());
  };
  py::dict d;
  d["iteration"] = s.anneal.iteration + 1;
  d["iterations"] = iterations;
  d["temperature"] = s.anneal.temperature;
  d["object"] = s.anneal.object >= 0 ? py::object(py::str(scene.objects[s.anneal.object].id))
                                     : py::object(py::none());
  d["valid"] = s.anneal.valid;
  d["accepted"] = s.anneal.accepted;
  d["proposed"] = finite_or_none(s.anneal.proposed_cost);
  d["current"] = s.anneal.current_cost;
  d["best"] = finite_or_none(s.anneal.best_cost);
  d["planning_ms"] = s.planning_ms;
  return d;
}

//! `weights` as --weights text: None, a string "L,R,C[,D,A]" or a sequence
//! of 3 or 5 numbers (written exactly, so the shared parser sees the values).
std::optional<std::string> weights_text(const py::object& weights) {
  if (weights.is_none()) return std::nullopt;
  if (py::isinstance<py::str>(weights)) return weights.cast<std::string>();
  std::string text;
  for (const py::handle item : weights) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", item.cast<double>());
    text += (text.empty() ? "" : ",") + std::string(buf);
  }
  return text;
}

py::object run_design(const PyScene& scene, long long seed, long long iterations,
                      const std::string& planner, const std::optional<std::string>& reuse,
                      const std::optional<std::string>& disable, long long threads,
                      const std::string& rules, const py::object& progress,
                      long long access_goal, const py::object& weights, long long designs,
                      long long restarts) {
  scene.validate();
  // The same request, checks and messages as `hrspace design` (api/design_request.h).
  api::DesignRequest request;
  request.planner = planner;
  request.reuse = reuse;
  request.disable = disable;
  request.weights = weights_text(weights);
  request.seed = seed;
  request.iterations = iterations;
  request.designs = designs;
  request.threads = threads;
  request.rules = rules;
  request.access_goal = access_goal;
  request.restarts = restarts;
  request.validate();
  geometry::Scene working = scene.scene;
  request.apply_weights(working);
  geometry::require_sequences(working, scene.label);
  const optimize::PlannerConfig choice = request.planner_config();

  std::atomic<bool> stop{false};
  std::optional<py::error_already_set> pending;  // a Python exception that stopped the run
  std::exception_ptr failure;                    // any other exception from `progress`
  const std::function<void(const optimize::DesignStep&)> step_done =
      [&](const optimize::DesignStep& step) {
        py::gil_scoped_acquire gil;
        if (stop.load()) return;
        try {
          if (!progress.is_none())
            progress(step_dict(step, working, static_cast<int>(request.iterations)));
          if (PyErr_CheckSignals() != 0) throw py::error_already_set();
        } catch (py::error_already_set& e) {
          pending.emplace(std::move(e));
          stop.store(true);
        } catch (...) {
          failure = std::current_exception();
          stop.store(true);
        }
      };

  // The other chains of a design with restarts: Ctrl-C is polled there too.
  const std::function<void()> others = [&] {
    py::gil_scoped_acquire gil;
    if (stop.load()) return;
    if (PyErr_CheckSignals() != 0) {
      pending.emplace(py::error_already_set());
      stop.store(true);
    }
  };

  py::list out;
  for (long long d = 0; d < request.designs && !stop.load(); ++d) {
    const optimize::DesignOptions options = request.options(d);
    auto design = std::make_unique<PyDesign>();
    api::AccessGoalResult goal;
    {
      py::gil_scoped_release release;
      // Try k of design d has seed + d + k·designs, as with the command.
      goal = api::design_for_access(working, options, rules, static_cast<int>(request.access_goal),
                                    static_cast<std::uint64_t>(request.designs),
                                    static_cast<int>(request.restarts), &stop, step_done, {},
                                    others);
    }
    if (failure) std::rethrow_exception(failure);
    design->result = std::move(goal.result);
    design->info = {goal.seed, choice.name(), static_cast<int>(request.iterations)};
    api::add_goal_sections(goal, design->info);
    design->extras = api::attach_extras(design->result, rules, design->info);
    design->label = scene.label;
    design->tours = json_loads(optimize::tours_document(design->result))["tours"];
    design->report = json_loads(optimize::report_document(design->result, design->info));
    out.append(py::cast(std::move(design)));
  }
  py::object result = request.designs == 1 ? py::object(out[0]) : py::object(out);
  // A Ctrl-C during the last iteration (or a run of no iterations).
  if (!pending && PyErr_CheckSignals() != 0) pending.emplace();
  if (pending) {
    py::setattr(pending->value(), "design", result);
    throw std::move(*pending);
  }
  return result;
}

//! hrspace.Design: the result of design() and its files.
void bind_design_result(py::module_& m) {
  py::class_<PyDesign>(m, "Design",
                       "The result of design(): the best layout, its tours and the report.")
      .def_property_readonly(
          "layout",
          [](const PyDesign& d) { return PyScene{d.result.layout, d.label}; },
          "The best layout as a Scene (what layout.json holds); a new copy at each access.")
      .def_readonly("tours", &PyDesign::tours,
                    "The M tours of the best layout: the `tours` list of tours.json (dicts).")
      .def_readonly("report", &PyDesign::report,
                    "report.json as a dict: scene, seed, planner, iterations, cost {initial, "
                    "final, terms}, time_s, acceptance_rate, trace, ...")
      .def_property_readonly(
          "stopped", [](const PyDesign& d) { return d.result.stopped; },
          "True when the run was interrupted before its last iteration.")
      .def_property_readonly(
          "valid", [](const PyDesign& d) { return d.result.valid; },
          "True when the best layout passed every exact check.")
      .def_property_readonly(
          "cost", [](const PyDesign& d) { return d.result.final.total(); },
          "Total cost of the best layout.")
      .def_property_readonly(
          "initial_cost", [](const PyDesign& d) { return d.result.initial.total(); },
          "Total cost of the input layout.")
      .def_property_readonly(
          "svg",
          [](const PyDesign& d) {
            return optimize::design_svg(d.result, api::design_title(d.result, d.info.seed),
                                        d.info.svg_overlay);
          },
          "design.svg's text.")
      .def(
          "save",
          [](const PyDesign& d, const py::object& dir) {
            const std::string path =
                py::module_::import("os").attr("fspath")(dir).cast<std::string>();
            py::gil_scoped_release release;
            api::write_design_files(d.result, d.info, d.extras, path);
          },
          py::arg("dir"),
          "Writes accessibility.json, design.html, layout.json, tours.json, design.svg, "
          "report.json and "
          "manifest.json into `dir` (created if missing), byte for byte what `hrspace design "
          "--out dir` writes for the same run; each file is replaced atomically.")
      .def_property_readonly(
          "accessibility", [](const PyDesign& d) { return json_loads(d.extras.accessibility); },
          "accessibility.json as a dict: route widths, clear floor spaces, turning space, door.")
      .def_property_readonly(
          "html", [](const PyDesign& d) { return d.extras.viewer; },
          "design.html's text: the interactive page (layout, tours with the chair animated, "
          "annealing trace, accessibility overlays), self-contained.")
      .def(
          "_repr_html_",
          [](const PyDesign& d) {
            // A notebook shows the page in a sandboxed iframe (srcdoc), so its
            // script and style stay apart from the notebook's.
            std::string escaped;
            for (const char c : d.extras.viewer) {
              if (c == '&') escaped += "&amp;";
              else if (c == '"') escaped += "&quot;";
              else if (c == '<') escaped += "&lt;";
              else if (c == '>') escaped += "&gt;";
              else escaped += c;
            }
            return "<iframe sandbox=\"allow-scripts\" style=\"width:100%;height:760px;border:0\" "
                   "title=\"hrspace design\" srcdoc=\"" + escaped + "\"></iframe>";
          },
          "The interactive page (design.html) in an iframe, for notebooks.")
      .def("__repr__", [](const PyDesign& d) {
        return "Design('" + d.result.layout.name + "', seed " + std::to_string(d.info.seed) +
               ", cost " + std::to_string(d.result.initial.total()) + " -> " +
               std::to_string(d.result.final.total()) +
               (d.result.stopped ? ", stopped)" : ")");
      });
}

}  // namespace

void bind_design(py::module_& m) {
  bind_design_result(m);
  static const std::string doc =
      "Optimizes the scene's furniture layout as `hrspace design` does (simulated annealing, "
      "every layout toured by the wheelchair) and returns a Design. seed, iterations, "
      "planner (a preset, then optional comma items, as --planner), reuse (replaces the "
      "proposed planner's techniques, as --reuse), disable (design-loop switches to turn off, "
      "as --disable), threads (0: all cores; results do not depend on it) and rules (the "
      "accessibility rule set, ada or iso, as --rules), access_goal (designs tried until "
      "one passes the rules, as --access-goal), weights (3 or 5 numbers, or their text, as "
      "--weights) and designs (as --designs: seeds seed … seed + designs - 1; a list of "
      "Designs when designs > 1) and restarts (annealing chains per design, the lowest "
      "final cost kept, as --restarts) are the "
      "command's options. progress(step) is called after every iteration with a dict (the "
      "fields of report.json's trace: iteration from 1, iterations, temperature, object, valid, "
      "accepted, proposed, current, best, planning_ms). The GIL is released while it runs. "
      "Ctrl-C stops the run at the end of the current iteration and raises KeyboardInterrupt "
      "whose `design` attribute holds the best design so far; an exception raised by progress "
      "stops it the same way.\n\nplanner:\n" +
      optimize::PlannerConfig::help();
  m.def("design", &run_design, py::arg("scene"), py::kw_only(), py::arg("seed") = 1,
        py::arg("iterations") = 700, py::arg("planner") = "default",
        py::arg("reuse") = py::none(), py::arg("disable") = py::none(), py::arg("threads") = 0,
        py::arg("rules") = "ada", py::arg("progress") = py::none(), py::arg("access_goal") = 1,
        py::arg("weights") = py::none(), py::arg("designs") = 1,
        py::arg("restarts") = api::kDefaultRestarts, doc.c_str());
}

}  // namespace hrs::python
