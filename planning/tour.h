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

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/cspace.h"
#include "geometry/pose.h"
#include "geometry/scene.h"
#include "planning/goals.h"
#include "planning/metrics.h"
#include "planning/rrt.h"
#include "rs/reeds_shepp.h"

namespace hrs::planning {

//! Id of the start node in sequences (the door).
inline constexpr std::string_view kDoorId = "door";

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
  //! waits, never changing any outcome.
  virtual LegOutcome resolve(const LegKey& key, const Pose2& from, const Pose2& to,
                             std::uint64_t tour_seed, bool may_plan, LegPlanner& planner,
                             std::span<const LegRequest> next = {}) = 0;
};

class LegMeasures;

struct TourHooks {
  PlannerHooks planner;  //!< sampler / steering of the leg planner
  //! Non-null: legs come from here (the proposed planner); null: every leg
  //! is planned by the tour's own RRT (the baseline).
  LegProvider* provider = nullptr;
  //! Non-null: found legs are measured through it (same results, work kept
  //! across tours and layouts: planning/leg_measures.h); null: afresh.
  LegMeasures* measures = nullptr;
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
  int backtracks = 0;     //!< returns to an earlier leg
  int depth = 0;          //!< most legs joined at once (= sequence size − 1 when found)
  bool capped = false;    //!< max_leg_plans was reached
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
  std::vector<std::vector<GoalPose>> local_goals_;
};

//! The RRT seed of one leg: a hash of the tour seed and the key.
std::uint64_t leg_seed(std::uint64_t tour_seed, const LegKey& key);

}  // namespace hrs::planning
