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
      invalidated_[k] = planning::recheck_tour(cspace_, work_.wheelchair.turning_radius, tours_[k],
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

namespace {

//! One design run (paper §III-E with the tours of §III-C): the annealer's
//! callbacks on one object, each step a named member. run() is design().
class DesignRun {
 public:
  DesignRun(const geometry::Scene& scene, const DesignOptions& options,
            const std::atomic<bool>* stop, const std::function<void(const DesignStep&)>& progress)
      : t0_(Clock::now()),
        scene_(scene),
        options_(options),
        stop_(stop),
        progress_(progress),
        sequences_(scene_sequences(scene)),
        model_(scene, sequences_),
        round_(scene, options, sequences_),
        work_(round_.work()),
        cspace_(round_.cspace()),
        tours_(round_.tours()) {
    result_.sequences = sequences_;
    result_.threads = round_.threads();
    for (const auto& o : scene.objects) {
      poses_.push_back(o.pose);
      movable_.push_back(!o.fixed);
    }
    // With all path weights 0 the cost does not depend on the tours: plan
    // only the initial and the best layout (Fig. 1's "designed without the
    // chair").
    const auto& wp = scene.weights.path;
    plan_every_iteration_ = wp[0] != 0.0 || wp[1] != 0.0 || wp[2] != 0.0;
    result_.planned_every_iteration = plan_every_iteration_;
  }

  DesignResult run() {
    plan_current();
    current_terms_ = model_.evaluate(poses_, tours_);
    result_.initial = current_terms_;
    current_tours_ = tours_;
    const AnnealOptions schedule = make_schedule();
    std::mt19937_64 rng(options_.seed);
    const AnnealResult r = anneal(poses_, movable_, schedule, callbacks(), rng, stop_);
    finish(r);
    result_.time_total_s = seconds_since(t0_);
    return std::move(result_);
  }

 private:
  //! Plans the M tours of the current layout (round `iteration_`).
  void plan_current() {
    const auto p0 = Clock::now();
    if (options_.layouts_out) {
      options_.layouts_out->emplace_back();
      for (int i = 0; i < cspace_.object_count(); ++i)
        options_.layouts_out->back().push_back(cspace_.object_pose(i));
    }
    result_.tours_invalidated += round_.plan(iteration_, iteration_legs_);
    planning_ms_ = 1e3 * seconds_since(p0);
    result_.time_planning_s += planning_ms_ / 1e3;
  }

  //! Temperatures from the initial cost (docs/optimize.md), jumps inside
  //! the room's bounding box unless the options bound them.
  AnnealOptions make_schedule() {
    AnnealOptions schedule = options_.anneal;
    schedule.iterations = options_.iterations;
    if (!schedule.bounds) {
      const geometry::Box b = geometry::bounding_box(scene_.room.polygon);
      schedule.bounds = std::array<double, 4>{b.xmin, b.ymin, b.xmax, b.ymax};
    }
    schedule.t_start = std::max(1e-6, options_.t_start_fraction * current_terms_.total());
    schedule.t_end = schedule.t_start * options_.t_end_ratio;
    result_.t_start = schedule.t_start;
    result_.t_end = schedule.t_end;
    return schedule;
  }

  AnnealCallbacks callbacks() {
    AnnealCallbacks cb;
    cb.move_valid = [this](const std::vector<Pose2>& p, int moved) { return move_valid(p, moved); };
    cb.cost = [this](const std::vector<Pose2>& p, const Move& move) { return cost(p, move); };
    cb.rejected = [this](const Move& move) { undo(move); };
    cb.layout_valid = [this](const std::vector<Pose2>&) { return layout_violation(work_).empty(); };
    cb.new_best = [this] { new_best(); };
    cb.progress = [this](const TraceEntry& e) { step_done(e); };
    return cb;
  }

  //! The exact checks of one moved object, before any planning.
  bool move_valid(const std::vector<Pose2>& p, int moved) {
    const Pose2 old = work_.objects[moved].pose;
    work_.objects[moved].pose = p[moved];
    const bool ok = object_violation(work_, moved).empty();
    work_.objects[moved].pose = old;
    return ok;
  }

  //! Applies a proposal to the C-space, tours it and returns its cost.
  double cost(const std::vector<Pose2>& p, const Move& move) {
    if (move.object < 0) return current_terms_.total();
    ++iteration_;
    work_.objects[move.object].pose = move.to;
    cspace_.move_object(move.object, move.to);
    planning_ms_ = 0.0;
    if (plan_every_iteration_) plan_current();
    proposed_terms_ = model_.evaluate(p, tours_);
    return proposed_terms_.total();
  }

  void undo(const Move& move) {
    work_.objects[move.object].pose = move.from;
    cspace_.move_object(move.object, move.from);
  }

  //! Called for the initial layout (before any proposal) or right after an
  //! accepted proposal: `tours_` and the terms belong to the current layout.
  void new_best() {
    if (iteration_ == 0) {
      result_.final = current_terms_;
      result_.tours = current_tours_;
    } else {
      result_.final = proposed_terms_;
      result_.tours = tours_;
    }
  }

  //! The trace entry of one iteration; an accepted proposal becomes current.
  void step_done(const TraceEntry& e) {
    DesignStep step;
    step.anneal = e;
    if (e.valid) {
      step.proposed = proposed_terms_;
      step.planning_ms = planning_ms_;
      step.planned = plan_every_iteration_;
      if (plan_every_iteration_) step.legs = iteration_legs_;
    }
    if (e.accepted) {
      current_terms_ = proposed_terms_;
      current_tours_ = tours_;
    }
    result_.trace.push_back(step);
    if (progress_) progress_(step);
  }

  //! The best layout, its tours (toured now when the tours were not planned
  //! every iteration) and the run's counts.
  void finish(const AnnealResult& r) {
    result_.layout = scene_;
    for (std::size_t i = 0; i < scene_.objects.size(); ++i)
      result_.layout.objects[i].pose = r.best[i];
    result_.valid = r.best_valid && layout_violation(result_.layout).empty();
    if (!r.best_valid) {
      // No valid layout was ever seen: report the chain's last state.
      for (std::size_t i = 0; i < scene_.objects.size(); ++i)
        result_.layout.objects[i].pose = r.final_poses[i];
      result_.final = current_terms_;
      result_.tours = current_tours_;
    }
    if (!plan_every_iteration_ && r.best_valid) {
      for (std::size_t i = 0; i < scene_.objects.size(); ++i)
        cspace_.move_object(static_cast<int>(i), r.best[i]);
      iteration_ = r.proposals + 1;
      plan_current();
      result_.tours = tours_;
      result_.final = model_.evaluate(r.best, tours_);
    }
    result_.proposals = r.proposals;
    result_.valid_proposals = r.valid_proposals;
    result_.accepted = r.accepted;
    result_.stopped = r.stopped;
    result_.proposed = options_.proposed;
    if (planning::ReusePlanner* reuse = round_.reuse()) {
      result_.reuse = options_.reuse.names();
      result_.counters = reuse->totals();
    }
  }

  Clock::time_point t0_;
  const geometry::Scene& scene_;
  DesignOptions options_;
  const std::atomic<bool>* stop_;
  const std::function<void(const DesignStep&)>& progress_;
  std::vector<Sequence> sequences_;
  CostModel model_;
  TourRound round_;
  geometry::Scene& work_;
  geometry::CSpace& cspace_;
  std::vector<planning::Tour>& tours_;
  std::vector<Pose2> poses_;
  std::vector<bool> movable_;
  bool plan_every_iteration_ = true;
  int iteration_ = 0;  //!< 0: the initial layout; proposals count from 1
  double planning_ms_ = 0.0;
  std::optional<planning::ReuseCounters> iteration_legs_;
  CostTerms current_terms_, proposed_terms_;
  std::vector<planning::Tour> current_tours_;
  DesignResult result_;
};

}  // namespace

DesignResult design(const geometry::Scene& scene, const DesignOptions& options,
                    const std::atomic<bool>* stop,
                    const std::function<void(const DesignStep&)>& progress) {
  return DesignRun(scene, options, stop, progress).run();
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
