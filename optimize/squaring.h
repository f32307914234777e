#pragma once
// SPDX-License-Identifier: GPL-3.0-or-later
// Square headings (docs/optimize.md "Preferences"): an object whose heading
// no preference fixes (a lamp, an armchair with only a wall distance) is
// wanted parallel or perpendicular to its nearest wall, as a designer draws
// it. The polish turns such objects square after its other moves, and the
// higher-score rearrangement squares the ones its chains move before their
// layouts are planned (an armchair taken to another wall keeps its old
// heading there, 42° off square, and no square heading planned after the
// move may keep the tours).

#include <functional>
#include <vector>

#include "geometry/pose.h"
#include "geometry/scene.h"
#include "optimize/costs.h"
#include "optimize/preferences.h"

namespace hrs::optimize {

//! Headings this close to square (radians, about 0.06°) are left alone.
inline constexpr double kSquareTolerance = 1e-3;

//! True when a preference fixes the object's heading: a wall angle, a
//! relation angle, or facing a partner.
bool heading_fixed(const geometry::Scene& scene, int object);

//! One square pose of an object and the layout's preference report with it.
struct SquarePlace {
  geometry::Pose2 pose;
  PreferenceReport report;
};

//! The square poses of `object` at `poses` (whose report is `report`): for
//! each quarter turn from its nearest wall's normal, nearest its heading
//! first (a tie, an object at 45°, takes the lower multiple of 90°), the
//! object turned in place, or else slid along the wall's normal to keep its
//! footprint's gap to the wall (turned about its centre, a lamp 5 cm from
//! its wall ends 11 cm from it); the first of the two that `valid` accepts
//! and that scores no lower (polish_score()). Empty when the heading is
//! square within kSquareTolerance. Whether a preference fixes the heading
//! is the caller's question (heading_fixed()).
std::vector<SquarePlace> square_places(
    const geometry::Scene& scene, const CostModel& model, const std::vector<geometry::Pose2>& poses,
    int object, const PreferenceReport& report,
    const std::function<bool(const std::vector<geometry::Pose2>& poses, int moved)>& valid);

}  // namespace hrs::optimize
