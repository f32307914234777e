// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The one proof behind three of the proposed planner's shortcuts (§V and
// beyond): a stored path served without a check (PathDatabase::still_free),
// a failed RRT run that would repeat (FailureMemory::repeats) and a
// certified prefix kept (LegMeasures). Each answer came from collision
// queries made near a set of points in an earlier layout. The walls never
// move; if every object that moved since lies farther than a margin from
// every point, no query can have changed its answer, so the old answer holds.
//
// The margin is each caller's: how far its queries' reference point strays
// from the nearest point (a piece length, a trace step), plus
// CSpace::swept_reach() (an object's C-obstacle pieces A ⊕ (−S_k) lie within
// it of the footprint A), plus kOffsetSlack. Whether an object's old pose
// counts depends on the answer: "free" cannot turn "blocked" when an object
// leaves, while "blocked" can turn "free".

#include <span>
#include <vector>

#include "geometry/cspace.h"
#include "geometry/pose.h"
#include "geometry/scene.h"

namespace hrs::planning {

//! Added to every margin: the C-space's half-plane offsets round outward by
//! far less than 1 mm (geometry/cspace.h), as do the world footprints and
//! distances computed here.
inline constexpr double kOffsetSlack = 1e-3;

//! The object poses of `cspace`'s current layout, in index order.
std::vector<geometry::Pose2> layout_of(const geometry::CSpace& cspace);

//! True when every object i with now[i] != then[i] keeps its footprint
//! (scene.objects[i].footprint placed at now[i], and also at then[i] when
//! `old_poses_too`) farther than `margin` (>= 0) from every point: no point
//! inside it (geometry::point_in_polygon) and none within `margin` of an
//! edge (geometry::point_segment_distance). A box test skips points far
//! from the footprint. False when the layouts differ in size.
bool moved_objects_clear(const geometry::Scene& scene, std::span<const geometry::Pose2> then,
                         std::span<const geometry::Pose2> now,
                         std::span<const geometry::Vec2> points, double margin, bool old_poses_too);

}  // namespace hrs::planning
