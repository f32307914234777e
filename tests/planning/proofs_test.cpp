// SPDX-License-Identifier: GPL-3.0-or-later
// Infeasibility proofs of geometry::FreeGrid (the "impossible" verdict of
// `hrspace plan`) against the planner: a leg the RRT found is never proven
// impossible, and every pose of its path lies in an unblocked cell, each
// cell a 26-neighbour of the last (the path is the witness the proof must
// not contradict); a leg through a gap narrower than the chair is proven
// impossible and the baseline RRT with ten times its budget finds nothing
// either, while a wide gap is connected and its leg found.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "geometry/cspace.h"
#include "geometry/free_grid.h"
#include "planning/rrt.h"
#include "tests/support/paths.h"

namespace hrs::planning {
namespace {

using geometry::FreeGrid;
using geometry::ReachabilityQuery;

//! True if cells a and b are equal or 26-neighbours (heading wraps).
bool adjacent(const FreeGrid& g, std::size_t a, std::size_t b) {
  int ax, ay, ak, bx, by, bk;
  g.coords(a, ax, ay, ak);
  g.coords(b, bx, by, bk);
  const int dk = std::abs(ak - bk);
  return std::abs(ax - bx) <= 1 && std::abs(ay - by) <= 1 && (dk <= 1 || dk == g.slices() - 1);
}

TEST(Proofs, FoundPathsCrossOnlyUnblockedNeighbouringCellsAndAreNeverProvenImpossible) {
  int paths = 0;
  for (const std::string& file : test_support::planning_scene_files()) {
    const geometry::Scene scene = geometry::load_scene(file);
    const geometry::CSpace cspace(scene);
    const FreeGrid grid(scene);
    LegPlanner planner(scene, cspace);
    ReachabilityQuery query;
    std::mt19937_64 rng(99);
    for (int i = 0; i < 60; ++i) {
      const Pose2 a = test_support::random_free_pose(scene, cspace, rng);
      const Pose2 b = test_support::random_free_pose(scene, cspace, rng);
      const LegResult r = planner.plan(a, b, 1 + i);
      if (!r.found) continue;
      ++paths;
      ASSERT_NE(query.query(grid, a, b), ReachabilityQuery::Answer::kDisconnected)
          << file << " leg " << i << ": found, yet proven impossible";
      // Walk the path every 2 mm (a cell is >= 2.4 cm and 2.5°; the chair
      // turns by at most 2 mm / 0.7 m = 0.16° a step).
      std::size_t last = grid.cell_of(a);
      for (const Pose2& p : rs::sample(a, r.path, 0.002)) {
        const std::size_t cell = grid.cell_of(p);
        ASSERT_FALSE(grid.blocked(cell)) << file << " leg " << i << ": path pose in a blocked cell";
        ASSERT_TRUE(adjacent(grid, last, cell)) << file << " leg " << i << ": cells jump";
        last = cell;
      }
    }
  }
  EXPECT_GT(paths, 150);
}

//! test_support::split_room with a table in the right half (a leg's goal object).
geometry::Scene split_room(double gap) {
  geometry::Scene s = test_support::split_room(gap);
  geometry::Object table;
  table.id = "table";
  table.footprint = {{-0.3, -0.3}, {0.3, -0.3}, {0.3, 0.3}, {-0.3, 0.3}};
  table.pose = {5.0, 1.0, 0.0};
  s.objects.push_back(table);
  return s;
}

TEST(Proofs, LegThroughTooNarrowAGapIsProvenAndNoLongRrtFindsIt) {
  // The verdict `hrspace plan` prints as "impossible" (api::plan_leg).
  const Pose2 left{1.0, 1.2, 0.0}, right{4.6, 2.0, 0.0};
  for (double gap : {0.5, 1.6}) {
    const geometry::Scene scene = split_room(gap);
    const geometry::CSpace cspace(scene);
    ASSERT_TRUE(cspace.is_free(left) && cspace.is_free(right));
    const FreeGrid grid(scene);
    ReachabilityQuery query;
    const auto answer = query.query(grid, left, right, 10'000'000);  // both halves are large
    PlannerOptions long_run;
    long_run.max_iterations = 30'000;
    long_run.max_nodes = 200'000;
    LegPlanner baseline(scene, cspace, long_run);
    const LegResult r = baseline.plan(left, right, 11);
    if (gap < 0.65) {
      EXPECT_EQ(answer, ReachabilityQuery::Answer::kDisconnected);
      EXPECT_FALSE(r.found) << "a path through a " << gap << " m gap";
    } else {
      EXPECT_EQ(answer, ReachabilityQuery::Answer::kConnected) << "wide gap";
      EXPECT_TRUE(r.found);
    }
  }
}

TEST(Proofs, RandomLegsProvenImpossibleAreNotFoundByTenTimesTheBudget) {
  // Random free pose pairs in rooms split by too narrow a gap: a pair is
  // proven impossible exactly when its poses are in different halves, and
  // every such pair is given to the baseline RRT with 30 000 iterations.
  int proven = 0, pairs = 0;
  for (double gap : {0.45, 0.55}) {
    const geometry::Scene scene = split_room(gap);
    const geometry::CSpace cspace(scene);
    const FreeGrid grid(scene);
    ReachabilityQuery query;
    PlannerOptions long_run;
    long_run.max_iterations = 30'000;
    long_run.max_nodes = 200'000;
    LegPlanner planner(scene, cspace, long_run);
    std::mt19937_64 rng(5);
    for (int i = 0; i < 24; ++i) {
      const Pose2 a = test_support::random_free_pose(scene, cspace, rng);
      const Pose2 b = test_support::random_free_pose(scene, cspace, rng);
      ++pairs;
      const bool across = (a.x < 3.0) != (b.x < 3.0);
      const auto answer = query.query(grid, a, b, 10'000'000);
      // Analytic: the halves are separated, each half is connected.
      EXPECT_EQ(answer, across ? ReachabilityQuery::Answer::kDisconnected
                               : ReachabilityQuery::Answer::kConnected)
          << "gap " << gap << " pair " << i;
      if (answer != ReachabilityQuery::Answer::kDisconnected) continue;
      ++proven;
      EXPECT_FALSE(planner.plan(a, b, 1 + i).found) << "pair " << i << ": proven, yet found";
    }
  }
  std::printf("pairs proven impossible: %d of %d\n", proven, pairs);
  EXPECT_GT(proven, 8);
}

}  // namespace
}  // namespace hrs::planning
