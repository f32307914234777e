// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Tours (paper §III-C): the wheelchair leaves the door and stops at each
// object of a sequence in order. Each object gets goal poses around it
// (planning/goals.h); the door has one, its start pose. Consecutive legs join:
// leg i starts where leg i−1 ended. From a start pose the goal poses of the
// next object are tried in order of RS length; when no goal pose of object
// i+1 can be reached from the chosen pose of object i, the search backtracks
// to leg i and tries its next (longer) candidate: branch and bound, depth
// first. A start pose whose subtree failed is remembered, so every leg
// (start pose, goal pose) is planned at most once per tour, and documented
// caps bound the effort of an impossible tour.
//
// Reuse hooks for the proposed planner (§V): a LegProvider (planning/reuse.h)
// answers whole legs (path database, tree reuse, failure memory), each a pure
// function of its inputs, so that tours planned in parallel agree whatever
// thread planned a shared leg first. The baseline passes no hooks.
// Hooks are shared by the caller's choice and must then be thread-safe.
//
// Thread-safety: a TourPlanner reads the CSpace (shared, const) and keeps all
// mutable state per instance: M tours run in parallel with M planners. Object
// poses are read from the CSpace at each plan() (the optimizer moves objects
// through CSpace::move_object between calls). Deterministic in the seed: each
// leg's RRT seed is derived from the tour seed and the leg's key, not from
// the order legs are tried.

#include <atomic>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/cspace.h"
#include "geometry/pose.h"
#include "geometry/scene.h"
#include "planning/goals.h"
#include "planning/leg_provider.h"
#include "planning/metrics.h"
#include "planning/rrt.h"
#include "planning/tour_types.h"
#include "rs/reeds_shepp.h"

namespace hrs::planning {

class TourPlanner {
 public:
  //! `cspace` must outlive the planner; it is read, never modified.
  TourPlanner(const geometry::Scene& scene, const CSpace& cspace, TourOptions options = {},
              std::uint64_t seed = 1, TourHooks hooks = {});

  //! Plans a tour of `sequence` ("door" first, then object ids) in the
  //! CSpace's current layout. Unknown ids throw hrs::InputError.
  Tour plan(const std::vector<std::string>& sequence);

  //! Goal poses of `id` in the current layout ("door": its start pose).
  std::vector<GoalPose> goals_for(std::string_view id) const;

  const TourOptions& options() const { return options_; }
  void set_seed(std::uint64_t seed) { seed_ = seed; }

 private:
  struct Stop;
  //! The next stop's goal poses as leg requests from goal `pose` of `here`,
  //! shortest RS length first, at most max_candidates; `goal[c]` is the
  //! index in next.goals of request c.
  struct Candidates {
    std::vector<int> goal;
    std::vector<LegRequest> requests;
  };
  Candidates candidates(const Stop& here, int pose, const Stop& next) const;
  //! A leg's path, from the provider or a fresh RRT query, counted into
  //! `tour`'s stats. kCapped: the tour hit max_leg_plans (stats.capped set).
  enum class Fetch { kFound, kFailed, kCapped };
  Fetch fetch_leg(std::span<const LegRequest> requests, std::size_t c, Tour& tour, Leg& leg);
  //! Depth-first branch and bound from goal `pose` of stop `level`: true
  //! when the rest of the tour was found (its legs appended to `legs`).
  bool search(std::vector<Stop>& stops, std::size_t level, int pose, std::vector<Leg>& legs,
              Tour& tour);

  const geometry::Scene* scene_;
  const CSpace* cspace_;
  TourOptions options_;
  std::uint64_t seed_;
  TourHooks hooks_;
  LegPlanner planner_;
  MotionValidator validator_;
  //! local_goal_poses() of every object, computed once (they do not depend
  //! on where the object stands).
  std::shared_ptr<const std::vector<std::vector<GoalPose>>> local_goals_;
};

//! The RRT seed of one leg: a hash of the tour seed and the key.
std::uint64_t leg_seed(std::uint64_t tour_seed, const LegKey& key);

}  // namespace hrs::planning
