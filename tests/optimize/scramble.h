#pragma once
// SPDX-License-Identifier: GPL-3.0-or-later
// A scrambled copy of a shipped room for the polish's and the
// rearrangement's randomized tests, and one with its free headings askew.

#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "geometry/scene.h"
#include "optimize/design.h"
#include "optimize/squaring.h"

namespace hrs::optimize::testing {

//! `scene` with each `movable` object turned by a multiple of 90° and
//! nudged by up to 30 cm per axis (seeded by `seed`), each kept only where
//! the object stays valid; the result is valid when `scene` is.
inline geometry::Scene scrambled(const geometry::Scene& scene, const std::vector<bool>& movable,
                                 std::uint64_t seed) {
  geometry::Scene work = scene;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  for (std::size_t i = 0; i < work.objects.size(); ++i) {
    if (!movable[i]) continue;
    const geometry::Pose2 was = work.objects[i].pose;
    work.objects[i].pose = {was.x + u(rng), was.y + u(rng),
                            geometry::wrap_angle(was.theta + (rng() % 4) * std::numbers::pi / 2)};
    if (!object_violation(work, static_cast<int>(i)).empty()) work.objects[i].pose = was;
  }
  return work;
}

//! `work` (a layout of `scene`) with each `movable` object whose heading
//! no preference of `scene` fixes (optimize/squaring.h) turned to a
//! uniform angle (seeded by `seed`), kept only where the object stays
//! valid: scrambled() turns by quarters only, so these stand askew.
inline geometry::Scene askew_free_headings(const geometry::Scene& scene, geometry::Scene work,
                                           const std::vector<bool>& movable, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> angle(-std::numbers::pi, std::numbers::pi);
  for (std::size_t i = 0; i < work.objects.size(); ++i) {
    const double theta = angle(rng);
    if (!movable[i] || heading_fixed(scene, static_cast<int>(i))) continue;
    const geometry::Pose2 was = work.objects[i].pose;
    work.objects[i].pose.theta = theta;
    if (!object_violation(work, static_cast<int>(i)).empty()) work.objects[i].pose = was;
  }
  return work;
}

}  // namespace hrs::optimize::testing
