// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Shortcutting of found paths (beyond the paper; the proposed planner's
// `shortcuts` technique): RRT legs wander, and a stored path that is reused
// layout after layout should not carry the RRT's detours.

#include "geometry/pose.h"
#include "planning/motion_validator.h"
#include "rs/reeds_shepp.h"

namespace hrs::planning {

using geometry::Pose2;

//! A path from `start` to the same end that is at most as long as `path`:
//! greedy shortcuts between poses along it (every `step` metres and at
//! segment borders), each replacement the exact shortest RS path between
//! the two poses, kept only when shorter by more than 1 mm and free by the
//! continuous checks of `validator`. From each pose the farthest pose is
//! tried first, then halfway closer, down to the next pose. Deterministic.
rs::Path shorten_path(const Pose2& start, const rs::Path& path, MotionValidator& validator,
                      double step);

}  // namespace hrs::planning
