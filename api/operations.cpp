// SPDX-License-Identifier: GPL-3.0-or-later
#include "api/operations.h"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "access/accessibility.h"
#include "api/reuse_list.h"
#include "geometry/error.h"
#include "geometry/free_grid.h"
#include "geometry/polygon_ops.h"
#include "geometry/random.h"
#include "io/files.h"
#include "planning/reuse.h"
#include "planning/rrt.h"
#include "planning/tour.h"
#include "planning/tour_json.h"
#include "view/viewer.h"

namespace hrs::api {

std::optional<planning::ReuseOptions> choose_planner(const std::string& planner,
                                                     const std::optional<std::string>& reuse,
                                                     const ReuseRule& rule) {
  if (planner != "baseline" && planner != "proposed" && planner != "default")
    throw InputError("--planner: unknown planner '" + planner +
                     "' (baseline, or default for the proposed planner)");
  if (reuse && planner == "baseline") throw InputError("--reuse needs --planner default");
  if (planner == "baseline") return std::nullopt;
  const std::string list = reuse.value_or(rule.fallback);
  const std::string allowed = rule.allowed;
  planning::ReuseOptions o = parse_reuse(list);
  const planning::ReuseOptions ok = parse_reuse(allowed);
  planning::ReuseOptions extra = planning::ReuseOptions::none();
  for (const auto& t : planning::ReuseOptions::techniques()) extra.*t.on = o.*t.on && !(ok.*t.on);
  if (extra.any())
    throw InputError("--reuse: '" + list + "': " + extra.names() +
                     " would do nothing here; this command takes " + allowed +
                     " (the others reuse work across the layouts of a design: see hrspace "
                     "design --planner proposed)");
  return o;
}

std::string planner_name(const std::optional<planning::ReuseOptions>& reuse) {
  return reuse ? "proposed" : "baseline";
}

void require_free(const geometry::Scene& scene, const geometry::CSpace& cspace,
                  const geometry::Pose2& pose, const std::string& what) {
  if (cspace.is_free(pose)) return;
  const geometry::Polygon chair = geometry::chair_footprint(scene.wheelchair, pose);
  std::ostringstream at;
  at << what << " pose " << pose.x << "," << pose.y << "," << pose.theta << ": ";
  if (!geometry::polygon_inside(chair, scene.room.polygon))
    throw InputError(at.str() + "the wheelchair is outside the room");
  for (int i = 0; i < cspace.object_count(); ++i) {
    geometry::Object o = scene.objects[i];
    o.pose = cspace.object_pose(i);
    if (geometry::interiors_overlap(chair, geometry::world_footprint(o)))
      throw InputError(at.str() + "the wheelchair collides with object '" + o.id + "'");
  }
  throw InputError(
      at.str() + "the wheelchair touches or nearly touches a wall or object (not certified free)");
}

std::vector<std::string> split_sequence(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  std::string id;
  while (std::getline(ss, id, ',')) {
    if (id.empty()) throw InputError("--sequence: empty object id in '" + text + "'");
    out.push_back(id);
  }
  if (out.empty()) throw InputError("--sequence: no object ids");
  return out;
}

void check_sequence(const geometry::Scene& scene, const std::vector<std::string>& sequence) {
  if (sequence.empty()) throw InputError("--sequence: no object ids");
  for (const std::string& id : sequence) {
    if (id != geometry::kStartNodeId && scene.find_object(id) < 0)
      throw InputError("--sequence: unknown object id '" + id + "'");
  }
}

std::string plan_leg_json(const geometry::Scene& scene, const geometry::Pose2& from,
                          const geometry::Pose2& to, const LegSettings& settings) {
  const geometry::CSpace cspace(scene);
  require_free(scene, cspace, from, "--from");
  require_free(scene, cspace, to, "--to");
  if (!(settings.step > 0.0)) throw InputError("--step: must be > 0");
  planning::PlannerOptions options;
  options.max_iterations = settings.iterations;
  options.step_length = settings.step;
  planning::TourOptions tour;
  tour.planner = options;
  std::unique_ptr<planning::ReusePlanner> proposed;
  if (settings.reuse)
    proposed = std::make_unique<planning::ReusePlanner>(scene, cspace, tour, *settings.reuse,
                                                        settings.seed);
  planning::LegPlanner planner(scene, cspace, options,
                               proposed ? proposed->hooks().planner : planning::PlannerHooks{});
  const planning::LegResult result = planner.plan(from, to, settings.seed);
  // Not found: is there any motion at all? (A certificate, or "not proven".)
  bool impossible = false;
  if (!result.found) {
    try {
      const geometry::FreeGrid grid(scene);
      geometry::ReachabilityQuery query;
      impossible = query.query(grid, from, to, grid.cell_count()) ==
                   geometry::ReachabilityQuery::Answer::kDisconnected;
    } catch (const std::invalid_argument&) {
      // The chair is too small for the grid's cells: nothing is proven.
    }
  }
  return planning::plan_json(from, to, result, scene.wheelchair.turning_radius, impossible);
}

std::string plan_tour_json(const geometry::Scene& scene, const std::vector<std::string>& sequence,
                           std::uint64_t seed, const std::optional<planning::ReuseOptions>& reuse) {
  check_sequence(scene, sequence);
  const geometry::CSpace cspace(scene);
  std::unique_ptr<planning::ReusePlanner> proposed;
  if (reuse) {
    proposed = std::make_unique<planning::ReusePlanner>(scene, cspace, planning::TourOptions{},
                                                        *reuse, seed);
    proposed->begin_iteration(seed);
  }
  planning::TourPlanner planner(scene, cspace, {}, seed,
                                proposed ? proposed->hooks() : planning::TourHooks{});
  const planning::Tour tour = planner.plan(sequence);
  if (proposed) proposed->end_iteration();
  return planning::tour_json(tour);
}

optimize::PlannerConfig design_planner(const std::string& planner,
                                       const std::optional<std::string>& reuse,
                                       const std::optional<std::string>& disable) {
  optimize::PlannerConfig c = parse_planner(planner, "--planner");
  if (reuse) {
    if (!c.proposed)
      throw InputError("--reuse: the " + c.preset +
                       " preset plans each leg with the RRT, which has no reuse techniques "
                       "(use --planner default or paper)");
    c.reuse = parse_reuse(*reuse);
  }
  if (disable && *disable != "none") {
    for (std::size_t start = 0; start <= disable->size();) {
      const std::size_t end = std::min(disable->find(',', start), disable->size());
      const std::string name = disable->substr(start, end - start);
      start = end + 1;
      bool known = false;
      for (const optimize::PlannerConfig::Switch& s : optimize::PlannerConfig::switches()) {
        if (name != s.name) continue;
        c.*s.on = false;
        known = true;
      }
      if (!known) {
        std::string list;
        for (const optimize::PlannerConfig::Switch& s : optimize::PlannerConfig::switches())
          list += std::string(list.empty() ? "" : ", ") + s.name;
        throw InputError("--disable '" + *disable + "': unknown item '" + name +
                         "' (expected none or a comma list of " + list + ")");
      }
    }
  }
  return c;
}

optimize::DesignOptions design_options(std::uint64_t seed, int iterations, int threads,
                                       const optimize::PlannerConfig& planner) {
  optimize::DesignOptions options;
  options.seed = seed;
  options.iterations = iterations;
  options.threads = threads;
  options.planner = planner;
  return options;
}

std::uint64_t restart_seed(std::uint64_t seed, int r) {
  if (r == 0) return seed;
  const std::uint64_t h = splitmix64(seed ^ splitmix64(static_cast<std::uint64_t>(r)));
  return h & ((std::uint64_t{1} << 53) - 1);
}

RestartResult design_restarts(const geometry::Scene& scene, optimize::DesignOptions options,
                              int restarts, const std::atomic<bool>* stop,
                              const std::function<void(const optimize::DesignStep&)>& progress,
                              const std::function<void()>& others) {
  RestartResult out;
  out.seed = options.seed;
  if (restarts <= 1) {
    out.result = optimize::design(scene, options, stop, progress);
    return out;
  }
  const int cores = options.threads > 0
                        ? options.threads
                        : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int lanes = std::min(restarts, cores);
  const int share = std::max(1, cores / lanes);
  std::mutex others_mutex;
  std::function<void(const optimize::DesignStep&)> heard;
  if (others)
    heard = [&](const optimize::DesignStep&) {
      const std::lock_guard<std::mutex> lock(others_mutex);
      others();
    };
  std::vector<std::optional<optimize::DesignResult>> results(static_cast<std::size_t>(restarts));
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(restarts));
  std::atomic<int> next{0};
  const auto work = [&] {
    for (int r = next++; r < restarts; r = next++) {
      optimize::DesignOptions o = options;
      o.seed = restart_seed(options.seed, r);
      o.threads = share;
      try {
        results[static_cast<std::size_t>(r)] =
            optimize::design(scene, o, stop, r == 0 ? progress : heard);
      } catch (...) {
        errors[static_cast<std::size_t>(r)] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  for (int j = 1; j < lanes; ++j) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  // A chain that failed (not a stop before its first iteration) fails the design.
  for (const std::exception_ptr& e : errors) {
    if (!e) continue;
    try {
      std::rethrow_exception(e);
    } catch (const Interrupted&) {
    }
  }
  int kept = -1;
  for (int r = 0; r < restarts; ++r) {
    const auto& c = results[static_cast<std::size_t>(r)];
    if (!c) continue;
    out.chains.push_back(
        {restart_seed(options.seed, r), c->final.total(), c->final.tours_found, c->valid});
    if (kept < 0) {
      kept = r;
      continue;
    }
    const auto& k = *results[static_cast<std::size_t>(kept)];
    if (std::pair(!c->valid, c->final.total()) < std::pair(!k.valid, k.final.total())) kept = r;
  }
  if (kept < 0) std::rethrow_exception(errors[0]);  // every chain stopped before it began
  out.result = std::move(*results[static_cast<std::size_t>(kept)]);
  out.seed = restart_seed(options.seed, kept);
  return out;
}

namespace {

//! report.json's "restarts" section.
std::string restarts_json(const std::vector<RestartChain>& chains, std::uint64_t kept_seed) {
  std::string tried;
  for (const RestartChain& c : chains) {
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "%s{\"seed\":%llu,\"cost\":%.17g,\"tours_found\":%d,\"valid\":%s}",
                  tried.empty() ? "" : ",", static_cast<unsigned long long>(c.seed), c.cost,
                  c.tours_found, c.valid ? "true" : "false");
    tried += buf;
  }
  return "{\"chains\":" + std::to_string(chains.size()) + ",\"kept_seed\":" +
         std::to_string(kept_seed) + ",\"tried\":[" + tried + "]}";
}

}  // namespace

AccessGoalResult design_for_access(const geometry::Scene& scene, optimize::DesignOptions options,
                                   const std::string& rules, int tries, std::uint64_t stride,
                                   int restarts, const std::atomic<bool>* stop,
                                   const std::function<void(const optimize::DesignStep&)>& progress,
                                   const std::function<void(int)>& on_try,
                                   const std::function<void()>& others) {
  const access::Rules rule_set = access::Rules::named(rules);
  const std::uint64_t first = options.seed;
  AccessGoalResult best;
  if (tries <= 1) {  // one plain design: nothing to choose, so no report here
    if (on_try) on_try(0);
    RestartResult one = design_restarts(scene, options, restarts, stop, progress, others);
    best.result = std::move(one.result);
    best.seed = first;
    best.chain_seed = one.seed;
    best.chains = std::move(one.chains);
    return best;
  }
  AccessTry kept;
  for (int k = 0; k < tries; ++k) {
    if (k > 0 && stop && stop->load()) break;
    if (on_try) on_try(k);
    options.seed = first + static_cast<std::uint64_t>(k) * stride;
    RestartResult one;
    try {
      one = design_restarts(scene, options, restarts, stop, progress, others);
    } catch (const Interrupted&) {
      if (k == 0) throw;
      break;  // stopped before this try's first iteration: keep the best so far
    }
    optimize::DesignResult& result = one.result;
    const access::Report report = access::evaluate(result.layout, result.tours, rule_set);
    const AccessTry t{options.seed, report.pass(), report.failures(), result.final.total()};
    const bool stopped = result.stopped;
    if (best.tries.empty() || std::pair(t.failures, t.cost) < std::pair(kept.failures, kept.cost)) {
      best.result = std::move(result);
      best.chains = std::move(one.chains);
      best.chain_seed = one.seed;
      best.seed = t.seed;
      kept = t;
    }
    best.tries.push_back(t);
    if (t.pass || stopped) break;
  }
  return best;
}

std::string access_goal_json(const AccessGoalResult& goal) {
  std::string tried;
  for (const AccessTry& t : goal.tries) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%s{\"seed\":%llu,\"pass\":%s,\"failures\":%d,\"cost\":%.17g}",
                  tried.empty() ? "" : ",", static_cast<unsigned long long>(t.seed),
                  t.pass ? "true" : "false", t.failures, t.cost);
    tried += buf;
  }
  bool pass = false;
  for (const AccessTry& t : goal.tries) pass = pass || (t.seed == goal.seed && t.pass);
  return "{\"tries\":" + std::to_string(goal.tries.size()) + ",\"kept_seed\":" +
         std::to_string(goal.seed) + ",\"pass\":" + (pass ? "true" : "false") +
         ",\"tried\":[" + tried + "]}";
}

void add_goal_sections(const AccessGoalResult& goal, optimize::RunInfo& info) {
  if (!goal.tries.empty()) info.report_sections.emplace_back("access_goal", access_goal_json(goal));
  if (!goal.chains.empty())
    info.report_sections.emplace_back("restarts", restarts_json(goal.chains, goal.chain_seed));
}

std::string fnv1a64_hex(const std::string& text) {
  std::uint64_t h = 14695981039346656037ull;
  for (const unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

std::string design_title(const optimize::DesignResult& result, std::uint64_t seed) {
  return result.layout.name + " — seed " + std::to_string(seed) +
         (result.valid ? "" : " (NOT VALID)");
}

DesignExtras attach_extras(const optimize::DesignResult& result, const std::string& rules,
                           optimize::RunInfo& info, std::string* line) {
  const access::Report report =
      access::evaluate(result.layout, result.tours, access::Rules::named(rules));
  DesignExtras extras;
  extras.accessibility = access::report_json(report);
  std::string summary = access::summary_json(report);
  summary.pop_back();  // the closing brace
  summary += ",\"file\":\"accessibility.json\",\"fnv1a64\":\"" +
             fnv1a64_hex(extras.accessibility) + "\"}";
  info.report_sections.emplace_back("accessibility", summary);
  info.svg_overlay = access::svg_overlay(report);
  if (line) *line = access::summary_line(report);
  extras.viewer = view::design_html(result, design_title(result, info.seed) + ", planner " +
                                                info.planner, extras.accessibility);
  info.report_sections.emplace_back(
      "viewer", "{\"file\":\"design.html\",\"fnv1a64\":\"" + fnv1a64_hex(extras.viewer) + "\"}");
  return extras;
}

const std::vector<std::string>& extra_file_names() {
  static const std::vector<std::string> names = {"accessibility.json", "design.html"};
  return names;
}

void write_design_files(const optimize::DesignResult& result, const optimize::RunInfo& info,
                        const DesignExtras& extras, const std::filesystem::path& dir) {
  io::require_writable_directory(dir);
  const auto& names = extra_file_names();
  io::write_files_atomic({{dir / names[0], extras.accessibility},
                                {dir / names[1], extras.viewer}});
  optimize::write_design(result, info, dir);
}

}  // namespace hrs::api
