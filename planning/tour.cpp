// SPDX-License-Identifier: GPL-3.0-or-later
#include "planning/tour.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <utility>

#include "geometry/error.h"
#include "geometry/random.h"
#include "planning/leg_measures.h"
#include "planning/path_ops.h"
#include "planning/reach_gate.h"

namespace hrs::planning {

namespace {}  // namespace

std::uint64_t leg_seed(std::uint64_t tour_seed, const LegKey& key) {
  std::uint64_t h = splitmix64(tour_seed);
  for (int v : {key.from_object, key.to_object, key.from_slot, key.to_slot}) {
    h = splitmix64(h ^ static_cast<std::uint64_t>(static_cast<std::int64_t>(v)));
  }
  return h;
}

//! One stop of the sequence: its object (−1: door) and its goal poses.
struct TourPlanner::Stop {
  std::string id;
  int object = -1;
  std::vector<GoalPose> goals;
  std::vector<char> dead;  //!< goal pose whose continuation is known to fail
};

TourPlanner::TourPlanner(const geometry::Scene& scene, const CSpace& cspace, TourOptions options,
                         std::uint64_t seed, TourHooks hooks)
    : scene_(&scene),
      cspace_(&cspace),
      options_(options),
      seed_(seed),
      hooks_(hooks),
      planner_(scene, cspace, options.planner, hooks.planner),
      validator_(cspace, scene.wheelchair.turning_radius) {
  if (hooks.local_goals) {
    local_goals_ = hooks.local_goals;
    return;
  }
  auto goals = std::make_shared<std::vector<std::vector<GoalPose>>>();
  for (const geometry::Object& o : scene.objects)
    goals->push_back(local_goal_poses(scene, o, options_.goals, hooks.stop));
  local_goals_ = std::move(goals);
}

std::vector<GoalPose> TourPlanner::goals_for(std::string_view id) const {
  if (id == geometry::kStartNodeId) {
    const Pose2 start = geometry::door_start_pose(*scene_);
    if (!cspace_->is_free(start)) return {};
    return {GoalPose{start, geometry::Side::kFront, 0}};
  }
  const int index = scene_->find_object(id);
  if (index < 0) throw InputError("unknown object id '" + std::string(id) + "' in sequence");
  return place_goal_poses((*local_goals_)[index], cspace_->object_pose(index), *cspace_);
}

Tour TourPlanner::plan(const std::vector<std::string>& sequence) {
  const auto t0 = std::chrono::steady_clock::now();
  Tour tour;
  tour.sequence = sequence;
  std::vector<Stop> stops;
  stops.reserve(sequence.size());
  for (const std::string& id : sequence) {
    Stop stop;
    stop.id = id;
    stop.object = id == geometry::kStartNodeId ? -1 : scene_->find_object(id);
    stop.goals = goals_for(id);
    stop.dead.assign(stop.goals.size(), 0);
    stops.push_back(std::move(stop));
  }

  std::vector<Leg> legs;
  if (!stops.empty()) {
    if (stops.size() == 1) {
      tour.found = !stops[0].goals.empty();
    } else {
      for (std::size_t i = 0; i < stops[0].goals.size() && !tour.found; ++i) {
        tour.found = search(stops, 0, static_cast<int>(i), legs, tour);
        if (tour.stats.capped || tour.stats.cancelled) break;
      }
    }
  }

  if (tour.stats.cancelled) tour.found = false;
  if (tour.found) {
    std::vector<PathMetrics> parts;
    for (Leg& leg : legs) {
      if (hooks_.measures) {
        hooks_.measures->measure(leg, options_.waypoint_step);
      } else {
        leg.waypoints = waypoints_of(leg.from, leg.path, options_.waypoint_step);
        leg.metrics = measure(*cspace_, leg.waypoints, leg.path.length(),
                              scene_->weights.clearance_width);
      }
      parts.push_back(leg.metrics);
    }
    tour.metrics = combine(parts);
    tour.legs = std::move(legs);
  }
  tour.stats.time_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return tour;
}

TourPlanner::Candidates TourPlanner::candidates(const Stop& here, int pose,
                                                const Stop& next) const {
  const Pose2 from = here.goals[pose].pose;
  const double radius = planner_.radius();
  std::vector<std::pair<double, int>> order;
  order.reserve(next.goals.size());
  for (std::size_t j = 0; j < next.goals.size(); ++j) {
    order.emplace_back(rs::shortest_length(from, next.goals[j].pose, radius), static_cast<int>(j));
  }
  std::sort(order.begin(), order.end());
  if (static_cast<int>(order.size()) > options_.max_candidates) {
    order.resize(static_cast<std::size_t>(std::max(0, options_.max_candidates)));
  }
  // As leg requests: a provider may start on the later ones while it waits
  // for an earlier one (LegProvider::resolve).
  Candidates out;
  out.goal.reserve(order.size());
  out.requests.reserve(order.size());
  for (const auto& [rs_length, j] : order) {
    out.goal.push_back(j);
    out.requests.push_back({{here.object, next.object, here.goals[pose].slot, next.goals[j].slot},
                            from,
                            next.goals[j].pose});
  }
  return out;
}

TourPlanner::Fetch TourPlanner::fetch_leg(std::span<const LegRequest> requests, std::size_t c,
                                          Tour& tour, Leg& leg) {
  const LegRequest& r = requests[c];
  leg.key = r.key;
  leg.from = r.from;
  leg.to = r.to;
  // The outcome from the provider (proposed) or from this tour's own RRT
  // query (baseline); a query past max_leg_plans is not run (capped below).
  const bool may_plan = tour.stats.legs_planned < options_.max_leg_plans;
  if (hooks_.cancel && hooks_.cancel->load(std::memory_order_relaxed)) {
    tour.stats.cancelled = true;
    return Fetch::kCapped;
  }
  LegOutcome outcome;
  if (hooks_.provider) {
    outcome = hooks_.provider->resolve(r.key, r.from, r.to, seed_, may_plan, planner_,
                                       requests.subspan(c + 1), hooks_.tour);
  } else {
    outcome.planned = true;
    if (may_plan) {
      // The gate is asked only once the RRT has run kRefuseAfter iterations
      // in vain: most legs are found sooner, and their layouts need no grid
      // fill. A refused leg could never be found, so the tour is the same.
      // A cancelled tour is discarded whole (TourHooks::cancel), so its
      // leg may stop mid-search.
      Termination stop;
      if (hooks_.gate)
        stop.ask_after(kRefuseAfter, [&] { return hooks_.gate->refuses(r.from, r.to); });
      stop.cancelled_by(hooks_.cancel);
      LegResult result = planner_.plan(r.from, r.to, leg_seed(seed_, r.key), stop);
      if (result.stopped == StopReason::kCancelled) {
        tour.stats.cancelled = true;
        return Fetch::kCapped;
      }
      if (result.gave_up()) ++tour.stats.legs_refused;
      if (!result.found && !result.gave_up() && hooks_.fallback) {
        if (std::optional<rs::Path> path = hooks_.fallback(r.from, r.to)) {
          result.found = true;
          result.path = *std::move(path);
          ++tour.stats.legs_fallback;
        }
      }
      outcome.found = result.found;
      outcome.path = std::move(result.path);
      outcome.stats = result.stats;
    }
  }
  if (outcome.rejected) ++tour.stats.legs_rejected;
  if (outcome.planned) {
    if (!may_plan) {
      tour.stats.capped = true;
      return Fetch::kCapped;
    }
    ++tour.stats.legs_planned;
    leg.stats = outcome.stats;
  }
  tour.stats.rrt_iterations += static_cast<std::uint64_t>(outcome.stats.iterations);
  tour.stats.collision_checks += outcome.stats.collision_checks;
  if (!outcome.found) {
    ++tour.stats.legs_failed;
    return Fetch::kFailed;
  }
  leg.source = outcome.source;
  if (leg.source == LegSource::kReused) ++tour.stats.legs_reused;
  if (leg.source == LegSource::kRepaired) ++tour.stats.legs_repaired;
  leg.path = std::move(outcome.path);
  return Fetch::kFound;
}

bool TourPlanner::search(std::vector<Stop>& stops, std::size_t level, int pose,
                         std::vector<Leg>& legs, Tour& tour) {
  if (level + 1 == stops.size()) return true;
  Stop& here = stops[level];
  Stop& next = stops[level + 1];
  if (here.dead[pose]) return false;
  const Candidates cand = candidates(here, pose, next);
  for (std::size_t c = 0; c < cand.goal.size(); ++c) {
    const int j = cand.goal[c];
    if (next.dead[j]) continue;  // reached before: its continuation failed
    Leg leg;
    leg.from_id = here.id;
    leg.to_id = next.id;
    const Fetch fetched = fetch_leg(cand.requests, c, tour, leg);
    if (fetched == Fetch::kCapped) return false;
    if (fetched == Fetch::kFailed) continue;
    legs.push_back(std::move(leg));
    tour.stats.depth = std::max(tour.stats.depth, static_cast<int>(legs.size()));
    if (search(stops, level + 1, j, legs, tour)) return true;
    legs.pop_back();
    ++tour.stats.backtracks;
    if (tour.stats.capped || tour.stats.cancelled) return false;
  }
  here.dead[pose] = 1;
  return false;
}

}  // namespace hrs::planning
