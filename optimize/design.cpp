#include "optimize/design.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <memory>
#include <random>
#include <stdexcept>

#include "geometry/polygon_ops.h"
#include "geometry/random.h"
#include "optimize/thread_pool.h"
#include "planning/motion_validator.h"

namespace hrs::optimize {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}


}  // namespace

bool recheck_tour(const geometry::CSpace& cspace, double radius, planning::Tour& tour,
                  planning::LegMeasures* measures) {
  if (!tour.found) return true;
  planning::MotionValidator validator(cspace, radius);
  for (std::size_t i = 0; i < tour.legs.size(); ++i) {
    const auto& leg = tour.legs[i];
    const double length = leg.path.length();
    const double prefix = measures ? measures->certified_prefix(leg, kRecheckPiece)
                                   : validator.certified_prefix(leg.from, leg.path, kRecheckPiece);
    if (prefix < length - 1e-9) {
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

namespace {

//! The M tours of one layout, planned in parallel (baseline or proposed):
//! shared by design() and replay_planning().
class TourRound {
 public:
  TourRound(const geometry::Scene& scene, const DesignOptions& options,
            const std::vector<Sequence>& sequences)
      : work_(scene),
        cspace_(work_, options.cspace),
        options_(options),
        sequences_(&sequences),
        pool_(options.threads),
        tours_(sequences.size()),
        invalidated_(sequences.size(), 0) {
    if (options.proposed)
      reuse_ = std::make_unique<planning::ReusePlanner>(work_, cspace_, options.tour, options.reuse,
                                                        options.seed);
    const planning::TourHooks hooks = reuse_ ? reuse_->hooks() : planning::TourHooks{};
    for (std::size_t k = 0; k < sequences.size(); ++k)
      planners_.push_back(std::make_unique<planning::TourPlanner>(
          work_, cspace_, options.tour, tour_seed(options.seed, 0, static_cast<int>(k)), hooks));
  }

  geometry::Scene& work() { return work_; }
  geometry::CSpace& cspace() { return cspace_; }
  int threads() const { return pool_.size(); }
  std::vector<planning::Tour>& tours() { return tours_; }
  planning::ReusePlanner* reuse() { return reuse_.get(); }

  //! Plans round `iteration` in the current layout; returns the tours the
  //! re-certification dropped. `legs` gets the proposed planner's counts.
  int plan(int iteration, std::optional<planning::ReuseCounters>& legs) {
    const int m = static_cast<int>(tours_.size());
    // The proposed planner's legs derive from (seed, iteration), not the tour.
    if (reuse_) reuse_->begin_iteration(tour_seed(options_.seed, iteration, m));
    pool_.run(m, [&](int k) {
      planners_[k]->set_seed(tour_seed(options_.seed, iteration, k));
      tours_[k] = planners_[k]->plan((*sequences_)[k].nodes);
      invalidated_[k] = recheck_tour(cspace_, work_.wheelchair.turning_radius, tours_[k],
                                     reuse_ ? reuse_->measures() : nullptr)
                            ? 0
                            : 1;
    });
    if (reuse_) legs = reuse_->end_iteration();
    int dropped = 0;
    for (int k = 0; k < m; ++k) dropped += invalidated_[k];
    return dropped;
  }

 private:
  geometry::Scene work_;  // poses follow the annealer's current layout
  geometry::CSpace cspace_;
  DesignOptions options_;
  const std::vector<Sequence>* sequences_;
  std::unique_ptr<planning::ReusePlanner> reuse_;
  std::vector<std::unique_ptr<planning::TourPlanner>> planners_;
  ThreadPool pool_;
  std::vector<planning::Tour> tours_;
  std::vector<int> invalidated_;
};

}  // namespace

DesignResult design(const geometry::Scene& scene, const DesignOptions& options,
                    const std::atomic<bool>* stop,
                    const std::function<void(const DesignStep&)>& progress) {
  const auto t0 = Clock::now();
  DesignResult result;
  result.sequences = scene_sequences(scene);
  const CostModel model(scene, result.sequences);

  TourRound round(scene, options, result.sequences);
  geometry::Scene& work = round.work();
  geometry::CSpace& cspace = round.cspace();
  planning::ReusePlanner* reuse = round.reuse();
  std::vector<planning::Tour>& tours = round.tours();
  result.threads = round.threads();

  std::vector<Pose2> poses;
  std::vector<bool> movable;
  for (const auto& o : scene.objects) {
    poses.push_back(o.pose);
    movable.push_back(!o.fixed);
  }

  int iteration = 0;  // 0: the initial layout; proposals count from 1
  double planning_ms = 0.0;
  std::optional<planning::ReuseCounters> iteration_legs;
  auto plan_all = [&] {
    const auto p0 = Clock::now();
    if (options.layouts_out) {
      options.layouts_out->emplace_back();
      for (int i = 0; i < cspace.object_count(); ++i)
        options.layouts_out->back().push_back(cspace.object_pose(i));
    }
    result.tours_invalidated += round.plan(iteration, iteration_legs);
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

ReplayResult replay_planning(const geometry::Scene& scene,
                             const std::vector<std::vector<Pose2>>& layouts,
                             const DesignOptions& options) {
  ReplayResult out;
  const std::vector<Sequence> sequences = scene_sequences(scene);
  const auto t0 = Clock::now();
  TourRound round(scene, options, sequences);
  out.setup_s = seconds_since(t0);
  std::optional<planning::ReuseCounters> legs;
  for (std::size_t r = 0; r < layouts.size(); ++r) {
    const auto& poses = layouts[r];
    if (static_cast<int>(poses.size()) != round.cspace().object_count())
      throw std::invalid_argument("replay_planning: layout size differs from the scene's objects");
    for (int i = 0; i < round.cspace().object_count(); ++i) {
      if (round.cspace().object_pose(i) == poses[i]) continue;
      round.work().objects[i].pose = poses[i];
      round.cspace().move_object(i, poses[i]);
    }
    const auto p0 = Clock::now();
    out.tours_invalidated += round.plan(static_cast<int>(r), legs);
    out.planning_s += seconds_since(p0);
    for (const planning::Tour& t : round.tours()) {
      ++out.tours_total;
      if (!t.found) continue;
      ++out.tours_found;
      out.tour_length += t.metrics.length;
    }
  }
  out.layouts = static_cast<int>(layouts.size());
  if (round.reuse()) out.counters = round.reuse()->totals();
  return out;
}

}  // namespace hrs::optimize
