// C-space tests against the exact CGAL reference (tests/geometry/reference.h),
// analytic clearance cases, and incremental update vs rebuild.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "geometry/cspace.h"
#include "tests/geometry/fixtures.h"
#include "tests/geometry/reference.h"

namespace hrs::geometry {
namespace {

using testing::ExactReference;
using testing::random_pose;
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
  const Counts c = check_poses(testing::l_shaped_scene(), 20000, 7);
  EXPECT_EQ(c.missed, 0);
  EXPECT_GT(c.free, 1000);  // the test must exercise free answers
  const double rate = double(c.conservative) / double(c.ref_free);
  std::printf("[l_room] poses 20000, free %ld, reference-free %ld, conservative %ld (%.4f%%)\n",
              c.free, c.ref_free, c.conservative, 100 * rate);
  EXPECT_LT(rate, 0.01);
}

TEST(CSpace, EmptyRoomCentreIsFreeAndOutsideIsNot) {
  CSpace cs(testing::empty_room(4, 3));
  EXPECT_TRUE(cs.is_free({2, 1.5, 0.3}));
  EXPECT_FALSE(cs.is_free({-1, 1.5, 0}));
  EXPECT_FALSE(cs.is_free({0.2, 1.5, 0}));  // half the chair through the wall
  // Chair 1.1 x 0.65: heading along x needs 0.55 from the side walls.
  EXPECT_TRUE(cs.is_free({0.56, 1.5, 0}));
  EXPECT_FALSE(cs.is_free({0.549, 1.5, 0}));
  EXPECT_FALSE(cs.is_free({2, 1.5, std::nan("")}));
}

TEST(CSpace, StraightAndArcAgainstWalls) {
  CSpace cs(testing::empty_room(4, 3));
  EXPECT_TRUE(cs.straight_free({1, 1.5, 0}, 2.0));
  EXPECT_FALSE(cs.straight_free({1, 1.5, 0}, 3.0));   // ends through the east wall
  EXPECT_FALSE(cs.straight_free({3, 1.5, 0}, -2.6));  // reverses through the west wall
  EXPECT_TRUE(cs.arc_free({2, 1.0, 0}, 0.7, kPi / 2, 1));
  // A full left circle of radius 0.7 around (2, 1.7): the chair's far corner
  // reaches 1.7 + |(0.7 + 0.325, 0.55)| = 2.863 m: free in a 3 m room, not in 2.8 m.
  EXPECT_TRUE(cs.arc_free({2, 1.0, 0}, 0.7, 2 * kPi, 1));
  EXPECT_TRUE(cs.arc_free({2, 1.0, 0}, 0.7, 2 * kPi, -1));
  CSpace low(testing::empty_room(4, 2.8));
  EXPECT_TRUE(low.arc_free({2, 1.0, 0}, 0.7, kPi / 4, 1));
  EXPECT_FALSE(low.arc_free({2, 1.0, 0}, 0.7, 2 * kPi, 1));
  // Right turns mirror left turns about the heading line.
  EXPECT_FALSE(low.arc_free({2, 1.8, 0}, 0.7, -2 * kPi, 1));
  EXPECT_TRUE(cs.arc_free({2, 2.0, 0}, 0.7, -2 * kPi, 1));
}

TEST(CSpace, ClearanceBetweenParallelWalls) {
  CSpace cs(testing::empty_room(10, 2));
  const Clearance c = cs.clearance({5, 0.7, 0});
  EXPECT_NEAR(c.left, 1.3, 1e-12);
  EXPECT_NEAR(c.right, 0.7, 1e-12);
  const Clearance r = cs.clearance({5, 0.7, kPi});  // turned around: sides swap
  EXPECT_NEAR(r.left, 0.7, 1e-12);
  EXPECT_NEAR(r.right, 1.3, 1e-12);
}

TEST(CSpace, ClearanceInLCorner) {
  Scene s = testing::l_shaped_scene();
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
  Scene s = testing::empty_room(10, 4);
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
  Scene scene = testing::l_shaped_scene();
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

}  // namespace
}  // namespace hrs::geometry
