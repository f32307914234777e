// SPDX-License-Identifier: GPL-3.0-or-later
// C-space tests against the exact CGAL reference (tests/geometry/reference.h),
// analytic clearance cases, and incremental update vs rebuild.

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

struct Counts {
  long free = 0, ref_free = 0, missed = 0, conservative = 0;
};

Counts check_poses(const Scene& scene, int n, std::uint64_t seed) {
  CSpace cs(scene);
  ExactReference ref(scene);
  std::mt19937_64 rng(seed);
  Counts c;
  for (int i = 0; i < n; ++i) {
    const Pose2 p = random_pose(scene, rng);
    const bool ours = cs.is_free(p);
    const bool truth = ref.pose_free(p);
    c.free += ours;
    c.ref_free += truth;
    if (ours && !truth) {
      ++c.missed;
      ADD_FAILURE() << scene.name << ": reported free but collides: " << p.x << "," << p.y << ","
                    << p.theta;
    }
    if (!ours && truth) ++c.conservative;
  }
  return c;
}

TEST(CSpace, FreePosesAreCertifiedInLShapedRoomWithNonConvexObject) {
  const Counts c = check_poses(test_support::l_shaped_scene(), 20000, 7);
  EXPECT_EQ(c.missed, 0);
  EXPECT_GT(c.free, 1000);  // the test must exercise free answers
  const double rate = double(c.conservative) / double(c.ref_free);
  std::printf("[l_room] poses 20000, free %ld, reference-free %ld, conservative %ld (%.4f%%)\n",
              c.free, c.ref_free, c.conservative, 100 * rate);
  EXPECT_LT(rate, 0.01);
}

TEST(CSpace, EmptyRoomCentreIsFreeAndOutsideIsNot) {
  CSpace cs(test_support::empty_room(4, 3));
  EXPECT_TRUE(cs.is_free({2, 1.5, 0.3}));
  EXPECT_FALSE(cs.is_free({-1, 1.5, 0}));
  EXPECT_FALSE(cs.is_free({0.2, 1.5, 0}));  // half the chair through the wall
  // Chair 1.1 x 0.65: heading along x needs 0.55 from the side walls.
  EXPECT_TRUE(cs.is_free({0.56, 1.5, 0}));
  EXPECT_FALSE(cs.is_free({0.549, 1.5, 0}));
  EXPECT_FALSE(cs.is_free({2, 1.5, std::nan("")}));
}

TEST(CSpace, StraightAndArcAgainstWalls) {
  CSpace cs(test_support::empty_room(4, 3));
  EXPECT_TRUE(cs.straight_free({1, 1.5, 0}, 2.0));
  EXPECT_FALSE(cs.straight_free({1, 1.5, 0}, 3.0));   // ends through the east wall
  EXPECT_FALSE(cs.straight_free({3, 1.5, 0}, -2.6));  // reverses through the west wall
  EXPECT_TRUE(cs.arc_free({2, 1.0, 0}, 0.7, kPi / 2, 1));
  // A full left circle of radius 0.7 around (2, 1.7): the chair's far corner
  // reaches 1.7 + |(0.7 + 0.325, 0.55)| = 2.863 m: free in a 3 m room, not in 2.8 m.
  EXPECT_TRUE(cs.arc_free({2, 1.0, 0}, 0.7, 2 * kPi, 1));
  EXPECT_TRUE(cs.arc_free({2, 1.0, 0}, 0.7, 2 * kPi, -1));
  CSpace low(test_support::empty_room(4, 2.8));
  EXPECT_TRUE(low.arc_free({2, 1.0, 0}, 0.7, kPi / 4, 1));
  EXPECT_FALSE(low.arc_free({2, 1.0, 0}, 0.7, 2 * kPi, 1));
  // Right turns mirror left turns about the heading line.
  EXPECT_FALSE(low.arc_free({2, 1.8, 0}, 0.7, -2 * kPi, 1));
  EXPECT_TRUE(cs.arc_free({2, 2.0, 0}, 0.7, -2 * kPi, 1));
}

