// SPDX-License-Identifier: GPL-3.0-or-later
// What the studies share (experiments/studies_shared.h): the planners they
// compare, rooms, run keys and parameters, and the design or replay run that
// most studies make.

#include "experiments/studies_shared.h"

#include <cctype>
#include <algorithm>
#include <cmath>
#include <string>

#include "api/design_request.h"
#include "api/reuse_list.h"
#include "experiments/runner.h"
#include "geometry/error.h"
#include "optimize/design_io.h"
#include "optimize/planner_config.h"
#include "planning/reuse.h"

namespace hrs::experiments::shared {

namespace fs = std::filesystem;

namespace {

//! Mean length of the found tours.
double mean_tour_length(const std::vector<planning::Tour>& tours) {
  double sum = 0.0;
  int n = 0;
  for (const auto& t : tours) {
    if (!t.found) continue;
    sum += t.metrics.length;
    ++n;
  }
  return n > 0 ? sum / n : std::nan("");
}

//! The measures of a finished design (the columns of its run row).
Row design_measures(const optimize::DesignResult& r) {
  Row m;
  m.set("total_s", r.time_total_s);
  m.set("planning_s", r.time_planning_s);
  m.set("planning_share", r.time_total_s > 0 ? r.time_planning_s / r.time_total_s : 0.0);
  m.set("design_setup_s", r.time_setup_s);
  m.set("anneal_s", r.time_anneal_s);
  m.set("finish_s", r.time_finish_s);
  m.set("grid_s", r.gate_ms / 1e3);
  m.set("cost_initial", r.initial.total());
  m.set("cost_final", r.final.total());
  m.set("tours_found", r.final.tours_found);
  m.set("tours_total", r.final.tours_total);
  m.set("mean_tour_m", mean_tour_length(r.tours));
  m.set("valid", r.valid ? 1L : 0L);
  m.set("acceptance", r.proposals ? static_cast<double>(r.accepted) / r.proposals : 0.0);
  m.set("tours_invalidated", r.tours_invalidated);
  m.set("early_rejections", r.early.proposals);
  m.set("legs_refused", r.legs_refused);
  if (r.proposed) {
    m.set("legs_database", static_cast<long>(r.counters.legs_database));
    m.set("legs_planned", static_cast<long>(r.counters.legs_planned));
    m.set("legs_failed", static_cast<long>(r.counters.legs_failed));
    m.set("trees_reused", static_cast<long>(r.counters.trees_reused));
  }
  return m;
}

}  // namespace

std::string room_label(const std::string& room) {
  return room.ends_with(".json") ? fs::path(room).stem().string() : room;
}

geometry::Scene load_room(const StudyConfig& config, const std::string& room) {
  return geometry::load_scene(scene_path(config, room).string());
}

std::string scene_digest(const StudyConfig& config, const std::string& room) {
  const fs::path path = scene_path(config, room);
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    throw InputError("room '" + room + "': no scene file " + path.string() +
                     (room.ends_with(".json") ? std::string()
                                              : " (names are looked up in --scenes " +
                                                    config.scenes_dir.string() + ")"));
  return file_digest(path);
}

Row planner_identity(const StudyConfig& config, const std::string& planner) {
  const optimize::DesignOptions o = design_options(config, planner, 1);
  Row id;
  id.set("planner_config", o.planner.name());
  return id;
}

Row run_identity(const RunSpec& spec, const StudyConfig& config) {
  Row id;
  if (const auto room = spec.params.get("room"))
    id.set("scene_digest", scene_digest(config, *room));
  if (const auto planner = spec.params.get("planner")) id.merge(planner_identity(config, *planner));
  return id;
}

std::vector<std::string> rooms_of(const StudyConfig& config, std::vector<std::string> defaults) {
  if (!config.rooms.empty()) return config.rooms;
  if (config.quick) defaults.resize(1);
  return defaults;
}

std::string param(const RunSpec& spec, const std::string& name) {
  const auto v = spec.params.get(name);
  if (!v) throw InputError("run " + spec.key + ": missing parameter " + name);
  return *v;
}

long int_param(const RunSpec& spec, const std::string& name) {
  return std::stol(param(spec, name));
}

RunSpec make_run(const std::string& study, std::vector<std::pair<std::string, std::string>> p) {
  RunSpec s;
  s.key = study;
  for (auto& [k, v] : p) {
    s.params.set(k, v);
    std::string safe = room_label(v);
    for (char& c : safe)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_') c = '_';
    s.key += '-';
    if (k == "seed") s.key += 's';
    s.key += safe;
  }
  return s;
}

std::vector<std::string> seed_list(const StudyConfig& c) {
  std::vector<std::string> s;
  for (int i = 1; i <= c.seeds; ++i) s.push_back(std::to_string(i));
  return s;
}

api::DesignRequest design_request(const StudyConfig& config, const std::string& planner,
                                  std::uint64_t seed) {
  api::DesignRequest r;
  r.planner = planner;
  if (planner == "all") r.planner = "default";
  if (planner == "samples_steering") r.planner = "default", r.reuse = "samples,steering";
  if (planner == "none") r.planner = "default", r.reuse = "none";
  r.seed = static_cast<long long>(seed);
  r.iterations = config.iterations;
  r.threads = config.threads;
  return r;
}

optimize::DesignOptions design_options(const StudyConfig& config, const std::string& planner,
                                       std::uint64_t seed) {
  return design_request(config, planner, seed).options();
}

optimize::DesignOptions run_options(const RunSpec& spec, const RunContext& context) {
  return design_options(context.config, param(spec, "planner"),
                        static_cast<std::uint64_t>(int_param(spec, "seed")));
}

RunOutput design_output(const optimize::DesignResult& r) {
  RunOutput out;
  out.stopped = r.stopped;
  if (!out.stopped) out.measures = design_measures(r);
  return out;
}

void keep_design(const RunContext& context, const std::string& key, const optimize::DesignResult& r,
                 const optimize::DesignOptions& o, const std::string& planner) {
  optimize::RunInfo info{o.seed, planner, o.iterations};
  optimize::write_design(r, info, context.study_dir / "designs" / key);
}

RunOutput design_or_replay(const RunSpec& spec, RunContext& context, bool keep, bool trace) {
  const std::string room = param(spec, "room");
  const std::string planner = param(spec, "planner");
  const std::string mode = param(spec, "mode");
  const auto seed = static_cast<std::uint64_t>(int_param(spec, "seed"));
  geometry::Scene scene = load_room(context.config, room);
  if (const auto w = spec.params.get("path_weights"); w && *w == "0")
    scene.weights.path = {0, 0, 0};
  optimize::DesignOptions o = design_options(context.config, planner, seed);
  RunOutput out;
  // Recordings are keyed by the scene's contents, not only its name: an
  // edited scene of the same file name records its own layouts.
  const std::string label = room_label(room) + "-" + scene_digest(context.config, room);
  if (mode == "design") {
    Recordings::Layouts layouts;
    const bool record = planner == "baseline" && !spec.params.get("path_weights");
    if (record) o.layouts_out = &layouts;
    const optimize::DesignResult r = optimize::design(scene, o, context.stop);
    out = design_output(r);
    if (out.stopped) return out;
    if (record) context.recordings->put(label, seed, o.iterations, layouts);
    if (keep) keep_design(context, spec.key, r, o, planner);
    if (trace) {
      Table t;
      for (std::size_t i = 0; i < r.trace.size(); ++i) {
        Row row;
        row.set("iteration", static_cast<long>(r.trace[i].anneal.iteration));
        row.set("planning_ms", r.trace[i].planning_ms);
        row.set("planned", r.trace[i].planned ? 1L : 0L);
        row.set("best_cost", r.trace[i].anneal.best_cost);
        t.push_back(std::move(row));
      }
      out.tables.emplace_back("trace", std::move(t));
    }
    return out;
  }
  // Replay: the layouts the baseline design of this room and seed planned.
  const Recordings::Layouts layouts =
      context.recordings->get(label, seed, context.config.iterations, [&] {
        optimize::DesignOptions b = design_options(context.config, "baseline", seed);
        Recordings::Layouts recorded;
        b.layouts_out = &recorded;
        optimize::design(scene, b, context.stop);
        return recorded;
      });
  if (context.stop && context.stop->load()) {
    out.stopped = true;
    return out;
  }
  const optimize::ReplayResult r = optimize::replay_planning(scene, layouts, o);
  out.measures.set("planning_s", r.planning_s);
  out.measures.set("setup_s", r.setup_s);
  out.measures.set("layouts", r.layouts);
  out.measures.set(
      "tours_found_pct",
      r.tours_total ? 100.0 * static_cast<double>(r.tours_found) / r.tours_total : 0.0);
  out.measures.set("mean_tour_m", r.tours_found ? r.tour_length / r.tours_found : std::nan(""));
  out.measures.set("tours_invalidated", r.tours_invalidated);
  return out;
}

}  // namespace hrs::experiments::shared
