#include "optimize/design.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <memory>
#include <random>

#include "geometry/polygon_ops.h"
#include "optimize/thread_pool.h"
#include "planning/motion_validator.h"

namespace hrs::optimize {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

}  // namespace

bool recheck_tour(const geometry::CSpace& cspace, double radius, planning::Tour& tour) {
  if (!tour.found) return true;
  planning::MotionValidator validator(cspace, radius);
  for (std::size_t i = 0; i < tour.legs.size(); ++i) {
    const auto& leg = tour.legs[i];
    const double length = leg.path.length();
    if (validator.certified_prefix(leg.from, leg.path, kRecheckPiece) < length - 1e-9) {
      tour.found = false;
      tour.legs.clear();
      tour.metrics = {};
      tour.stats.depth = static_cast<int>(i);
      return false;
    }
  }
  return true;
}

std::uint64_t tour_seed(std::uint64_t seed, int iteration, int tour) {
  std::uint64_t h = splitmix64(seed);
  h = splitmix64(h ^ static_cast<std::uint64_t>(iteration));
  return splitmix64(h ^ (static_cast<std::uint64_t>(tour) << 32));
}

std::string object_violation(const geometry::Scene& scene, int index) {
  const auto& o = scene.objects[index];
  const auto fp = geometry::world_footprint(o);
  if (!geometry::polygon_inside(fp, scene.room.polygon)) return o.id + " is not inside the room";
  if (geometry::interiors_overlap(fp, geometry::door_clear_zone(scene)))
    return o.id + " enters the door's clear zone";
  for (std::size_t j = 0; j < scene.objects.size(); ++j) {
    if (static_cast<int>(j) == index) continue;
    if (geometry::interiors_overlap(fp, geometry::world_footprint(scene.objects[j])))
      return o.id + " overlaps " + scene.objects[j].id;
  }
  return "";
}

std::string layout_violation(const geometry::Scene& scene) {
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    auto v = object_violation(scene, static_cast<int>(i));
    if (!v.empty()) return v;
  }
  return "";
}

