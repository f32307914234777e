// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One planning round of a design run: the M tours of the current layout,
// planned in parallel by the baseline or the proposed planner, with the
// free-grid gate that refuses impossible legs and grades walled-off stops,
// and early rejection on a cost bound (docs/optimize.md). Used by design()
// and replay_planning() (optimize/design.cpp); not a public header.

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "geometry/cspace.h"
#include "geometry/scene.h"
#include "optimize/annealer.h"
#include "optimize/costs.h"
#include "optimize/design.h"
#include "optimize/sequences.h"
#include "optimize/thread_pool.h"
#include "planning/goals.h"
#include "planning/reach_gate.h"
#include "planning/reuse.h"
#include "planning/tour.h"

namespace hrs::optimize {

//! The M tours of one layout, planned in parallel (baseline or proposed):
//! shared by design() and replay_planning().
//!
//! Early rejection (docs/optimize.md): given a Bound, tours are started in
//! index order and, as each finishes, the longest finished prefix of tours
//! adds its cost to the bound; once the Acceptance rejects the bound, no
//! further tour starts and the running ones stop (the proposed planner's
//! before their next leg, the baseline's within the leg's RRT). The
//! prefix at which that happens depends only on the tours' outcomes, never
//! on the threads, and the proposed planner keeps only the work of that
//! prefix (ReusePlanner::end_iteration), so runs stay identical for any
//! thread count.
class TourRound {
 public:
  //! Cost of the tours planned so far, and the decision that ends a round.
  struct Bound {
    const CostModel* model;
    double base;  //!< the cost known before planning (the interior terms)
    const Acceptance* acceptance;
    //! Per tour, a lower bound of its cost before it is planned (may be
    //! null: 0); see certain_floors().
    const std::vector<double>* floors = nullptr;
  };
  struct Outcome {
    int dropped = 0;        //!< kept tours that the re-certification dropped
    int kept = 0;           //!< tours planned to the end and counted
    bool rejected = false;  //!< the bound was rejected after `kept` tours
    double bound = 0.0;     //!< base + the kept tours' costs
  };

  //! `stop` (may be null): checked while the planners generate their goal
  //! poses (hrs::Interrupted once set).
  TourRound(const geometry::Scene& scene, const DesignOptions& options,
            const std::vector<Sequence>& sequences, const std::atomic<bool>* stop = nullptr);

  //! The working layout. Every change goes through move() or place(),
  //! which count a layout version. The gate's fill is keyed on it;
  //! the stop grades are a round's and follow it when the next round starts.
  const geometry::Scene& scene() const { return work_; }
  const geometry::CSpace& cspace() const { return cspace_; }
  //! The free-grid gate of the current layout (refilled at its first query
  //! after a change).
  const planning::ReachGate& gate() {
    follow_gate();
    return gate_;
  }
  std::uint64_t version() const { return version_; }
  int threads() const { return pool_.size(); }
  //! The last round's tours (rescue(): the rescued layout's).
  //! Each object's goal poses in its own frame (planning::local_goal_poses
  //! with the tours' options), scene order.
  const std::vector<std::vector<planning::GoalPose>>& local_goals() const { return *local_goals_; }
  const std::vector<planning::Tour>& tours() const { return tours_; }
  //! Each tour's leg grades (optimize/costs.h; empty for found tours).
  const std::vector<std::vector<double>>& blockage() const { return blockage_; }
  //! Objects graded walled off (grade > 0) in this round, index order.
  std::vector<int> walled_stops() const;
  //! The stops where this round's unfound tours broke off (the target of
  //! the first leg not joined), index order.
  std::vector<int> failing_stops();
  //! True when this round has unfound tours and every one of them broke
  //! off at its first leg, the one that leaves the door.
  bool fails_leaving_the_door() const;
  //! Moves object `o` to `to` in the working scene and the C-space.
  void move(int o, const Pose2& to);
  //! Moves every object whose C-space pose differs from `poses` (scene order).
  void place(const std::vector<Pose2>& poses);
  //! The exact checks of object `moved` (object_fits) with every
  //! object at `p`; the working layout is unchanged afterwards.
  bool fits(const std::vector<Pose2>& p, int moved);
  //! Runs `f` with object `moved` at `to` in the C-space, then moves it
  //! back (a trial that leaves the version and the gate as they were). `f`
  //! may ask goal poses (goals_of) but must not query the gate: a fill made
  //! during the trial would be kept as the current layout's.
  void trial(int moved, const Pose2& to, const std::function<void()>& f);
  //! Goal poses of object `index` in the current layout.
  std::vector<planning::GoalPose> goals_of(int index) const;
  planning::ReusePlanner* reuse() { return reuse_.get(); }

  //! Plans round `iteration` in the current layout. `legs` gets the
  //! proposed planner's counts; `bound` (may be null) enables early rejection.
  Outcome plan(int iteration, std::optional<planning::ReuseCounters>& legs,
               const Bound* bound = nullptr);
  //! Per tour, a lower bound of its cost in the current layout known before
  //! planning: a tour with a stop the gate certifies unreachable
  //! (ReachGate::walls_off) is unfound, with at most the legs before that
  //! stop joined, so it costs at least tour_total() of an unfound tour of
  //! that depth with the same grades; other tours: 0.
  std::vector<double> certain_floors(const CostModel& model);
  //! The rescue (PlannerConfig::rescue): the objects are placed at `poses`,
  //! the round's tours become `tours` (that layout's), and unfound ones are
  //! planned again by the RRT per leg, every leg it misses and the gate does
  //! not refuse answered by the lattice planner: the first kRescueTours
  //! unfound tours (the most likely), at most kRescueLegs lattice searches
  //! each, so the work is bounded whatever the scene. Returns the tours
  //! found now that were not.
  int rescue(const std::vector<Pose2>& poses, const std::vector<planning::Tour>& tours,
             int iteration);
  static constexpr int kRescueTours = 5, kRescueLegs = 4;

 private:
  //! The gate follows the current layout version.
  void follow_gate();
  //! The gate and the grades follow the current layout version (a round
  //! starts).
  void follow_layout();

  //! Fills blockage_[k]: for an unfound tour, the grade of each leg's stop
  //! (computed once per object and round); empty otherwise.
  void grade(int k);

  //! The grade of each stop of tour k's sequence (computed once per object
  //! and round; 1 for a node that is not an object).
  std::vector<double> stop_grades(int k);

  geometry::Scene work_;  // poses follow the annealer's current layout
  geometry::CSpace cspace_;
  planning::ReachGate gate_;
  DesignOptions options_;
  const std::vector<Sequence>* sequences_;
  std::unique_ptr<planning::ReusePlanner> reuse_;
  std::vector<std::unique_ptr<planning::TourPlanner>> planners_;
  planning::TourOptions tour_options_;
  std::shared_ptr<const std::vector<std::vector<planning::GoalPose>>> local_goals_;
  const std::atomic<bool>* stop_ = nullptr;
  ThreadPool pool_;
  std::vector<planning::Tour> tours_;
  std::vector<int> invalidated_;
  std::vector<std::vector<double>> blockage_;
  std::vector<char> finished_;
  std::vector<double> grades_;  //!< per object this round (−1: not yet)
  std::uint64_t version_ = 0;         //!< counts layout changes
  std::uint64_t gate_version_ = ~std::uint64_t{0};    //!< the version the gate follows
  std::uint64_t graded_version_ = ~std::uint64_t{0};  //!< the version grades_ follow
  std::atomic<bool> cancel_{false};
  std::mutex mutex_;
};

}  // namespace hrs::optimize
