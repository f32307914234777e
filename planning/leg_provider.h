// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The seam between tours and the proposed planner (paper §V): a tour asks a
// LegProvider for whole legs by key (the object pair and goal-pose slots)
// instead of running its own RRT. Outcomes are pure functions of their
// inputs, so that tours planned in parallel agree whatever thread computed
// a shared leg first. planning/reuse.h implements it.

#include <cstdint>
#include <span>

#include "geometry/pose.h"
#include "planning/rrt.h"
#include "rs/reeds_shepp.h"

namespace hrs::planning {

using geometry::Pose2;

//! Identifies a leg for the path database: object indices (−1: the door) and
//! goal-pose slots (GoalPose::slot; 0 for the door).
struct LegKey {
  int from_object = -1;
  int to_object = -1;
  int from_slot = 0;
  int to_slot = 0;
  friend bool operator==(const LegKey&, const LegKey&) = default;
  friend auto operator<=>(const LegKey&, const LegKey&) = default;
};

//! How a leg's path was obtained.
enum class LegSource {
  kPlanned,   //!< an RRT query from scratch (or from a reused tree)
  kReused,    //!< a stored path, transformed and validated (§V-B)
  kRepaired,  //!< a stored path's valid part kept, the gap re-planned (§V-B)
};

//! What a LegProvider answers for one leg.
struct LegOutcome {
  bool found = false;
  rs::Path path;  //!< driven from the leg's `from`; free in the current layout
  LegSource source = LegSource::kPlanned;
  //! An RRT query was run (or would be: see LegProvider::resolve); it counts
  //! against TourOptions::max_leg_plans.
  bool planned = false;
  bool rejected = false;  //!< a stored path existed but was not valid as it is
  LegStats stats;         //!< work behind the outcome (RRT and validation)
};

//! Resolves whole legs for the proposed planner (§V; planning/reuse.h): path
//! database, tree reuse and within-iteration sharing behind one call. Called
//! from parallel tours, so it must be thread-safe, and each outcome must be a
//! pure function of the key, the poses, the current layout and the
//! provider's state: then tours agree whatever thread computed a leg first.
//! A leg a tour may ask for: its key and its ends in the current layout.
struct LegRequest {
  LegKey key;
  Pose2 from, to;
};

class LegProvider {
 public:
  virtual ~LegProvider() = default;
  //! The outcome of leg `key` from `from` to `to`. `tour_seed` is the calling
  //! tour's seed; `planner` is the calling tour's (per-thread) leg planner.
  //! With `may_plan` false no RRT query is run: an outcome that needs one
  //! comes back with planned = true and found = false. `next`: the legs the
  //! tour asks for next, in order, should this one fail (the remaining
  //! candidates of its search level); a provider may work on them while it
  //! waits, never changing any outcome. `tour`: the caller's index of the
  //! asking tour (TourHooks::tour), so that a provider can keep only the
  //! work of the tours its caller keeps (ReusePlanner::end_iteration).
  virtual LegOutcome resolve(const LegKey& key, const Pose2& from, const Pose2& to,
                             std::uint64_t tour_seed, bool may_plan, LegPlanner& planner,
                             std::span<const LegRequest> next = {}, int tour = 0) = 0;
};

}  // namespace hrs::planning