DesignResult design(const geometry::Scene& scene, const DesignOptions& options,
                    const std::atomic<bool>* stop,
                    const std::function<void(const DesignStep&)>& progress) {
  const auto t0 = Clock::now();
  DesignResult result;
  result.sequences = scene_sequences(scene);
  const CostModel model(scene, result.sequences);
  const int m = static_cast<int>(result.sequences.size());

  geometry::Scene work = scene;  // poses follow the annealer's current layout
  geometry::CSpace cspace(work, options.cspace);
  std::unique_ptr<planning::ReusePlanner> reuse;
  if (options.proposed)
    reuse = std::make_unique<planning::ReusePlanner>(work, cspace, options.tour, options.reuse,
                                                     options.seed);
  const planning::TourHooks hooks = reuse ? reuse->hooks() : planning::TourHooks{};
  std::vector<std::unique_ptr<planning::TourPlanner>> planners;
  for (int k = 0; k < m; ++k)
    planners.push_back(std::make_unique<planning::TourPlanner>(
        work, cspace, options.tour, tour_seed(options.seed, 0, k), hooks));
  ThreadPool pool(options.threads);
  result.threads = pool.size();

  std::vector<Pose2> poses;
  std::vector<bool> movable;
  for (const auto& o : scene.objects) {
    poses.push_back(o.pose);
    movable.push_back(!o.fixed);
  }

  int iteration = 0;  // 0: the initial layout; proposals count from 1
  std::vector<planning::Tour> tours(m);
  std::vector<int> invalidated(m, 0);
  double planning_ms = 0.0;
  std::optional<planning::ReuseCounters> iteration_legs;
  auto plan_all = [&] {
    const auto p0 = Clock::now();
    // The proposed planner's legs derive from (seed, iteration), not the tour.
    if (reuse) reuse->begin_iteration(tour_seed(options.seed, iteration, m));
    pool.run(m, [&](int k) {
      planners[k]->set_seed(tour_seed(options.seed, iteration, k));
      tours[k] = planners[k]->plan(result.sequences[k].nodes);
      invalidated[k] = recheck_tour(cspace, scene.wheelchair.turning_radius, tours[k]) ? 0 : 1;
    });
    if (reuse) iteration_legs = reuse->end_iteration();
    for (int k = 0; k < m; ++k) result.tours_invalidated += invalidated[k];
    planning_ms = 1e3 * seconds_since(p0);
    result.time_planning_s += planning_ms / 1e3;
  };

  // With all path weights 0 the cost does not depend on the tours: plan only
  // the initial and the best layout (Fig. 1's "designed without the chair").
  const auto& wp = scene.weights.path;
  const bool plan_every_iteration = wp[0] != 0.0 || wp[1] != 0.0 || wp[2] != 0.0;
  result.planned_every_iteration = plan_every_iteration;

  plan_all();
  CostTerms current_terms = model.evaluate(poses, tours);
  result.initial = current_terms;
  std::vector<planning::Tour> current_tours = tours;
  CostTerms proposed_terms;

  AnnealOptions schedule = options.anneal;
  schedule.iterations = options.iterations;
  if (!schedule.bounds) {
    std::array<double, 4> box{1e300, 1e300, -1e300, -1e300};
    for (const auto& v : scene.room.polygon)
      box = {std::min(box[0], v.x), std::min(box[1], v.y), std::max(box[2], v.x),
             std::max(box[3], v.y)};
    schedule.bounds = box;  // jumps land anywhere in the room's bounding box
  }
  schedule.t_start = std::max(1e-6, options.t_start_fraction * current_terms.total());
  schedule.t_end = schedule.t_start * options.t_end_ratio;
  result.t_start = schedule.t_start;
  result.t_end = schedule.t_end;

  AnnealCallbacks cb;
  cb.move_valid = [&](const std::vector<Pose2>& p, int moved) {
    const Pose2 old = work.objects[moved].pose;
    work.objects[moved].pose = p[moved];
    const bool ok = object_violation(work, moved).empty();
    work.objects[moved].pose = old;
    return ok;
  };
  cb.cost = [&](const std::vector<Pose2>& p, const Move& move) {
    if (move.object < 0) return current_terms.total();
    ++iteration;
    work.objects[move.object].pose = move.to;
    cspace.move_object(move.object, move.to);
    planning_ms = 0.0;
    if (plan_every_iteration) plan_all();
    proposed_terms = model.evaluate(p, tours);
    return proposed_terms.total();
  };
  cb.rejected = [&](const Move& move) {
    work.objects[move.object].pose = move.from;
    cspace.move_object(move.object, move.from);
  };
  cb.layout_valid = [&](const std::vector<Pose2>&) { return layout_violation(work).empty(); };
  cb.new_best = [&] {
    // Called for the initial layout (before any proposal) or right after an
    // accepted proposal: `tours` and the terms belong to the current layout.
    if (iteration == 0) {
      result.final = current_terms;
      result.tours = current_tours;
    } else {
      result.final = proposed_terms;
      result.tours = tours;
    }
  };
  cb.progress = [&](const TraceEntry& e) {
    DesignStep step;
    step.anneal = e;
    if (e.valid) {
      step.proposed = proposed_terms;
      step.planning_ms = planning_ms;
      step.planned = plan_every_iteration;
      if (plan_every_iteration) step.legs = iteration_legs;
    }
    if (e.accepted) {
      current_terms = proposed_terms;
      current_tours = tours;
    }
    result.trace.push_back(step);
    if (progress) progress(step);
  };

  std::mt19937_64 rng(options.seed);
  const AnnealResult r = anneal(poses, movable, schedule, cb, rng, stop);

  result.layout = scene;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) result.layout.objects[i].pose = r.best[i];
  result.valid = r.best_valid && layout_violation(result.layout).empty();
  if (!r.best_valid) {
    // No valid layout was ever seen: report the chain's last state.
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
      result.layout.objects[i].pose = r.final_poses[i];
    result.final = current_terms;
    result.tours = current_tours;
  }
  if (!plan_every_iteration && r.best_valid) {
    // Tour the best layout once, for tours.json and the feasible-tour count.
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
      cspace.move_object(static_cast<int>(i), r.best[i]);
    iteration = r.proposals + 1;
    plan_all();
    result.tours = tours;
    result.final = model.evaluate(r.best, tours);
  }
  result.proposals = r.proposals;
  result.valid_proposals = r.valid_proposals;
  result.accepted = r.accepted;
  result.stopped = r.stopped;
  result.proposed = options.proposed;
  if (reuse) {
    result.reuse = options.reuse.names();
    result.counters = reuse->totals();
  }
  result.time_total_s = seconds_since(t0);
  return result;
}

}  // namespace hrs::optimize
