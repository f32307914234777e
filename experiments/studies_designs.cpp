// SPDX-License-Identifier: GPL-3.0-or-later
// The studies of what the designs look like: small_room (§VI-B), ao_graph
// (§VI-C), designs (Fig. "cover3", Fig. 1), and beyond the paper hard_rooms
// and design_loop. docs/experiments.md says what each measures.

#include <algorithm>
#include <cmath>

#include "experiments/stats.h"
#include "experiments/studies_shared.h"
#include "optimize/sequences.h"
#include "planning/tour.h"

namespace hrs::experiments {
namespace {

using shared::design_or_replay;
using shared::design_output;
using shared::int_param;
using shared::kDesignMeasures;
using shared::keep_design;
using shared::load_room;
using shared::make_run;
using shared::param;
using shared::rooms_of;
using shared::run_options;
using shared::seed_list;

// --- small_room -------------------------------------------------------------

std::vector<RunSpec> small_runs(const StudyConfig& c) {
  std::vector<RunSpec> runs;
  const std::vector<std::string> rooms =
      c.rooms.empty() ? std::vector<std::string>{"bedroom", "small_bedroom"} : c.rooms;
  for (const auto& room : rooms)
    for (const auto& seed : seed_list(c))
      for (const char* planner : {"baseline", "paper", "all"})
        runs.push_back(
            make_run("small_room",
                     {{"mode", "design"}, {"room", room}, {"seed", seed}, {"planner", planner}}));
  return runs;
}

RunOutput small_run(const RunSpec& spec, RunContext& context) {
  const bool keep = param(spec, "planner") != "baseline" && int_param(spec, "seed") <= 2;
  return design_or_replay(spec, context, keep);
}

Table small_summary(const Table& runs) {
  Table s = summarize_table(runs, {"room", "planner"}, kDesignMeasures);
  add_ratio(s, "planner", "baseline", {"room"}, "planning_s");
  return s;
}

// --- ao_graph ---------------------------------------------------------------

std::vector<RunSpec> ao_runs(const StudyConfig& c) {
  std::vector<RunSpec> runs;
  const std::vector<std::string> rooms =
      c.rooms.empty() ? std::vector<std::string>{"office", "office_round_table"} : c.rooms;
  // The paper's planner and the default preset with the AO graph's α; the
  // default preset again with uniform α, the control: does the heavier
  // table sit nearer the door because of α, or anyway?
  struct Arm {
    const char* planner;
    const char* alpha;
  };
  for (const Arm arm : {Arm{"paper", "scene"}, Arm{"all", "scene"}, Arm{"all", "uniform"}})
    for (const auto& room : rooms)
      for (const auto& seed : seed_list(c))
        runs.push_back(make_run("ao_graph", {{"room", room},
                                             {"seed", seed},
                                             {"planner", arm.planner},
                                             {"alpha", arm.alpha}}));
  return runs;
}

//! Path length from the door to the first stop at `id`, over the found tours
//! that visit it (mean); NaN when none does.
double tour_distance(const std::vector<planning::Tour>& tours, const std::string& id) {
  double sum = 0.0;
  int n = 0;
  for (const auto& t : tours) {
    if (!t.found) continue;
    double along = 0.0;
    for (const auto& leg : t.legs) {
      along += leg.metrics.length;
      if (leg.to_id == id) {
        sum += along;
        ++n;
        break;
      }
    }
  }
  return n > 0 ? sum / n : std::nan("");
}

RunOutput ao_run(const RunSpec& spec, RunContext& context) {
  const geometry::Scene scene = load_room(context.config, param(spec, "room"));
  const auto seed = static_cast<std::uint64_t>(int_param(spec, "seed"));
  optimize::DesignOptions o = run_options(spec, context);
  o.uniform_alpha = param(spec, "alpha") == "uniform";
  const optimize::DesignResult r = optimize::design(scene, o, context.stop);
  RunOutput out = design_output(r);
  if (out.stopped) return out;
  const auto alpha = optimize::object_scales(r.sequences);
  const geometry::Pose2 door = geometry::door_start_pose(scene);
  // The two objects the paper compares when present, else the two with the
  // largest α (any room can be studied).
  std::vector<std::string> pair;
  if (scene.find_object("office_table") >= 0 && scene.find_object("round_table") >= 0) {
    pair = {"office_table", "round_table"};
  } else {
    std::vector<std::pair<double, std::string>> by_alpha;
    for (const auto& [id, a] : alpha)
      if (id != geometry::kStartNodeId) by_alpha.emplace_back(-a, id);
    std::sort(by_alpha.begin(), by_alpha.end());
    for (std::size_t i = 0; i < std::min<std::size_t>(2, by_alpha.size()); ++i)
      pair.push_back(by_alpha[i].second);
  }
  std::vector<double> a(2, 0.0), d(2, 0.0);
  for (std::size_t i = 0; i < pair.size(); ++i) {
    const auto& obj = r.layout.objects[r.layout.find_object(pair[i])];
    a[i] = alpha.count(pair[i]) ? alpha.at(pair[i]) : 0.0;
    d[i] = std::hypot(obj.pose.x - door.x, obj.pose.y - door.y);
    const std::string n = "obj" + std::to_string(i + 1);
    out.measures.set(n, pair[i]);
    out.measures.set(n + "_alpha", a[i]);
    out.measures.set(n + "_door_dist_m", d[i]);
    out.measures.set(n + "_tour_dist_m", tour_distance(r.tours, pair[i]));
  }
  if (pair.size() == 2 && a[0] != a[1]) {
    const int heavy = a[0] > a[1] ? 0 : 1;
    out.measures.set("heavier", pair[heavy]);
    out.measures.set("heavier_nearer", d[heavy] < d[1 - heavy] ? 1L : 0L);
  }
  if (seed <= 2 && !o.uniform_alpha) keep_design(context, spec.key, r, o, param(spec, "planner"));
  return out;
}

Table ao_summary(const Table& runs) {
  std::vector<std::string> m = kDesignMeasures;
  for (const char* x : {"obj1_alpha", "obj1_door_dist_m", "obj1_tour_dist_m", "obj2_alpha",
                        "obj2_door_dist_m", "obj2_tour_dist_m", "heavier_nearer"})
    m.push_back(x);
  return summarize_table(runs, {"room", "planner", "alpha"}, m);
}

// --- designs ----------------------------------------------------------------

std::vector<RunSpec> designs_runs(const StudyConfig& c) {
  std::vector<RunSpec> runs;
  const int n = std::min(c.seeds, 4);
  for (const char* planner : {"paper", "all"})
    for (const auto& room : rooms_of(c, {"bedroom", "office", "living_room"}))
      for (int seed = 1; seed <= n; ++seed)
        runs.push_back(make_run("designs", {{"figure", "cover"},
                                            {"mode", "design"},
                                            {"room", room},
                                            {"seed", std::to_string(seed)},
                                            {"planner", planner}}));
  const std::string fig1 = c.rooms.empty() ? "bedroom" : c.rooms.front();
  for (const char* w : {"0", "scene"})
    runs.push_back(make_run("designs", {{"figure", "fig1"},
                                        {"mode", "design"},
                                        {"room", fig1},
                                        {"seed", "1"},
                                        {"planner", "all"},
                                        {"path_weights", w}}));
  return runs;
}

RunOutput designs_run(const RunSpec& spec, RunContext& context) {
  return design_or_replay(spec, context, true);
}

Table designs_summary(const Table& runs) {
  return summarize_table(runs, {"figure", "room", "planner", "path_weights"}, kDesignMeasures);
}

// --- hard_rooms and design_loop ---------------------------------------------

//! Rooms the project made hard on purpose (scenes/): a door area sealed off,
//! a narrow passage, a crowded room.
const std::vector<std::string> kHardRooms = {"l_studio", "narrow_passage", "crowded_living"};

std::vector<RunSpec> hard_runs(const StudyConfig& c) {
  std::vector<RunSpec> runs;
  for (const auto& room : rooms_of(c, kHardRooms))
    for (const auto& seed : seed_list(c))
      for (const char* planner : {"baseline", "all"})
        runs.push_back(
            make_run("hard_rooms",
                     {{"mode", "design"}, {"room", room}, {"seed", seed}, {"planner", planner}}));
  return runs;
}

//! The design loop's additions (refused legs, early rejection) on and off,
//! in the paper's rooms and the hard ones, for both planners.
std::vector<RunSpec> loop_runs(const StudyConfig& c) {
  std::vector<std::string> rooms = rooms_of(c, {"bedroom", "office", "living_room"});
  std::vector<RunSpec> runs;
  for (const auto& room : rooms)
    for (const auto& seed : seed_list(c))
      for (const char* planner : {"baseline", "all"})
        for (const char* loop : {"on", "off"})
          runs.push_back(make_run("design_loop", {{"mode", "design"},
                                                  {"room", room},
                                                  {"seed", seed},
                                                  {"planner", planner},
                                                  {"loop", loop}}));
  return runs;
}

RunOutput loop_run(const RunSpec& spec, RunContext& context) {
  const geometry::Scene scene = load_room(context.config, param(spec, "room"));
  optimize::DesignOptions o = run_options(spec, context);
  if (param(spec, "loop") == "off") o.planner.refuse = o.planner.escape = o.planner.early = false;
  return design_output(optimize::design(scene, o, context.stop));
}

Table hard_summary(const Table& runs) {
  Table s = summarize_table(runs, {"room", "planner"}, kDesignMeasures);
  add_ratio(s, "planner", "baseline", {"room"}, "total_s");
  return s;
}

Table loop_summary(const Table& runs) {
  Table s = summarize_table(
      runs, {"room", "planner", "loop"},
      {"total_s", "planning_s", "cost_final", "tours_found", "early_rejections", "legs_refused"});
  add_ratio(s, "loop", "off", {"room", "planner"}, "total_s");
  return s;
}

}  // namespace

Study shared::small_room_study() {
  return {"small_room",
          "§VI-B (+30 % planning time) and Fig. \"small\"",
          "bedroom vs small bedroom, baseline and proposed",
          small_runs,
          small_run,
          small_summary};
}

Study shared::ao_graph_study() {
  return {"ao_graph",
          "§VI-C and Fig. \"actionoffice\"",
          "office vs office_round_table: does the heavier table sit nearer the door?",
          ao_runs,
          ao_run,
          ao_summary};
}

Study shared::designs_study() {
  return {"designs",
          "Fig. \"cover3\" and Fig. 1",
          "designs per room; path weights 0 vs the scene's",
          designs_runs,
          designs_run,
          designs_summary};
}

Study shared::hard_rooms_study() {
  return {"hard_rooms",
          "beyond the paper: rooms made hard on purpose",
          "baseline vs proposed designs in a sealed L-studio, a narrow passage, a crowded room",
          hard_runs,
          [](const RunSpec& s, RunContext& c) { return design_or_replay(s, c); },
          hard_summary};
}

Study shared::design_loop_study() {
  return {"design_loop",
          "beyond the paper: refused legs and early rejection",
          "designs with the design loop's additions on and off, both planners",
          loop_runs,
          loop_run,
          loop_summary};
}

}  // namespace hrs::experiments