TEST(CSpace, ClearanceBetweenParallelWalls) {
  CSpace cs(test_support::empty_room(10, 2));
  const Clearance c = cs.clearance({5, 0.7, 0});
  EXPECT_NEAR(c.left, 1.3, 1e-12);
  EXPECT_NEAR(c.right, 0.7, 1e-12);
  const Clearance r = cs.clearance({5, 0.7, kPi});  // turned around: sides swap
  EXPECT_NEAR(r.left, 0.7, 1e-12);
  EXPECT_NEAR(r.right, 1.3, 1e-12);
}

TEST(CSpace, ClearanceInLCorner) {
  Scene s = test_support::l_shaped_scene();
  s.room.polygon = {{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}};
  s.objects.clear();
  CSpace cs(s);
  Clearance c = cs.clearance({1.5, 2.5, kPi / 2});
  EXPECT_NEAR(c.left, 1.5, 1e-12);
  EXPECT_NEAR(c.right, 0.5, 1e-12);
  c = cs.clearance({2.5, 1.5, 0});
  EXPECT_NEAR(c.left, 0.5, 1e-12);
  EXPECT_NEAR(c.right, 1.5, 1e-12);
  // Facing the inner corner: it lies on the heading line, in both closed halves.
  c = cs.clearance({1.5, 1.5, kPi / 4});
  EXPECT_NEAR(c.left, std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(c.right, std::sqrt(0.5), 1e-12);
}

TEST(CSpace, ClearanceSeesFurniture) {
  Scene s = test_support::empty_room(10, 4);
  Object box;
  box.id = "box";
  box.footprint = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  box.pose = {5, 3, 0};  // spans y in [2.5, 3.5]
  s.objects = {box};
  CSpace cs(s);
  const Clearance c = cs.clearance({5, 1, 0});
  EXPECT_NEAR(c.left, 1.5, 1e-12);
  EXPECT_NEAR(c.right, 1.0, 1e-12);
}

TEST(CSpace, IncrementalUpdateEqualsRebuild) {
  Scene scene = test_support::l_shaped_scene();
  CSpace inc(scene);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> step(-0.4, 0.4), turn(-1.0, 1.0);
  std::uniform_int_distribution<int> which(0, static_cast<int>(scene.objects.size()) - 1);
  for (int move = 0; move < 60; ++move) {
    const int i = which(rng);
    Pose2 p = scene.objects[i].pose;
    if (move % 2 == 0) {
      p.x += step(rng), p.y += step(rng);
    } else {
      p.theta = wrap_angle(p.theta + turn(rng));
    }
    scene.objects[i].pose = p;
    inc.move_object(i, p);
    const CSpace fresh(scene);
    for (int q = 0; q < 500; ++q) {
      const Pose2 pose = random_pose(scene, rng);
      ASSERT_EQ(inc.is_free(pose), fresh.is_free(pose)) << "move " << move;
      const double len = step(rng);
      ASSERT_EQ(inc.straight_free(pose, len), fresh.straight_free(pose, len));
      const double t = turn(rng);
      ASSERT_EQ(inc.arc_free(pose, 0.7, t, q % 2 ? 1 : -1),
                fresh.arc_free(pose, 0.7, t, q % 2 ? 1 : -1));
      const Clearance a = inc.clearance(pose), b = fresh.clearance(pose);
      ASSERT_EQ(a.left, b.left);
      ASSERT_EQ(a.right, b.right);
    }
  }
}

// Clearance by an independent formulation: each boundary segment is
// parametrized a + t(b − a); the part on one side of the heading is an
// interval of t, and the nearest point of that part is the projection of the
// position clamped to the interval. Walls and every object's world footprint.
struct BruteClearance {
  double side[2];
  int owner[2];
};
BruteClearance brute_clearance(const Scene& scene, const Pose2& pose) {
  const Vec2 p = pose.position(), left{-std::sin(pose.theta), std::cos(pose.theta)};
  BruteClearance c{{INFINITY, INFINITY}, {CSpace::kNothing, CSpace::kNothing}};
  auto ring = [&](const Polygon& poly, int owner) {
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Vec2 a = poly[i], b = poly[(i + 1) % poly.size()], ab = b - a;
      const double sa = dot(a - p, left), sd = dot(ab, left);  // s(t) = sa + t·sd
      for (int side = 0; side < 2; ++side) {
        const double g = side == 0 ? 1.0 : -1.0;  // want g·s(t) >= 0
        double lo = 0.0, hi = 1.0;
        if (g * sd > 0)
          lo = std::max(lo, -sa / sd);
        else if (g * sd < 0)
          hi = std::min(hi, -sa / sd);
        else if (g * sa < 0)
          continue;
        if (lo > hi) continue;
        const double l2 = dot(ab, ab);
        const double t = std::clamp(l2 > 0 ? dot(p - a, ab) / l2 : 0.0, lo, hi);
        const double d = norm(p - (a + t * ab));
        if (d < c.side[side]) c.side[side] = d, c.owner[side] = owner;
      }
    }
  };
  ring(scene.room.polygon, CSpace::kWalls);
  for (std::size_t k = 0; k < scene.objects.size(); ++k)
    ring(world_footprint(scene.objects[k]), static_cast<int>(k));
  return c;
}

