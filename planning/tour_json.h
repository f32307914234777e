// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// JSON text of legs and tours in the shapes of docs/design-notes.md "Output shapes"
// (the `plan` object and the entries of tours.json). Field names there are
// fixed; extra fields are added. nlohmann_json stays inside the .cpp.

#include <optional>
#include <string>
#include <vector>

#include "geometry/pose.h"
#include "planning/rrt.h"
#include "planning/tour.h"

namespace hrs::planning {

//! The `hrspace plan` object: found, from, to, radius, length, segments,
//! waypoints (every kWaypointStep), iterations, time_ms, plus tree_nodes and
//! collision_checks, and `impossible` when given (true: no motion exists).
//! One line, no trailing newline.
std::string plan_json(const Pose2& from, const Pose2& to, const LegResult& result, double radius,
                      std::optional<bool> impossible = std::nullopt);

//! One entry of tours.json: sequence, likelihood (when given), found, legs
//! (from, to, segments, waypoints, ...), metrics {length, rotation,
//! clearance, ...}, stats. One line, no trailing newline.
std::string tour_json(const Tour& tour, std::optional<double> likelihood = std::nullopt);

//! The whole tours.json document: {"tours": [...]}; likelihoods may be
//! empty or one per tour. Without `timings` the stats carry no time_ms (so
//! the same seed gives the same bytes); `indent` >= 0 pretty-prints.
std::string tours_json(const std::vector<Tour>& tours, const std::vector<double>& likelihoods = {},
                       bool timings = true, int indent = -1);

}  // namespace hrs::planning
