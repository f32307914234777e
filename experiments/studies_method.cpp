// SPDX-License-Identifier: GPL-3.0-or-later
// The method study: the figures of the method rather than of a result, the
// AO graphs (Fig. "actiongraph") and the goal poses and one leg of a designed
// layout (Fig. "goal").

#include <cmath>
#include <filesystem>

#include "experiments/runner.h"
#include "experiments/stats.h"
#include "experiments/studies_shared.h"
#include "geometry/cspace.h"
#include "planning/tour.h"

namespace hrs::experiments {
namespace {

namespace fs = std::filesystem;
using shared::design_options;
using shared::int_param;
using shared::load_room;
using shared::make_run;
using shared::param;
using shared::room_label;

// --- method figures ---------------------------------------------------------

std::vector<RunSpec> method_runs(const StudyConfig& c) {
  const std::string room = c.rooms.empty() ? "bedroom" : c.rooms.front();
  return {make_run("method", {{"room", room}, {"seed", "1"}})};
}

//! Rows x, y, theta, slot of the goal poses of object `id`.
void add_goal_rows(Table& goals, const planning::TourPlanner& planner, const std::string& id) {
  for (const auto& g : planner.goals_for(id)) {
    Row row;
    row.set("object", id);
    row.set("x", g.pose.x);
    row.set("y", g.pose.y);
    row.set("theta", g.pose.theta);
    row.set("slot", g.slot);
    goals.push_back(std::move(row));
  }
}

//! The rooms whose AO graphs the method run draws: the paper's, or --rooms.
std::vector<std::string> graph_rooms(const StudyConfig& config) {
  return config.rooms.empty()
             ? std::vector<std::string>{"bedroom", "office", "office_round_table", "living_room"}
             : config.rooms;
}

//! The edges of the AO graph of each room (Fig. "actiongraph").
Table ao_edges(const StudyConfig& config) {
  Table edges;
  for (const auto& name : graph_rooms(config)) {
    const geometry::Scene s = load_room(config, name);
    for (const auto& [from, row] : s.activity.transitions)
      for (const auto& [to, p] : row) {
        Row e;
        e.set("graph", room_label(name));
        e.set("from", from);
        e.set("to", to);
        e.set("p", p);
        edges.push_back(std::move(e));
      }
  }
  return edges;
}

RunOutput method_run(const RunSpec& spec, RunContext& context) {
  // A designed layout (proposed planner, this seed): the initial layouts of
  // the shipped rooms block some legs, a design shows the method at work.
  const geometry::Scene input = load_room(context.config, param(spec, "room"));
  const auto seed = static_cast<std::uint64_t>(int_param(spec, "seed"));
  const optimize::DesignResult designed =
      optimize::design(input, design_options(context.config, "all", seed), context.stop);
  RunOutput out;
  if (designed.stopped) {
    out.stopped = true;
    return out;
  }
  const geometry::Scene& scene = designed.layout;
  const geometry::CSpace cspace(scene);
  planning::TourPlanner planner(scene, cspace, {}, seed);
  // Goal poses around the first two objects (the bed and the TV in the
  // paper's Fig. "goal") and the leg between them, from the tour door →
  // first → second.
  const std::string first = scene.objects.front().id;
  const std::string second = scene.objects.size() > 1 ? scene.objects[1].id : first;
  Table goals;
  add_goal_rows(goals, planner, first);
  add_goal_rows(goals, planner, second);
  const planning::Tour tour = planner.plan({std::string(geometry::kStartNodeId), first, second});
  Table leg;
  if (tour.found && tour.legs.size() == 2) {
    for (const auto& w : tour.legs[1].waypoints) {
      Row row;
      row.set("from", first);
      row.set("to", second);
      row.set("x", w.x);
      row.set("y", w.y);
      row.set("theta", w.theta);
      leg.push_back(std::move(row));
    }
  }
  out.measures.set("goal_object", first);
  out.measures.set("leg_to", second);
  out.measures.set("leg_found", tour.found ? 1L : 0L);
  out.measures.set("leg_length_m", tour.found ? tour.legs[1].metrics.length : std::nan(""));
  out.tables.emplace_back("goals", std::move(goals));
  out.tables.emplace_back("leg", std::move(leg));
  out.tables.emplace_back("ao_edges", ao_edges(context.config));
  // The layout, for drawing the goal figure.
  const fs::path dir = context.study_dir / "designs" / spec.key;
  fs::create_directories(dir);
  write_text_atomic(dir / "layout.json", geometry::write_scene(scene));
  return out;
}

Table method_summary(const Table& runs) {
  return summarize_table(runs, {"room"}, {"leg_found", "leg_length_m"});
}

//! The method run reads its room, designs with the planner "all" and draws
//! the AO graphs of graph_rooms(): each scene's digest is in its identity.
Row method_identity(const RunSpec& spec, const StudyConfig& config) {
  Row id = shared::run_identity(spec, config);
  id.merge(shared::planner_identity(config, "all"));
  std::string graphs;
  for (const auto& room : graph_rooms(config))
    graphs +=
        (graphs.empty() ? "" : ";") + room_label(room) + "=" + shared::scene_digest(config, room);
  id.set("graph_digests", graphs);
  return id;
}

}  // namespace

Study shared::method_study() {
  Study s{"method",
          "Fig. \"actiongraph\" and Fig. \"goal\"",
          "AO graphs; goal poses around an object and one leg",
          method_runs,
          method_run,
          method_summary};
  s.identity = method_identity;
  return s;
}

}  // namespace hrs::experiments