TEST(CSpace, NearestObstaclesMatchBruteForceAndObjectClearances) {
  long cases = 0, object_owned = 0, wall_owned = 0;
  for (const std::string& file : test_support::scene_files()) {
    Scene scene = load_scene(file);
    CSpace cs(scene);
    std::mt19937_64 rng(21);
    std::uniform_int_distribution<int> which(0, static_cast<int>(scene.objects.size()) - 1);
    for (int round = 0; round < 20; ++round) {
      // Move an object anywhere (clearance is defined whatever the layout).
      const int k = which(rng);
      const Pose2 to = random_pose(scene, rng);
      scene.objects[k].pose = to;
      cs.move_object(k, to);
      for (int q = 0; q < 200; ++q, ++cases) {
        const Pose2 pose = random_pose(scene, rng);
        const CSpace::NearestObstacles n = cs.nearest_obstacles(pose);
        const BruteClearance b = brute_clearance(scene, pose);
        const Clearance plain = cs.clearance(pose);
        ASSERT_EQ(plain.left, n.clearance.left);
        ASSERT_EQ(plain.right, n.clearance.right);
        const double ours[2] = {n.clearance.left, n.clearance.right};
        const int owners[2] = {n.left, n.right};
        for (int side = 0; side < 2; ++side) {
          // Outside a non-convex room a ray can miss every wall: both +inf.
          if (std::isinf(b.side[side]))
            ASSERT_EQ(ours[side], b.side[side]) << file << " side " << side;
          else
            ASSERT_NEAR(ours[side], b.side[side], 1e-9) << file << " side " << side;
          // The owner's own clearance is the value; no object is nearer.
          double lowest = INFINITY;
          for (int o = 0; o < cs.object_count(); ++o) {
            const Clearance oc = cs.object_clearance(pose, o);
            const double v = side == 0 ? oc.left : oc.right;
            ASSERT_GE(v, ours[side]) << file << " object " << o;
            lowest = std::min(lowest, v);
            if (o == owners[side]) {
              ASSERT_EQ(v, ours[side]) << file;
            }
          }
          if (owners[side] == CSpace::kNothing) {
            ASSERT_TRUE(std::isinf(ours[side])) << file;  // outside a non-convex room
          } else if (owners[side] == CSpace::kWalls) {
            ++wall_owned;
            ASSERT_GE(lowest, ours[side]) << file;  // walls, visited first, win ties
          } else {
            ASSERT_GE(owners[side], 0) << file;
            ++object_owned;
          }
        }
      }
    }
  }
  EXPECT_GT(object_owned, 1000);
  EXPECT_GT(wall_owned, 1000);
  std::printf("%ld poses: %ld sides nearest an object, %ld nearest a wall\n", cases, object_owned,
              wall_owned);
}

}  // namespace
}  // namespace hrs::geometry
