// SPDX-License-Identifier: GPL-3.0-or-later
// The studies of how fast the planners are: timing (§VI-A, Fig. "time"),
// rs_decomposition (§V-A, Fig. "partition") and rrt_iterations (§V-C,
// Fig. "rrt-it"). docs/experiments.md says what each measures.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>

#include "experiments/stats.h"
#include "experiments/studies_shared.h"
#include "rs/decomposition.h"
#include "rs/reeds_shepp.h"

namespace hrs::experiments {
namespace {

using shared::design_or_replay;
using shared::design_output;
using shared::kDesignMeasures;
using shared::load_room;
using shared::make_run;
using shared::param;
using shared::room_label;
using shared::rooms_of;
using shared::run_options;
using shared::seed_list;

// --- timing -----------------------------------------------------------------

std::vector<RunSpec> timing_runs(const StudyConfig& c) {
  std::vector<RunSpec> runs;
  for (const char* mode : {"design", "replay"})
    for (const auto& room : rooms_of(c, {"bedroom", "office", "living_room"}))
      for (const auto& seed : seed_list(c))
        for (const char* planner : {"baseline", "literal", "paper", "all"})
          runs.push_back(make_run(
              "timing", {{"mode", mode}, {"room", room}, {"seed", seed}, {"planner", planner}}));
  return runs;
}

Table timing_summary(const Table& runs) {
  Table s = summarize_table(runs, {"mode", "room", "planner"}, kDesignMeasures);
  for (const char* ref : {"literal", "baseline"}) {
    add_ratio(s, "planner", ref, {"mode", "room"}, "planning_s");
    add_ratio(s, "planner", ref, {"mode", "room"}, "total_s");
  }
  return s;
}

// --- rs_decomposition -------------------------------------------------------

std::vector<RunSpec> rsd_runs(const StudyConfig& c) {
  std::vector<RunSpec> runs;
  for (const char* radius : {"3", "chair"})
    runs.push_back(make_run("rs_decomposition", {{"kind", "regions"}, {"radius", radius}}));
  for (const auto& room : rooms_of(c, {"bedroom", "office", "living_room"}))
    for (const auto& seed : seed_list(c))
      for (const char* planner : {"baseline", "samples_steering"})
        runs.push_back(make_run("rs_decomposition", {{"kind", "replay"},
                                                     {"mode", "replay"},
                                                     {"room", room},
                                                     {"seed", seed},
                                                     {"planner", planner}}));
  return runs;
}

//! Nanoseconds per call of `f` over `pairs`, the best of 5 passes (the
//! least disturbed by other work on the machine).
template <class F>
double ns_per_query(const std::vector<std::pair<geometry::Pose2, geometry::Pose2>>& pairs, F f) {
  double best = std::numeric_limits<double>::infinity();
  volatile double sink = 0.0;
  for (int pass = 0; pass < 5; ++pass) {
    const auto t0 = std::chrono::steady_clock::now();
    double sum = 0.0;
    for (const auto& [a, b] : pairs) sum += f(a, b);
    const auto t1 = std::chrono::steady_clock::now();
    sink = sink + sum;
    best = std::min(best, std::chrono::duration<double, std::nano>(t1 - t0).count() /
                              static_cast<double>(pairs.size()));
  }
  return best;
}

//! The cost of the decomposition's look-up (§V-A) against the exact
//! shortest RS length it approximates: random pairs "near" (both poses in
//! a 1 m box) and "far" (in a box of the room's size), ns per query.
void rsd_lookup_cost(const rs::Decomposition& d, RunOutput& out) {
  const double radius = d.options().radius;
  for (const char* which : {"near", "far"}) {
    const double half =
        std::string(which) == "near" ? 1.0 : std::max(d.options().room_width, d.options().room_depth);
    std::mt19937_64 rng(std::string(which) == "near" ? 43 : 42);
    std::uniform_real_distribution<double> pos(-half, half), ang(-std::numbers::pi, std::numbers::pi);
    std::vector<std::pair<geometry::Pose2, geometry::Pose2>> pairs(4096);
    for (auto& [a, b] : pairs) {
      a = {pos(rng), pos(rng), ang(rng)};
      b = {pos(rng), pos(rng), ang(rng)};
    }
    const std::string w = which;
    out.measures.set("lookup_ns_" + w, ns_per_query(pairs, [&](const auto& a, const auto& b) {
                       const double l = d.predicted_length(a, b);
                       return std::isfinite(l) ? l : 0.0;
                     }));
    out.measures.set("exact_ns_" + w, ns_per_query(pairs, [&](const auto& a, const auto& b) {
                       return rs::shortest_length(a, b, radius);
                     }));
  }
}

//! The decomposition at a radius, in an empty room twice the size of the
//! first room's bounding box (§V-A), and its accuracy on random queries.
RunOutput rsd_regions(const RunSpec& spec, RunContext& context) {
  const std::string first = rooms_of(context.config, {"bedroom"}).front();
  const geometry::Scene scene = load_room(context.config, first);
  const auto [x0, y0, x1, y1] = geometry::bounding_box(scene.room.polygon);
  rs::DecompositionOptions o;
  const std::string r = param(spec, "radius");
  o.radius = r == "chair" ? scene.wheelchair.turning_radius : std::stod(r);
  o.room_width = x1 - x0;
  o.room_depth = y1 - y0;
  std::mt19937_64 rng(1);
  const rs::Decomposition d(o, rng);
  std::mt19937_64 query_rng(2);
  const rs::DecompositionAccuracy a = d.evaluate(context.config.quick ? 2000 : 20000, query_rng);
  RunOutput out;
  out.measures.set("radius_m", o.radius);
  out.measures.set("room", room_label(first));
  out.measures.set("box_width_m", 2 * o.room_width);
  out.measures.set("box_depth_m", 2 * o.room_depth);
  out.measures.set("samples", static_cast<long>(d.samples().size()));
  out.measures.set("drawn", static_cast<long>(d.drawn()));
  out.measures.set("regions", d.region_count());
  out.measures.set("word_accuracy", a.word_accuracy);
  out.measures.set("infeasible_fraction", a.infeasible_fraction);
  out.measures.set("mean_relative_excess", a.mean_relative_excess);
  out.measures.set("queries", a.queries);
  rsd_lookup_cost(d, out);
  Table samples;
  for (const auto& s : d.samples()) {
    Row row;
    row.set("x", s.pose.x);
    row.set("y", s.pose.y);
    row.set("theta", s.pose.theta);
    row.set("word", std::string(rs::word_name(s.word)));
    samples.push_back(std::move(row));
  }
  out.tables.emplace_back("samples", std::move(samples));
  return out;
}

RunOutput rsd_run(const RunSpec& spec, RunContext& context) {
  if (param(spec, "kind") == "regions") return rsd_regions(spec, context);
  return design_or_replay(spec, context);
}

Table rsd_summary(const Table& runs) {
  std::vector<std::string> m = kDesignMeasures;
  for (const char* x : {"radius_m", "samples", "drawn", "regions", "word_accuracy",
                        "infeasible_fraction", "mean_relative_excess", "lookup_ns_near",
                        "exact_ns_near", "lookup_ns_far", "exact_ns_far"})
    m.push_back(x);
  Table s = summarize_table(runs, {"kind", "room", "planner", "radius"}, m);
  add_ratio(s, "planner", "baseline", {"kind", "room"}, "planning_s");
  return s;
}

// --- rrt_iterations ---------------------------------------------------------

std::vector<std::string> thresholds(const StudyConfig& c) {
  if (c.quick) return {"10", "30"};
  return {"10", "20", "30", "50", "100"};
}

std::vector<RunSpec> rrt_runs(const StudyConfig& c) {
  std::vector<RunSpec> runs;
  for (const auto& room : rooms_of(c, {"bedroom", "office", "living_room"}))
    for (const auto& seed : seed_list(c))
      runs.push_back(make_run("rrt_iterations", {{"kind", "histogram"},
                                                 {"mode", "design"},
                                                 {"room", room},
                                                 {"seed", seed},
                                                 {"planner", "none"}}));
  for (const auto& room : rooms_of(c, {"bedroom", "office", "living_room"}))
    for (const auto& seed : seed_list(c))
      for (const auto& t : thresholds(c))
        runs.push_back(make_run("rrt_iterations", {{"kind", "threshold"},
                                                   {"mode", "design"},
                                                   {"room", room},
                                                   {"seed", seed},
                                                   {"planner", "paper"},
                                                   {"tree_max_nodes", t}}));
  return runs;
}

RunOutput rrt_run(const RunSpec& spec, RunContext& context) {
  const geometry::Scene scene = load_room(context.config, param(spec, "room"));
  optimize::DesignOptions o = run_options(spec, context);
  if (const auto t = spec.params.get("tree_max_nodes")) o.planner.reuse.tree_max_nodes = std::stoi(*t);
  const optimize::DesignResult r = optimize::design(scene, o, context.stop);
  RunOutput out = design_output(r);
  if (out.stopped) return out;
  if (param(spec, "kind") == "histogram") {
    Table h;
    std::uint64_t legs = 0, within = 0;
    for (const auto& [iterations, count] : r.counters.rrt_iterations) {
      Row row;
      row.set("rrt_iterations", static_cast<long>(iterations));
      row.set("legs", static_cast<long>(count));
      h.push_back(std::move(row));
      legs += count;
      if (iterations <= 30) within += count;
    }
    out.measures.set("legs_found_fresh", static_cast<long>(legs));
    out.measures.set("share_within_30", legs ? static_cast<double>(within) / legs : std::nan(""));
    out.tables.emplace_back("histogram", std::move(h));
  }
  return out;
}

Table rrt_summary(const Table& runs) {
  std::vector<std::string> m = kDesignMeasures;
  m.push_back("legs_found_fresh");
  m.push_back("share_within_30");
  return summarize_table(runs, {"kind", "room", "tree_max_nodes"}, m);
}

// --- sensitivity ------------------------------------------------------------

//! The parameter settings of the sensitivity sweep: the paper's values
//! (M = 10 sequences, k = 10 nearest nodes, goal-pose density 2) and one
//! parameter at a time halved and doubled.
std::vector<std::string> sensitivity_settings(const StudyConfig& c) {
  if (c.quick) return {"base", "m=5"};
  return {"base", "m=5", "m=20", "k=5", "k=20", "density=1", "density=4"};
}

std::vector<RunSpec> sensitivity_runs(const StudyConfig& c) {
  std::vector<RunSpec> runs;
  const int seeds = std::min(c.seeds, 5);
  for (const auto& room : rooms_of(c, {"bedroom"}))
    for (const auto& setting : sensitivity_settings(c))
      for (int seed = 1; seed <= seeds; ++seed)
        runs.push_back(make_run("sensitivity", {{"mode", "design"},
                                                {"room", room},
                                                {"seed", std::to_string(seed)},
                                                {"planner", "all"},
                                                {"setting", setting}}));
  return runs;
}

RunOutput sensitivity_run(const RunSpec& spec, RunContext& context) {
  geometry::Scene scene = load_room(context.config, param(spec, "room"));
  optimize::DesignOptions o = run_options(spec, context);
  const std::string setting = param(spec, "setting");
  if (setting != "base") {
    const std::size_t eq = setting.find('=');
    const std::string name = setting.substr(0, eq);
    const double value = std::stod(setting.substr(eq + 1));
    if (name == "m") scene.activity.sequences = static_cast<int>(value);
    if (name == "k") o.tour.planner.k_nearest = static_cast<int>(value);
    if (name == "density") o.tour.goals.density = value;
  }
  RunOutput out = design_output(optimize::design(scene, o, context.stop));
  if (out.stopped) return out;
  out.measures.set("m", scene.activity.sequences);
  out.measures.set("k", o.tour.planner.k_nearest);
  out.measures.set("density", o.tour.goals.density);
  return out;
}

Table sensitivity_summary(const Table& runs) {
  Table s = summarize_table(runs, {"room", "setting"}, kDesignMeasures);
  add_ratio(s, "setting", "base", {"room"}, "planning_s");
  return s;
}

}  // namespace

Study shared::sensitivity_study() {
  return {"sensitivity",
          "beyond the paper: M, k and the goal-pose density (§III-A, §III-B, §III-C)",
          "designs with M, k or the goal-pose density halved and doubled, default planner",
          sensitivity_runs,
          sensitivity_run,
          sensitivity_summary};
}

Study shared::timing_study() {
  return {"timing",
          "Fig. \"time\", the abstract's minutes, the 96.06 % planning share, the 65-70 % "
          "reduction (§VI-A)",
          "baseline vs proposed planners: whole designs and replays of identical layouts",
          timing_runs,
          [](const RunSpec& s, RunContext& c) { return design_or_replay(s, c, false, true); },
          timing_summary};
}

Study shared::rs_decomposition_study() {
  Study s{"rs_decomposition",
          "§V-A's -40 %, Fig. \"partition\", the 48 regions",
          "RS-decomposition: regions and word accuracy; samples+steering vs baseline on replays",
          rsd_runs,
          rsd_run,
          rsd_summary};
  // A regions run has no room parameter but sizes its box by the first room.
  s.identity = [](const RunSpec& spec, const StudyConfig& config) {
    Row id = shared::run_identity(spec, config);
    if (param(spec, "kind") == "regions")
      id.set("scene_digest", shared::scene_digest(config, rooms_of(config, {"bedroom"}).front()));
    return id;
  };
  return s;
}

Study shared::rrt_iterations_study() {
  return {"rrt_iterations",
          "Fig. \"rrt-it\" and the 30-node tree rebuild rule (§V-C)",
          "RRT iterations per found leg; sweep of the tree rebuild threshold",
          rrt_runs,
          rrt_run,
          rrt_summary};
}

}  // namespace hrs::experiments
