// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Goal poses around an object (paper §III-C, Fig. "goal"): N poses sampled
// uniformly along the object's outline, N proportional to its perimeter over
// the chair's width, each facing the object's reference point (its centre,
// the pose position) so that the person sits facing it. Only the object's
// allowed `approach` sides are used, and the chair stops `gap` away from the
// footprint. Poses in collision are dropped.

#include <atomic>
#include <vector>

#include "geometry/cspace.h"
#include "geometry/pose.h"
#include "geometry/scene.h"

namespace hrs::planning {

struct GoalOptions {
  //! N = ceil(density · perimeter / chair width) slots along the whole outline.
  double density = 2.0;
  //! The chair-to-footprint distance is `gap` within this tolerance (metres).
  double gap_tolerance = 0.005;
};

//! One goal pose and where it came from.
struct GoalPose {
  geometry::Pose2 pose;  //!< the chair's pose, facing the object's centre
  geometry::Side side;   //!< the side of the object it serves
  int slot = 0;          //!< index among the N slots (stable while the object moves rigidly)
};

//! Goal poses around `object` placed at `object_pose`, collision free in
//! `cspace` (poses in collision are dropped), in slot order. Equals
//! place_goal_poses(local_goal_poses(...), object_pose, cspace).
std::vector<GoalPose> goal_poses(const geometry::Scene& scene, const geometry::Object& object,
                                 const geometry::Pose2& object_pose, const geometry::CSpace& cspace,
                                 const GoalOptions& options = {});

//! The goal poses of `object` in its own frame (object at the origin,
//! heading +x), before any collision test: they depend only on the
//! footprint, the chair and the options, so a planner computes them once
//! per object and places them wherever the object moves. `stop` (may be
//! null) is checked before every slot: once set, hrs::Interrupted is thrown
//! (geometry/error.h); no partial result is returned.
std::vector<GoalPose> local_goal_poses(const geometry::Scene& scene, const geometry::Object& object,
                                       const GoalOptions& options = {},
                                       const std::atomic<bool>* stop = nullptr);
//! `local` goal poses moved with the object to `object_pose`, the ones in
//! collision in `cspace` dropped.
std::vector<GoalPose> place_goal_poses(const std::vector<GoalPose>& local,
                                       const geometry::Pose2& object_pose,
                                       const geometry::CSpace& cspace);

//! The side of `object` (at `object_pose`) that a chair position lies on:
//! the side whose outward direction (local ±x, ±y) is closest to the
//! direction from the centre to the point, scaled by the footprint's extent.
geometry::Side side_of(const geometry::Object& object, const geometry::Pose2& object_pose,
                       geometry::Vec2 point);

}  // namespace hrs::planning
