// SPDX-License-Identifier: GPL-3.0-or-later
// The lattice leg planner (planning/lattice.h) against independent answers:
// - its paths against the exact CGAL reference (every pose 5 mm apart, the
//   ends driven segment by segment);
// - its found / no-path answer against a breadth-first search of the same
//   lattice, and against its own A* at weight 0 (Dijkstra), on small rooms
//   with random boxes: the three must agree on every query;
// - its "no path" answers against a long RRT (30 000 iterations): in rooms
//   whose opening is too narrow (proven by the free grid) or is wide, the
//   RRT finds a leg only where the lattice does.

#include <gtest/gtest.h>

#include <random>
#include <string>

#include "geometry/cspace.h"
#include "geometry/free_grid.h"
#include "planning/lattice.h"
#include "planning/rrt.h"
#include "tests/support/paths.h"

namespace hrs::planning {
namespace {

//! test_support::split_room(gap) with `boxes` random fixed boxes (0.3-0.6 m).
geometry::Scene cluttered_split_room(double gap, int boxes, std::mt19937_64& rng) {
  geometry::Scene s = test_support::split_room(gap);
  std::uniform_real_distribution<double> x(0.4, 5.6), y(0.4, 2.6), side(0.15, 0.3);
  for (int i = 0; i < boxes; ++i) {
    geometry::Object box;
    box.id = "box" + std::to_string(i);
    const double a = side(rng), b = side(rng);
    box.footprint = {{-a, -b}, {a, -b}, {a, b}, {-a, b}};
    box.pose = {x(rng), y(rng), 0.0};
    box.fixed = true;
    s.objects.push_back(box);
  }
  return s;
}

TEST(Lattice, FoundPathsAreValidByTheExactReference) {
  int found = 0, queries = 0, searched = 0;
  for (const char* file : {"bedroom.json", "office.json", "narrow_passage.json"}) {
    const geometry::Scene scene = test_support::shipped_scene(file);
    const geometry::CSpace cspace(scene);
    const test_support::ReferenceChecker reference(scene);
    LatticePlanner lattice(scene, cspace, scene.wheelchair.turning_radius);
    std::mt19937_64 rng(41);
    for (int i = 0; i < 12; ++i) {
      const Pose2 a = test_support::random_free_pose(scene, cspace, rng);
      const Pose2 b = test_support::random_free_pose(scene, cspace, rng);
      const LatticeResult r = lattice.plan(a, b);
      ++queries;
      if (!r.found()) continue;
      ++found;
      if (r.expansions > 0) ++searched;
      test_support::expect_valid_path(reference, a, b, r.path, scene.wheelchair.turning_radius,
                                      std::string(file) + " query " + std::to_string(i), 0.005);
    }
  }
  EXPECT_GT(found, queries / 2);
  // Most paths come from the search, not from the direct RS path.
  EXPECT_GT(searched, found / 2) << found;
}

TEST(Lattice, BestFirstBreadthFirstAndDijkstraAgreeOnEveryQuery) {
  std::mt19937_64 rng(43);
  int found = 0, none = 0;
  for (int room = 0; room < 6; ++room) {
    const double gap = room % 3 == 0 ? 0.6 : room % 3 == 1 ? 0.95 : 1.4;
    const geometry::Scene scene = cluttered_split_room(gap, 3 + room, rng);
    const geometry::CSpace cspace(scene);
    LatticeOptions coarse;
    coarse.cell = 0.15;
    coarse.headings = 24;
    coarse.max_expansions = 10'000'000;  // exhaust: the answers must be proofs
    LatticeOptions dijkstra = coarse, bfs = coarse;
    dijkstra.heuristic_weight = 0.0;
    bfs.breadth_first = true;
    const double r = scene.wheelchair.turning_radius;
    LatticePlanner a(scene, cspace, r, coarse), d(scene, cspace, r, dijkstra),
        b(scene, cspace, r, bfs);
    for (int i = 0; i < 10; ++i) {
      const Pose2 from = test_support::random_free_pose(scene, cspace, rng);
      const Pose2 to = test_support::random_free_pose(scene, cspace, rng);
      const LatticeResult ra = a.plan(from, to), rd = d.plan(from, to), rb = b.plan(from, to);
      ASSERT_NE(ra.answer, LatticeAnswer::kBudget);
      EXPECT_EQ(ra.answer, rb.answer) << "room " << room << " query " << i;
      EXPECT_EQ(rd.answer, rb.answer) << "room " << room << " query " << i;
      (rb.found() ? found : none) += 1;
      // Breadth-first settles every reachable node when nothing joins the goal.
      if (!rb.found()) {
        EXPECT_EQ(ra.expansions, rb.expansions) << "room " << room << " query " << i;
      }
    }
  }
  // Both answers occurred (the narrow rooms separate their halves).
  EXPECT_GT(found, 10);
  EXPECT_GT(none, 3);
}

TEST(Lattice, NoPathAnswersAreConfirmedByALongRrt) {
  int no_path = 0, found = 0;
  for (double gap : {0.5, 0.95, 1.2}) {
    const geometry::Scene scene = test_support::split_room(gap);
    const geometry::CSpace cspace(scene);
    const geometry::FreeGrid grid(scene);
    geometry::ReachabilityQuery query;
    LatticeOptions exhaust;
    exhaust.max_expansions = 10'000'000;
    LatticePlanner lattice(scene, cspace, scene.wheelchair.turning_radius, exhaust);
    PlannerOptions long_run;
    long_run.max_iterations = 30'000;
    long_run.max_nodes = 200'000;
    LegPlanner rrt(scene, cspace, long_run);
    std::mt19937_64 rng(47);
    for (int i = 0; i < 10; ++i) {
      const Pose2 a = test_support::random_free_pose(scene, cspace, rng);
      const Pose2 b = test_support::random_free_pose(scene, cspace, rng);
      const LatticeResult r = lattice.plan(a, b);
      ASSERT_NE(r.answer, LatticeAnswer::kBudget);
      if (r.found()) {
        ++found;
        // A proof of impossibility would contradict a found path.
        EXPECT_NE(query.query(grid, a, b, 10'000'000),
                  geometry::ReachabilityQuery::Answer::kDisconnected);
        continue;
      }
      ++no_path;
      EXPECT_FALSE(rrt.plan(a, b, 100 + i).found) << "gap " << gap << " query " << i;
    }
  }
  EXPECT_GT(no_path, 3);
  EXPECT_GT(found, 5);
}

}  // namespace
}  // namespace hrs::planning
