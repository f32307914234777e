// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Pose helpers every suite shares: random poses (in a box or a room), the
// one pose error the suites compare against, and a goal tolerance.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "geometry/pose.h"
#include "geometry/scene.h"

namespace hrs::test_support {

using geometry::Pose2;

//! A uniformly random pose in [-half, half]^2 x (-π, π].
inline Pose2 random_pose(std::mt19937_64& rng, double half) {
  std::uniform_real_distribution<double> pos(-half, half);
  std::uniform_real_distribution<double> ang(-std::numbers::pi, std::numbers::pi);
  const double x = pos(rng), y = pos(rng);
  return {x, y, ang(rng)};
}

//! A uniform random pose in the room's bounding box, heading in [−π, π).
inline geometry::Pose2 random_pose(const geometry::Scene& s, std::mt19937_64& rng) {
  double xmin = 1e9, xmax = -1e9, ymin = 1e9, ymax = -1e9;
  for (const geometry::Vec2& v : s.room.polygon) {
    xmin = std::min(xmin, v.x), xmax = std::max(xmax, v.x);
    ymin = std::min(ymin, v.y), ymax = std::max(ymax, v.y);
  }
  std::uniform_real_distribution<double> ux(xmin, xmax), uy(ymin, ymax),
      ut(-std::numbers::pi, std::numbers::pi);
  return {ux(rng), uy(rng), ut(rng)};
}

//! Distance between poses: max of position error and wrapped heading error.
inline double pose_error(const Pose2& a, const Pose2& b) {
  return std::max(std::hypot(a.x - b.x, a.y - b.y),
                  std::abs(geometry::wrap_angle(a.theta - b.theta)));
}

//! Tolerance for reaching a goal: 1e-9 relative to the scale of the query.
inline double goal_tolerance(const Pose2& a, const Pose2& b) {
  return 1e-9 * (1.0 + std::max({std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y)}));
}

}  // namespace hrs::test_support
