// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The leg planner: RRT with Reeds–Shepp steering, the paper's baseline
// (§III-B, after LaValle 1998 and Dolgov et al. 2008). Each iteration draws a
// target: the goal with probability `goal_bias` (0.8), otherwise a sample.
// Among the k = 10 tree nodes nearest by weighted Euclidean distance
// (PoseNearest) it picks the one with the shortest RS path to the target and
// drives that path: towards the goal the whole curve up to the first invalid
// pose, towards a sample at most n = 5 steps of `step_length`. Every piece is
// checked continuously (MotionValidator); a node is added every step along the
// free part. The search ends when a node reaches the goal or when its
// Termination says so (by default after `max_iterations`).
//
// Reuse hooks for the proposed planner (§V): the sample source (RS-
// decomposition sampling, §V-A), the steering function (RS look-ups through
// the decomposition) and an existing tree to grow (tree reuse, §V-C) are
// injected; with the defaults (uniform samples, exact RS, a fresh tree) this
// is the baseline. Hooks are called a few times per iteration, far from the
// collision checks that dominate the cost.
//
// Thread-safety: a LegPlanner keeps all mutable state (engine, validator
// counters, scratch) per instance and only reads the shared CSpace; use one
// instance per thread. Results depend only on the inputs and the seed.

#include <cstdint>
#include <functional>
#include <limits>
#include <random>
#include <vector>

#include "geometry/cspace.h"
#include "geometry/pose.h"
#include "geometry/scene.h"
#include "planning/motion_validator.h"
#include "planning/nearest.h"
#include "planning/rrt_hooks.h"
#include "planning/termination.h"
#include "rs/reeds_shepp.h"

namespace hrs::planning {

using geometry::Pose2;

//! Parameters of the baseline RRT (§III-B), with the paper's values.
struct PlannerOptions {
  double goal_bias = 0.8;       //!< probability of steering to the goal (paper: 80 %)
  int k_nearest = 10;           //!< candidates by weighted distance before the RS pick (k)
  int max_steps = 5;            //!< steps of the curve added towards a sample (n)
  double step_length = 0.25;    //!< metres of curve per step and between tree nodes
  double heading_weight = 0.7;  //!< metres per radian in the weighted distance
  int max_iterations = 3000;    //!< cap: iterations before giving up (found = false)
  int max_nodes = 20000;        //!< cap: tree size before giving up
  //! A path whose end misses the goal by more (metres + radians) is not
  //! accepted: guards against an approximate steering function (§V-A).
  double goal_tolerance = 1e-6;
  //! Towards the goal, pick among the k nearest nodes whose RS curve to the
  //! goal has not been found blocked yet. The paper's text re-picks the same
  //! nearest nodes (blocked again, the iteration wasted); with this on, the
  //! goal is tried from ever farther nodes. Off: the literal baseline.
  bool skip_tried_goal_nodes = true;
};

//! Statistics of one leg query.
struct LegStats {
  int iterations = 0;                  //!< RRT iterations run
  int tree_nodes = 0;                  //!< nodes in the tree at the end (root included)
  std::uint64_t collision_checks = 0;  //!< continuous segment/piece checks
  double time_ms = 0.0;                //!< wall time of the query
};

//! Result of one leg query: the path from `from` to `to` when found.
struct LegResult {
  bool found = false;
  //! Why the search stopped without the goal (kNone when found, or when an
  //! end pose is not free and no search ran).
  StopReason stopped = StopReason::kNone;
  bool gave_up() const { return stopped == StopReason::kGaveUp; }
  rs::Path path;  //!< driven from the query's `from`; radius = the planner's radius
  LegStats stats;
};

//! An RRT tree: node 0 is the root; every edge is a free RS sub-path from the
//! parent's pose to the node's pose. Kept as plain data so that the proposed
//! planner can store, prune and regrow it (§V-C).
struct RrtTree {
  struct Node {
    Pose2 pose;
    std::int32_t parent = -1;  //!< -1 for the root
    rs::Path edge;             //!< from the parent's pose to `pose`
    double cost = 0.0;         //!< arc length from the root
  };
  std::vector<Node> nodes;
  const Pose2& root() const { return nodes.front().pose; }
  //! The path from the root to node `index` (segments merged).
  rs::Path path_to(std::int32_t index, double radius) const;
};

class LegPlanner {
 public:
  //! Plans in `cspace` (shared, read-only) for the scene's chair and room.
  LegPlanner(const geometry::Scene& scene, const CSpace& cspace, PlannerOptions options = {},
             PlannerHooks hooks = {});

  //! Plans from `from` to `to` with a fresh tree; deterministic in `seed`.
  //! `stop` says when the search ends without the goal (termination.h); by
  //! default at the options' caps.
  LegResult plan(const Pose2& from, const Pose2& to, std::uint64_t seed,
                 const Termination& stop = {});
  //! Plans by growing `tree` (its root must be `from`, its edges free in the
  //! current layout: the caller prunes, §V-C). The tree keeps its new nodes.
  LegResult plan(const Pose2& from, const Pose2& to, std::uint64_t seed, RrtTree& tree,
                 const Termination& stop = {});

  const PlannerOptions& options() const { return options_; }
  double radius() const { return radius_; }
  MotionValidator& validator() { return validator_; }

 private:
  //! Drives the RS path from node `from_node` towards `target` for at most
  //! `max_length` metres, adding a node every step (<= step_length, equal
  //! steps) along its free prefix. Returns the last node added (or -1) and sets
  //! `reached` when the whole path to `target` was added.
  std::int32_t extend(RrtTree& tree, std::int32_t from_node, const Pose2& target, double max_length,
                      bool& reached);
  //! Indexes the tree's nodes for nearest-node queries and orders them by
  //! distance to `goal` (all nodes untried).
  void index_tree(const RrtTree& tree, const Pose2& goal);
  //! Of the nodes in knn_, the one with the shortest steering distance to
  //! `target` (−1 when knn_ is empty).
  std::int32_t closest_by_steering(const RrtTree& tree, const Pose2& target,
                                   Steering& steering) const;
  //! closest_by_steering() for the exact steering (rs::first_shortest).
  std::int32_t closest_exact(const RrtTree& tree, const Pose2& target) const;
  //! A goal-biased iteration: extend the best of the k nearest (untried)
  //! nodes along the whole curve to `to`; the goal node when it is reached,
  //! else −1. `tree_size_at_goal_attempt` skips repeats (literal baseline).
  std::int32_t try_goal(RrtTree& tree, const Pose2& to, Steering& steering,
                        std::size_t& tree_size_at_goal_attempt);
  //! A sample iteration: extend the best of the k nearest nodes at most
  //! max_steps steps towards `target`.
  void try_sample(RrtTree& tree, const Pose2& target, Steering& steering);

  const CSpace* cspace_;
  PlannerOptions options_;
  double radius_;
  UniformSampler uniform_;
  ExactSteering exact_;
  PlannerHooks hooks_;  //!< resolved at each use, so the planner stays movable
  MotionValidator validator_;
  PoseNearest nearest_;
  QueryOrder goal_order_;  //!< nodes by distance to the goal (untried ones only, by default)
  std::vector<std::int32_t> knn_;
  mutable std::vector<Pose2> poses_;                            //!< closest_exact's scratch
  mutable std::vector<std::pair<double, std::size_t>> bounds_;  //!< closest_exact's scratch
};

}  // namespace hrs::planning
