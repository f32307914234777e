// The studies of the paper's §VI (and its method figures), one function pair
// each: the run list and the run. See study.h for the outputs, docs/
// experiments.md for what each study measures and how it maps to the paper.

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>

#include "api/reuse_list.h"
#include "experiments/runner.h"
#include "experiments/stats.h"
#include "experiments/study.h"
#include "geometry/cspace.h"
#include "geometry/error.h"
#include "geometry/scene.h"
#include "optimize/design.h"
#include "optimize/design_io.h"
#include "optimize/sequences.h"
#include "planning/reuse.h"
#include "planning/tour.h"
#include "rs/decomposition.h"
#include "rs/reeds_shepp.h"

namespace hrs::experiments {

namespace fs = std::filesystem;

namespace {

// --- shared pieces ----------------------------------------------------------

//! The planners the studies compare.
struct PlannerSpec {
  const char* name;
  const char* reuse;  //!< nullptr: the baseline RRT; else api::parse_reuse list
  bool literal;       //!< the paper's literal baseline: tried goal nodes are not skipped
  const char* what;
};

constexpr PlannerSpec kPlanners[] = {
    {"literal", nullptr, true, "the paper's baseline RRT read literally (§III-B)"},
    {"baseline", nullptr, false, "our baseline RRT (tried goal nodes skipped)"},
    {"paper", "samples,steering,paths,trees", false, "proposed, the paper's techniques (§V)"},
    {"all", "all", false, "proposed, every technique"},
    {"samples_steering", "samples,steering", false, "proposed, the RS-decomposition only (§V-A)"},
    {"none", "none", false,
     "proposed with every technique off (= baseline, counts RRT iterations)"},
};

const PlannerSpec& planner_spec(const std::string& name) {
  for (const auto& p : kPlanners)
    if (name == p.name) return p;
  throw InputError("unknown planner '" + name + "'");
}

std::string room_label(const std::string& room) {
  return room.ends_with(".json") ? fs::path(room).stem().string() : room;
}

geometry::Scene load_room(const StudyConfig& config, const std::string& room) {
  if (room.ends_with(".json")) return geometry::load_scene(room);
  return geometry::load_scene((config.scenes_dir / (room + ".json")).string());
}

//! The study's rooms: --rooms when given, else its own (the first only with --quick).
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

optimize::DesignOptions design_options(const StudyConfig& config, const std::string& planner,
                                       std::uint64_t seed) {
  const PlannerSpec& p = planner_spec(planner);
  optimize::DesignOptions o;
  o.seed = seed;
  o.iterations = config.iterations;
  o.threads = config.threads;
  o.proposed = p.reuse != nullptr;
  if (p.reuse) o.reuse = api::parse_reuse(p.reuse);
  if (p.literal) o.tour.planner.skip_tried_goal_nodes = false;
  return o;
}

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

Row design_measures(const optimize::DesignResult& r) {
  Row m;
  m.set("total_s", r.time_total_s);
  m.set("planning_s", r.time_planning_s);
  m.set("planning_share", r.time_total_s > 0 ? r.time_planning_s / r.time_total_s : 0.0);
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

//! The design options of a run: its planner and seed.
optimize::DesignOptions run_options(const RunSpec& spec, const RunContext& context) {
  return design_options(context.config, param(spec, "planner"),
                        static_cast<std::uint64_t>(int_param(spec, "seed")));
}

//! A finished design's measures; a stopped one is marked stopped (not stored).
RunOutput design_output(const optimize::DesignResult& r) {
  RunOutput out;
  out.stopped = r.stopped;
  if (!out.stopped) out.measures = design_measures(r);
  return out;
}

//! Keeps a design's four files under the study's designs/KEY/.
void keep_design(const RunContext& context, const std::string& key, const optimize::DesignResult& r,
                 const optimize::DesignOptions& o, const std::string& planner) {
  optimize::RunInfo info{o.seed, planner, o.iterations};
  optimize::write_design(r, info, context.study_dir / "designs" / key);
}

//! A design run (mode "design") or a replay of the baseline's layouts (mode
//! "replay"): the measures of one (room, planner, seed).
RunOutput design_or_replay(const RunSpec& spec, RunContext& context, bool keep = false) {
  const std::string room = param(spec, "room");
  const std::string planner = param(spec, "planner");
  const std::string mode = param(spec, "mode");
  const auto seed = static_cast<std::uint64_t>(int_param(spec, "seed"));
  geometry::Scene scene = load_room(context.config, room);
  if (const auto w = spec.params.get("path_weights"); w && *w == "0")
    scene.weights.path = {0, 0, 0};
  optimize::DesignOptions o = design_options(context.config, planner, seed);
  RunOutput out;
  const std::string label = room_label(room);
  if (mode == "design") {
    Recordings::Layouts layouts;
    const bool record = planner == "baseline" && !spec.params.get("path_weights");
    if (record) o.layouts_out = &layouts;
    const optimize::DesignResult r = optimize::design(scene, o, context.stop);
    out = design_output(r);
    if (out.stopped) return out;
    if (record) context.recordings->put(label, seed, o.iterations, layouts);
    if (keep) keep_design(context, spec.key, r, o, planner);
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

//! Summary of design/replay runs grouped by `group`, with planning-time
//! ratios against each reference planner present.
const std::vector<std::string> kDesignMeasures = {
    "total_s",     "planning_s",  "planning_share", "cost_initial",      "cost_final",
    "tours_found", "tours_total", "mean_tour_m",    "tours_found_pct",   "acceptance",
    "layouts",     "valid",       "setup_s",        "tours_invalidated", "trees_reused"};

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

//! The decomposition at a radius, in an empty room twice the size of the
//! first room's bounding box (§V-A), and its accuracy on random queries.
RunOutput rsd_regions(const RunSpec& spec, RunContext& context) {
  const std::string first = rooms_of(context.config, {"bedroom"}).front();
  const geometry::Scene scene = load_room(context.config, first);
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const auto& v : scene.room.polygon) {
    x0 = std::min(x0, v.x);
    x1 = std::max(x1, v.x);
    y0 = std::min(y0, v.y);
    y1 = std::max(y1, v.y);
  }
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
                        "infeasible_fraction", "mean_relative_excess"})
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
  if (const auto t = spec.params.get("tree_max_nodes")) o.reuse.tree_max_nodes = std::stoi(*t);
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

// --- small_room -------------------------------------------------------------

std::vector<RunSpec> small_runs(const StudyConfig& c) {
  std::vector<RunSpec> runs;
  const std::vector<std::string> rooms =
      c.rooms.empty() ? std::vector<std::string>{"bedroom", "small_bedroom"} : c.rooms;
  for (const auto& room : rooms)
    for (const auto& seed : seed_list(c))
      for (const char* planner : {"baseline", "all"})
        runs.push_back(
            make_run("small_room",
                     {{"mode", "design"}, {"room", room}, {"seed", seed}, {"planner", planner}}));
  return runs;
}

RunOutput small_run(const RunSpec& spec, RunContext& context) {
  const bool keep = param(spec, "planner") == "all" && int_param(spec, "seed") <= 2;
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
  for (const auto& room : rooms)
    for (const auto& seed : seed_list(c))
      runs.push_back(make_run("ao_graph", {{"room", room}, {"seed", seed}, {"planner", "all"}}));
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
  const optimize::DesignOptions o = run_options(spec, context);
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
      if (id != planning::kDoorId) by_alpha.emplace_back(-a, id);
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
  if (seed <= 2) keep_design(context, spec.key, r, o, param(spec, "planner"));
  return out;
}

Table ao_summary(const Table& runs) {
  std::vector<std::string> m = kDesignMeasures;
  for (const char* x : {"obj1_alpha", "obj1_door_dist_m", "obj1_tour_dist_m", "obj2_alpha",
                        "obj2_door_dist_m", "obj2_tour_dist_m", "heavier_nearer"})
    m.push_back(x);
  return summarize_table(runs, {"room"}, m);
}

// --- designs ----------------------------------------------------------------

std::vector<RunSpec> designs_runs(const StudyConfig& c) {
  std::vector<RunSpec> runs;
  const int n = std::min(c.seeds, 4);
  for (const auto& room : rooms_of(c, {"bedroom", "office", "living_room"}))
    for (int seed = 1; seed <= n; ++seed)
      runs.push_back(make_run("designs", {{"figure", "cover"},
                                          {"mode", "design"},
                                          {"room", room},
                                          {"seed", std::to_string(seed)},
                                          {"planner", "all"}}));
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
  return summarize_table(runs, {"figure", "room", "path_weights"}, kDesignMeasures);
}

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

//! The edges of the AO graph of each room (Fig. "actiongraph"): the
//! paper's rooms, or --rooms.
Table ao_edges(const StudyConfig& config) {
  Table edges;
  const std::vector<std::string> graphs =
      config.rooms.empty()
          ? std::vector<std::string>{"bedroom", "office", "office_round_table", "living_room"}
          : config.rooms;
  for (const auto& name : graphs) {
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
  const planning::Tour tour = planner.plan({std::string(planning::kDoorId), first, second});
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
            make_run("hard_rooms", {{"mode", "design"}, {"room", room}, {"seed", seed},
                                    {"planner", planner}}));
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
          runs.push_back(make_run("design_loop", {{"mode", "design"}, {"room", room},
                                                  {"seed", seed}, {"planner", planner},
                                                  {"loop", loop}}));
  return runs;
}

RunOutput loop_run(const RunSpec& spec, RunContext& context) {
  const geometry::Scene scene = load_room(context.config, param(spec, "room"));
  optimize::DesignOptions o = run_options(spec, context);
  if (param(spec, "loop") == "off") o.refuse_impossible = o.early_reject = false;
  return design_output(optimize::design(scene, o, context.stop));
}

Table hard_summary(const Table& runs) {
  Table s = summarize_table(runs, {"room", "planner"}, kDesignMeasures);
  add_ratio(s, "planner", "baseline", {"room"}, "total_s");
  return s;
}

Table loop_summary(const Table& runs) {
  Table s = summarize_table(runs, {"room", "planner", "loop"},
                            {"total_s", "planning_s", "cost_final", "tours_found",
                             "early_rejections", "legs_refused"});
  add_ratio(s, "loop", "off", {"room", "planner"}, "total_s");
  return s;
}

Table method_summary(const Table& runs) {
  return summarize_table(runs, {"room"}, {"leg_found", "leg_length_m"});
}

}  // namespace

const std::vector<Study>& studies() {
  static const std::vector<Study> all = {
      {"timing",
       "Fig. \"time\", the abstract's minutes, the 96.06 % planning share, the 65-70 % reduction "
       "(§VI-A)",
       "baseline vs proposed planners: whole designs and replays of identical layouts", timing_runs,
       [](const RunSpec& s, RunContext& c) { return design_or_replay(s, c); }, timing_summary},
      {"rs_decomposition", "§V-A's -40 %, Fig. \"partition\", the 48 regions",
       "RS-decomposition: regions and word accuracy; samples+steering vs baseline on replays",
       rsd_runs, rsd_run, rsd_summary},
      {"rrt_iterations", "Fig. \"rrt-it\" and the 30-node tree rebuild rule (§V-C)",
       "RRT iterations per found leg; sweep of the tree rebuild threshold", rrt_runs, rrt_run,
       rrt_summary},
      {"small_room", "§VI-B (+30 % planning time) and Fig. \"small\"",
       "bedroom vs small bedroom, baseline and proposed", small_runs, small_run, small_summary},
      {"ao_graph", "§VI-C and Fig. \"actionoffice\"",
       "office vs office_round_table: does the heavier table sit nearer the door?", ao_runs, ao_run,
       ao_summary},
      {"designs", "Fig. \"cover3\" and Fig. 1", "designs per room; path weights 0 vs the scene's",
       designs_runs, designs_run, designs_summary},
      {"hard_rooms", "beyond the paper: rooms made hard on purpose",
       "baseline vs proposed designs in a sealed L-studio, a narrow passage, a crowded room",
       hard_runs, [](const RunSpec& s, RunContext& c) { return design_or_replay(s, c); },
       hard_summary},
      {"design_loop", "beyond the paper: refused legs and early rejection",
       "designs with the design loop's additions on and off, both planners", loop_runs,
       loop_run, loop_summary},
      {"method", "Fig. \"actiongraph\" and Fig. \"goal\"",
       "AO graphs; goal poses around an object and one leg", method_runs, method_run,
       method_summary},
  };
  return all;
}

const Study* find_study(const std::string& name) {
  for (const Study& s : studies())
    if (s.name == name) return &s;
  return nullptr;
}

}  // namespace hrs::experiments
