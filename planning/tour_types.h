// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a tour is made of and how it is planned (paper §III-C): the options,
// the reuse hooks of the proposed planner (§V), the legs, their counters and
// the tour itself. The planner that fills them is in planning/tour.h.

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/pose.h"
#include "geometry/scene.h"
#include "planning/goals.h"
#include "planning/leg_provider.h"
#include "planning/metrics.h"
#include "planning/rrt.h"
#include "rs/reeds_shepp.h"

namespace hrs::planning {

//! RRT iterations a baseline leg runs before the gate is asked (TourHooks):
//! the gate's fill costs about as much as a few hundred iterations, and
//! most found legs need fewer.
inline constexpr int kRefuseAfter = 300;

struct TourOptions {
  PlannerOptions planner;  //!< the leg planner (baseline RRT, §III-B)
  GoalOptions goals;       //!< goal poses around objects
  //! From one start pose, only the this many nearest (by RS length) goal poses
  //! of the next object are planned to; the rest are never tried.
  int max_candidates = 6;
  //! Cap: leg plans (RRT queries) per tour; past it the tour is not found.
  int max_leg_plans = 40;
  //! Waypoint spacing of the returned legs (metres).
  double waypoint_step = kWaypointStep;
};

class LegMeasures;
class ReachGate;

struct TourHooks {
  PlannerHooks planner;  //!< sampler / steering of the leg planner
  //! Non-null: legs come from here (the proposed planner); null: every leg
  //! is planned by the tour's own RRT (the baseline).
  LegProvider* provider = nullptr;
  //! Non-null: found legs are measured through it (same results, work kept
  //! across tours and layouts: planning/leg_measures.h); null: afresh.
  LegMeasures* measures = nullptr;
  //! Non-null: a leg still unfound after kRefuseAfter RRT iterations whose
  //! ends the gate separates stops there; it counts as a planned leg that
  //! failed (legs_planned, legs_failed, max_leg_plans), exactly as the full
  //! RRT query it cuts short, so tours are the same with and without the
  //! gate. Used for the baseline's own legs; the proposed planner asks its
  //! gate inside the provider.
  const ReachGate* gate = nullptr;
  //! Non-null and set: the tour stops (before its next leg, or the
  //! baseline's RRT within its leg) and is not found (the caller no longer
  //! needs it; see optimize/tour_round.cpp).
  const std::atomic<bool>* cancel = nullptr;
  //! Non-null and set while the constructor generates the goal poses: the
  //! constructor throws hrs::Interrupted (the user asked to stop before the
  //! first plan; see optimize/design.cpp).
  const std::atomic<bool>* stop = nullptr;
  //! The caller's index of this tour, passed to the provider.
  int tour = 0;
  //! Non-null: local_goal_poses() of every object (scene order), computed
  //! once by the caller with the planner's GoalOptions and shared by all
  //! its tour planners. With M = 1000 tours of 100 objects, computing them
  //! per planner took minutes before the first iteration.
  std::shared_ptr<const std::vector<std::vector<GoalPose>>> local_goals;
  //! Set: a baseline leg that the RRT did not find (and the gate did not
  //! refuse) is asked here; a path from `from` to `to` is taken as found
  //! (LegSource::kPlanned). The design's rescue of unfound tours uses the
  //! lattice planner (planning/lattice.h); unset in every other round.
  std::function<std::optional<rs::Path>(const Pose2& from, const Pose2& to)> fallback;
};

struct Leg {
  std::string from_id, to_id;  //!< object ids ("door" for the start)
  LegKey key;                  //!< object indices and goal slots
  Pose2 from, to;
  rs::Path path;                 //!< driven from `from`, scene radius
  std::vector<Pose2> waypoints;  //!< every waypoint_step metres, ends included
  PathMetrics metrics;
  LegSource source = LegSource::kPlanned;
  LegStats stats;  //!< of the RRT query that found it (zeros when reused)
};

struct TourStats {
  int legs_planned = 0;   //!< RRT queries run
  int legs_failed = 0;    //!< of which found nothing
  int legs_reused = 0;    //!< paths taken from the provider's database
  int legs_repaired = 0;  //!< stored paths repaired by the provider (also in legs_planned)
  int legs_rejected = 0;  //!< stored paths invalid in the current layout
  int legs_refused = 0;   //!< legs the gate proved impossible (also in legs_failed)
  int legs_fallback = 0;  //!< legs the RRT missed and TourHooks::fallback found
  int backtracks = 0;     //!< returns to an earlier leg
  int depth = 0;          //!< most legs joined at once (= sequence size − 1 when found)
  bool capped = false;    //!< max_leg_plans was reached
  bool cancelled = false; //!< stopped through TourHooks::cancel
  std::uint64_t rrt_iterations = 0;
  std::uint64_t collision_checks = 0;
  double time_ms = 0.0;
};

struct Tour {
  std::vector<std::string> sequence;  //!< starts with "door"
  bool found = false;
  std::vector<Leg> legs;  //!< sequence.size() − 1 joined legs when found, else empty
  PathMetrics metrics;    //!< of the whole tour (zeros when not found)
  TourStats stats;
};

}  // namespace hrs::planning
