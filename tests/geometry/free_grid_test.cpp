// FreeGrid: a blocked cell holds only colliding poses (by the exact CGAL
// reference, which shares nothing with the grid), a certified-free pose never
// lies in a blocked cell, incremental moves equal a rebuild, and analytic
// passages: a gap narrower than the chair separates the room, a wide one
// does not.

#include "geometry/free_grid.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <numbers>
#include <random>

#include "geometry/cspace.h"
#include "tests/support/reference.h"
#include "tests/support/scenes.h"

namespace hrs::geometry {
namespace {

using hrs::uniform01;
using hrs::test_support::ExactReference;
using hrs::test_support::split_room;

//! The scenes under test: the L-shaped room and every shipped scene, each
//! also with its movable objects displaced at random (overlaps allowed).
std::vector<Scene> test_scenes(std::mt19937_64& rng) {
  std::vector<Scene> out{hrs::test_support::l_shaped_scene()};
  for (const std::string& f : hrs::test_support::scene_files()) out.push_back(load_scene(f));
  const std::size_t n = out.size();
  for (std::size_t i = 0; i < n; ++i) {
    Scene s = out[i];
    for (Object& o : s.objects) {
      if (o.fixed) continue;
      o.pose.x += 0.6 * (2 * uniform01(rng) - 1);
      o.pose.y += 0.6 * (2 * uniform01(rng) - 1);
      o.pose.theta += 0.8 * (2 * uniform01(rng) - 1);
    }
    out.push_back(std::move(s));
  }
  return out;
}

//! A uniformly random pose in the closed cell.
Pose2 pose_in_cell(const FreeGrid& g, std::size_t cell, std::mt19937_64& rng) {
  const Pose2 c = g.centre(cell);
  return {c.x + g.hx() * (uniform01(rng) - 0.5), c.y + g.hy() * (uniform01(rng) - 0.5),
          c.theta + g.slice_width() * (uniform01(rng) - 0.5)};
}

//! True if a 26-neighbour of the cell is not blocked (the cell is on the
//! border of the blocked region, where the test is tightest).
bool on_border(const FreeGrid& g, std::size_t cell) {
  int ix, iy, k;
  g.coords(cell, ix, iy, k);
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx)
      for (int dk = -1; dk <= 1; ++dk) {
        const int x = ix + dx, y = iy + dy, kk = (k + dk + g.slices()) % g.slices();
        if (x < 0 || y < 0 || x >= g.nx() || y >= g.ny()) continue;
        if (!g.blocked(g.index(x, y, kk))) return true;
      }
  return false;
}

TEST(FreeGrid, BlockedBorderCellsHoldOnlyCollidingPosesByExactReference) {
  std::mt19937_64 rng(20261122);
  int checked = 0;
  for (const Scene& scene : test_scenes(rng)) {
    const FreeGrid grid(scene);
    const ExactReference ref(scene);
    ASSERT_GT(grid.blocked_count(), 0u) << scene.name;
    // 400 border cells per scene, one or two random poses each, plus the
    // cell's corners at both heading ends (the extreme poses).
    int found = 0;
    for (int tries = 0; found < 400 && tries < 4'000'000; ++tries) {
      const std::size_t cell = rng() % grid.cell_count();
      if (!grid.blocked(cell) || !on_border(grid, cell)) continue;
      ++found;
      const Pose2 c = grid.centre(cell);
      const double sx[2] = {-0.5, 0.5}, st[2] = {-0.5, 0.5};
      std::vector<Pose2> poses{pose_in_cell(grid, cell, rng)};
      if (found % 4 == 0) {
        for (double a : sx)
          for (double b : sx)
            for (double t : st)
              poses.push_back(
                  {c.x + a * grid.hx(), c.y + b * grid.hy(), c.theta + t * grid.slice_width()});
      }
      for (const Pose2& p : poses) {
        ++checked;
        ASSERT_FALSE(ref.pose_free(p)) << scene.name << ": pose (" << p.x << ", " << p.y << ", "
                                       << p.theta << ") in a blocked cell is free";
      }
    }
    EXPECT_EQ(found, 400) << scene.name;
  }
  EXPECT_GT(checked, 6000);
}

TEST(FreeGrid, CertifiedFreePosesNeverLieInBlockedCells) {
  std::mt19937_64 rng(7);
  for (const Scene& scene : test_scenes(rng)) {
    const FreeGrid grid(scene);
    const CSpace cspace(scene);
    int free_poses = 0;
    for (int i = 0; i < 100'000; ++i) {
      const Pose2 p = hrs::test_support::random_pose(scene, rng);
      if (!cspace.is_free(p)) continue;
      ++free_poses;
      ASSERT_FALSE(grid.blocked(grid.cell_of(p)))
          << scene.name << ": free pose (" << p.x << ", " << p.y << ", " << p.theta << ")";
    }
    EXPECT_GT(free_poses, 300) << scene.name;
  }
}

TEST(FreeGrid, MostCollidingPosesAreInBlockedCells) {
  // Tightness, not soundness: the grid must not be vacuous. A pose that
  // collides by more than the core's margin lies in a blocked cell, so
  // blocked cells hold the large majority of the colliding poses.
  std::mt19937_64 rng(11);
  const Scene scene = load_scene(hrs::test_support::scene_files().front());
  const FreeGrid grid(scene);
  const ExactReference ref(scene);
  int colliding = 0, blocked = 0;
  for (int i = 0; i < 3000; ++i) {
    const Pose2 p = hrs::test_support::random_pose(scene, rng);
    if (ref.pose_free(p)) continue;
    ++colliding;
    blocked += grid.blocked(grid.cell_of(p)) ? 1 : 0;
  }
  ASSERT_GT(colliding, 500);
  EXPECT_GT(static_cast<double>(blocked) / colliding, 0.9) << blocked << " / " << colliding;
  std::printf("colliding poses in blocked cells: %d / %d\n", blocked, colliding);
}

TEST(FreeGrid, IncrementalMovesEqualRebuild) {
  std::mt19937_64 rng(3);
  Scene scene = hrs::test_support::l_shaped_scene();
  FreeGrid grid(scene, {0.05, 72});
  for (int step = 0; step < 60; ++step) {
    const int i = static_cast<int>(rng() % scene.objects.size());
    Pose2& p = scene.objects[i].pose;
    p.x = 0.5 + 5.0 * uniform01(rng), p.y = 0.5 + 5.0 * uniform01(rng);
    if (step % 2 == 0) p.theta = std::numbers::pi * (2 * uniform01(rng) - 1);
    grid.move_object(i, p);
    if (step % 10 != 9) continue;
    const FreeGrid fresh(scene, {0.05, 72});
    ASSERT_EQ(grid.blocked_count(), fresh.blocked_count());
    for (std::size_t c = 0; c < grid.cell_count(); ++c)
      ASSERT_EQ(grid.blocked(c), fresh.blocked(c)) << "cell " << c << " after step " << step;
  }
}

TEST(ReachabilityQuery, GapNarrowerThanTheChairSeparatesTheRoom) {
  // The chair is 0.65 m wide: no pose with its centre at x = 3 fits a
  // 0.55 m gap, so the halves are disconnected; a 1.5 m gap joins them.
  ReachabilityQuery q;
  const Pose2 left{1.0, 1.5, 0.3}, right{5.0, 1.0, -2.0};
  for (double gap : {0.4, 0.55}) {
    const FreeGrid grid(split_room(gap));
    EXPECT_EQ(q.query(grid, left, right), ReachabilityQuery::Answer::kDisconnected) << gap;
    EXPECT_EQ(q.query(grid, right, left), ReachabilityQuery::Answer::kDisconnected) << gap;
    EXPECT_EQ(q.query(grid, left, Pose2{1.5, 2.0, 2.5}), ReachabilityQuery::Answer::kConnected);
  }
  const FreeGrid wide(split_room(1.5));
  EXPECT_EQ(q.query(wide, left, right), ReachabilityQuery::Answer::kConnected);
}

TEST(ReachabilityQuery, BlockedEndIsUnknownAndBudgetIsRespected) {
  const FreeGrid grid(split_room(1.5));
  ReachabilityQuery q;
  // Centre inside the partition: the end cell is blocked.
  EXPECT_EQ(q.query(grid, Pose2{3.0, 0.5, 0.0}, Pose2{1.0, 1.5, 0.0}),
            ReachabilityQuery::Answer::kUnknown);
  EXPECT_EQ(q.query(grid, Pose2{1.0, 1.5, 0.3}, Pose2{5.0, 1.0, -2.0}, 1000),
            ReachabilityQuery::Answer::kUnknown);
  EXPECT_LE(q.visited(), 1000u + 27u);
}

}  // namespace
}  // namespace hrs::geometry
