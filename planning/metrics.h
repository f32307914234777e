// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Path metrics that the path cost of §III-D is built from (docs/design-notes.md
// "Costs"): length, rotation (sum of wrapped heading changes between
// consecutive waypoints) and clearance (corridor width left + right of each
// waypoint, through CSpace::clearance). Turning these into a cost is the
// optimizer's business; this file only measures.

#include <vector>

#include "geometry/cspace.h"
#include "geometry/pose.h"
#include "geometry/scene.h"
#include "rs/reeds_shepp.h"

namespace hrs::planning {

//! Waypoint spacing used for tours and the `plan` output (5 cm).
inline constexpr double kWaypointStep = 0.05;
//! The default corridor width (metres) below which clearance costs: the
//! scene's weights.clearance_width (geometry/scene.h) overrides it.
inline constexpr double kReferenceWidth = geometry::Weights{}.clearance_width;

struct PathMetrics {
  double length = 0.0;         //!< metres, sum of segment lengths
  double rotation = 0.0;       //!< radians, Σ |wrap(θ_{i+1} − θ_i)| over waypoints
  double clearance = 0.0;      //!< metres, mean corridor width (left + right) over waypoints
  double min_clearance = 0.0;  //!< metres, narrowest corridor width over waypoints
  //! metres, mean of max(0, reference width − width) over waypoints
  double clearance_deficit = 0.0;
  int waypoints = 0;  //!< number of waypoints the means are over
};

//! Waypoints of `path` from `start`, at most kWaypointStep apart, ends included.
std::vector<geometry::Pose2> waypoints_of(const geometry::Pose2& start, const rs::Path& path,
                                          double step = kWaypointStep);
//! Sum of |wrap(θ_{i+1} − θ_i)| over consecutive waypoints.
double rotation_of(const std::vector<geometry::Pose2>& waypoints);
//! All metrics of a path given by its waypoints and its length.
//! `reference_width`: the scene's weights.clearance_width.
PathMetrics measure(const geometry::CSpace& cspace, const std::vector<geometry::Pose2>& waypoints,
                    double length, double reference_width = kReferenceWidth);
//! measure() given the clearance at each waypoint: the one summation both
//! measure() and planning::LegMeasures use, so their results agree bit for bit.
PathMetrics metrics_of(const std::vector<geometry::Pose2>& waypoints, double length,
                       const std::vector<geometry::Clearance>& clearances,
                       double reference_width = kReferenceWidth);
//! Combines per-leg metrics into one (lengths and rotations add, clearance
//! means are weighted by waypoint counts).
PathMetrics combine(const std::vector<PathMetrics>& parts);

}  // namespace hrs::planning
