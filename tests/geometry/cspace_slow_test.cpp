// SPDX-License-Identifier: GPL-3.0-or-later
// Exhaustive randomized certification of the C-space against the exact CGAL
// reference: ≥ 100 000 poses per scene and ≥ 10 000 straight and arc motions,
// each motion re-checked pose by pose at 1 mm / 0.1°. Zero misses allowed;
// conservatism (reference-free answers called colliding) is measured and bounded.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "geometry/cspace.h"
#include "tests/support/reference.h"
#include "tests/support/scenes.h"

namespace hrs::geometry {
namespace {

using test_support::ExactReference;
using test_support::random_pose;
constexpr double kPi = std::numbers::pi;

std::vector<Scene> all_scenes() {
  std::vector<Scene> out{test_support::l_shaped_scene()};
  for (const std::string& f : test_support::scene_files()) out.push_back(load_scene(f));
  return out;
}

TEST(CSpaceSlow, NoPoseReportedFreeCollidesInAnyScene) {
  long total_ref_free = 0, total_conservative = 0;
  for (const Scene& scene : all_scenes()) {
    const CSpace cs(scene);
    const ExactReference ref(scene);
    std::mt19937_64 rng(1234);
    long free = 0, ref_free = 0, missed = 0, conservative = 0;
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
      const Pose2 p = random_pose(scene, rng);
      const bool ours = cs.is_free(p), truth = ref.pose_free(p);
      free += ours, ref_free += truth;
      if (ours && !truth) {
        ++missed;
        ADD_FAILURE() << scene.name << ": free but colliding " << p.x << "," << p.y << ","
                      << p.theta;
      }
      conservative += (!ours && truth);
    }
    std::printf(
        "[%s] poses %d, free %ld, reference-free %ld, missed %ld, conservative %ld (%.4f%%)\n",
        scene.name.c_str(), n, free, ref_free, missed, conservative,
        100.0 * conservative / std::max(1L, ref_free));
    EXPECT_EQ(missed, 0);
    EXPECT_GT(free, n / 20) << "too few free poses to certify anything";
    total_ref_free += ref_free, total_conservative += conservative;
  }
  // Bound: with exact-heading refinement only the 1e-9 m margin is conservative.
  EXPECT_LT(double(total_conservative) / double(total_ref_free), 0.001);
}

//! Motion from `start`: straight (radius 0) or arc; pose at fraction f in [0, 1].
struct Motion {
  Pose2 start;
  double length = 0;  // straight
  double radius = 0, turn = 0;
  int gear = 1;
  Pose2 at(double f) const {
    if (radius == 0) {
      return {start.x + f * length * std::cos(start.theta),
              start.y + f * length * std::sin(start.theta), start.theta};
    }
    const double side = turn > 0 ? 1 : -1;
    const double h = start.theta + f * gear * turn;
    const Vec2 c =
        start.position() + side * radius * Vec2{-std::sin(start.theta), std::cos(start.theta)};
    const double phi = h - side * kPi / 2;
    return {c.x + radius * std::cos(phi), c.y + radius * std::sin(phi), h};
  }
  int samples() const {  // 1 mm along the centre path and 0.1° of heading
    const double travel = radius == 0 ? std::abs(length) : radius * std::abs(turn);
    const double deg = std::abs(turn) * 180 / kPi;
    return 1 + static_cast<int>(std::ceil(std::max(travel / 1e-3, deg / 0.1)));
  }
};

TEST(CSpaceSlow, MotionsReportedFreeAreFreeAtEveryMillimetre) {
  long checked = 0, reported_free = 0, missed = 0, ref_free = 0, conservative = 0;
  for (const Scene& scene : all_scenes()) {
    const CSpace cs(scene);
    const ExactReference ref(scene);
    std::mt19937_64 rng(99);
    std::uniform_real_distribution<double> len(-0.6, 0.6), turn(-kPi / 2, kPi / 2), rad(0.3, 2.0);
    long here = 0;
    for (int i = 0; here < 1700; ++i) {
      Motion m;
      m.start = random_pose(scene, rng);
      if (!ref.pose_free(m.start)) continue;  // interesting motions start free
      ++here;
      if (i % 2 == 0) {
        m.length = len(rng);
      } else {
        m.radius = i % 4 == 1 ? scene.wheelchair.turning_radius : rad(rng);
        m.turn = turn(rng);
        m.gear = (i / 2) % 2 ? 1 : -1;
      }
      const bool ours = m.radius == 0 ? cs.straight_free(m.start, m.length)
                                      : cs.arc_free(m.start, m.radius, m.turn, m.gear);
      ++checked;
      reported_free += ours;
      bool truth = true;
      const int n = m.samples();
      for (int k = 0; k <= n && truth; ++k) truth = ref.pose_free(m.at(double(k) / n));
      ref_free += truth;
      if (ours && !truth) {
        ++missed;
        ADD_FAILURE() << scene.name << ": motion reported free collides, start " << m.start.x << ","
                      << m.start.y << "," << m.start.theta << " len " << m.length << " radius "
                      << m.radius << " turn " << m.turn << " gear " << m.gear;
      }
      conservative += (!ours && truth);
    }
  }
  std::printf(
      "motions checked %ld, reported free %ld, reference-free %ld, missed %ld, "
      "conservative %ld (%.3f%%)\n",
      checked, reported_free, ref_free, missed, conservative,
      100.0 * conservative / std::max(1L, ref_free));
  EXPECT_GE(checked, 10000);
  EXPECT_EQ(missed, 0);
  EXPECT_GT(reported_free, checked / 4);
  EXPECT_LT(double(conservative) / double(ref_free), 0.01);
}

}  // namespace
}  // namespace hrs::geometry
