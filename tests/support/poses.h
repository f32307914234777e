#pragma once
// Shared helpers for the rs test suites: random pose pairs and goal checks.

#include <cmath>
#include <numbers>
#include <random>

#include "rs/reeds_shepp.h"

namespace hrs::rs::test {

//! A uniformly random pose in [-half, half]^2 x (-π, π].
inline Pose2 random_pose(std::mt19937_64& rng, double half) {
  std::uniform_real_distribution<double> pos(-half, half);
  std::uniform_real_distribution<double> ang(-std::numbers::pi, std::numbers::pi);
  const double x = pos(rng), y = pos(rng);
  return {x, y, ang(rng)};
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

}  // namespace hrs::rs::test
