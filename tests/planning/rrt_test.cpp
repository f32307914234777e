// SPDX-License-Identifier: GPL-3.0-or-later
// Goal poses around objects, the RRT leg planner (unsolvable queries end
// within the caps, empty rooms always solved, determinism and thread
// independence) and impossible tours.

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <thread>

#include "geometry/cspace.h"
#include "geometry/random.h"
#include "geometry/scene.h"
#include "planning/goals.h"
#include "planning/rrt.h"
#include "planning/tour.h"
#include "tests/support/paths.h"
#include "tests/support/planning_scenes.h"

namespace hrs::planning {
namespace {

using geometry::Pose2;
using geometry::Vec2;
using hrs::uniform01;
using namespace hrs::test_support;

TEST(GoalPoses, FaceTheCentreLieOnAllowedSidesAtTheGapAndAreFree) {
  for (const std::string& file : test_support::planning_scene_files()) {
    const geometry::Scene scene = geometry::load_scene(file);
    const geometry::CSpace cspace(scene);
    const test_support::ExactReference reference(scene);
    int with_goals = 0;  // objects of this scene whose goal poses are checked below
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
      const geometry::Object& o = scene.objects[i];
      const auto goals = goal_poses(scene, o, o.pose, cspace);
      with_goals += goals.empty() ? 0 : 1;
      double perimeter = 0;
      for (std::size_t k = 0; k < o.footprint.size(); ++k)
        perimeter += geometry::norm(o.footprint[(k + 1) % o.footprint.size()] - o.footprint[k]);
      const int n = static_cast<int>(std::ceil(2.0 * perimeter / scene.wheelchair.width - 1e-9));
      EXPECT_LE(static_cast<int>(goals.size()), n) << file << " " << o.id;
      const auto approach = o.approach_or_default();
      for (const GoalPose& g : goals) {
        const Vec2 to_centre = o.pose.position() - g.pose.position();
        EXPECT_NEAR(geometry::wrap_angle(std::atan2(to_centre.y, to_centre.x) - g.pose.theta), 0.0,
                    1e-9)
            << file << " " << o.id;
        EXPECT_TRUE(cspace.is_free(g.pose));
        EXPECT_TRUE(reference.pose_free(g.pose)) << file << " " << o.id;
        EXPECT_TRUE(approach.sides[static_cast<int>(g.side)]) << file << " " << o.id;
        if (o.size) {
          // Independent side test for a rectangle in its local frame.
          const double hd = (*o.size)[0] / 2, hw = (*o.size)[1] / 2;
          const Vec2 l = geometry::rotate(g.pose.position() - o.pose.position(), -o.pose.theta);
          bool on_allowed = false;
          for (int side = 0; side < 4; ++side) {
            if (!approach.sides[side]) continue;
            const bool in = side == 0   ? (l.x > hd && std::abs(l.y) <= hw + 1e-9)
                            : side == 1 ? (l.x < -hd && std::abs(l.y) <= hw + 1e-9)
                            : side == 2 ? (l.y > hw && std::abs(l.x) <= hd + 1e-9)
                                        : (l.y < -hw && std::abs(l.x) <= hd + 1e-9);
            on_allowed = on_allowed || in;
          }
          EXPECT_TRUE(on_allowed) << file << " " << o.id << " local " << l.x << "," << l.y;
          // Gap: the chair's nearest corner to the footprint, by an independent
          // distance (chair corners to object edges and object corners to chair edges).
          const double hl = scene.wheelchair.length / 2, hc = scene.wheelchair.width / 2;
          geometry::Polygon chair;
          for (Vec2 c : {Vec2{hl, hc}, Vec2{-hl, hc}, Vec2{-hl, -hc}, Vec2{hl, -hc}})
            chair.push_back(geometry::to_world(g.pose, c));
          const geometry::Polygon fp = geometry::world_footprint(o);
          auto seg = [](Vec2 p, Vec2 a, Vec2 b) {
            const Vec2 ab = b - a;
            const double t = std::clamp(geometry::dot(p - a, ab) / geometry::dot(ab, ab), 0.0, 1.0);
            return geometry::norm(p - (a + t * ab));
          };
          double d = 1e300;
          for (std::size_t a = 0; a < 4; ++a)
            for (std::size_t b = 0; b < fp.size(); ++b) {
              d = std::min(d, seg(chair[a], fp[b], fp[(b + 1) % fp.size()]));
              d = std::min(d, seg(fp[b], chair[a], chair[(a + 1) % 4]));
            }
          EXPECT_GE(d, approach.gap - 1e-9) << file << " " << o.id;
          EXPECT_LE(d, approach.gap + 0.02) << file << " " << o.id;
        }
      }
    }
    // Every scene has objects the chair can stand at, so the checks above ran.
    EXPECT_GT(with_goals, 0) << file;
  }
}
TEST(LegPlanner, UnsolvableQueriesReturnNotFoundWithinTheCaps) {
  struct Case {
    const char* name;
    geometry::Scene scene;
    Pose2 from, to;
  };
  const Case cases[] = {
      {"enclosed goal", enclosed_goal_scene(), {0.6, 0.6, std::numbers::pi / 2}, {2.5, 3.5, 0.3}},
      {"walled-off pocket", pocket_scene(), {1.5, 2.0, 0.0}, {5.5, 2.0, 0.0}},
  };
  for (const Case& c : cases) {
    const geometry::CSpace cspace(c.scene);
    ASSERT_TRUE(cspace.is_free(c.from)) << c.name;
    ASSERT_TRUE(cspace.is_free(c.to)) << c.name;
    PlannerOptions opt;
    LegPlanner planner(c.scene, cspace, opt);
    const LegResult r = planner.plan(c.from, c.to, 11);
    EXPECT_FALSE(r.found) << c.name;
    EXPECT_TRUE(r.stats.iterations == opt.max_iterations || r.stats.tree_nodes >= opt.max_nodes)
        << c.name;
    std::printf("[unsolvable] %s: %d iterations, %d nodes, %llu checks, %.1f ms\n", c.name,
                r.stats.iterations, r.stats.tree_nodes,
                static_cast<unsigned long long>(r.stats.collision_checks), r.stats.time_ms);
  }
}
TEST(LegPlanner, GiveUpQuestionIsAskedOnceEvenUnderASmallerCap) {
  // The walled-off pocket: no motion exists, so the RRT never finds the goal.
  // Whichever stop comes first (the question at 300, an iteration cap below
  // or above it), the question is asked exactly once.
  const geometry::Scene scene = pocket_scene();
  const geometry::CSpace cspace(scene);
  const Pose2 from{1.5, 2.0, 0.0}, to{5.5, 2.0, 0.0};
  LegPlanner planner(scene, cspace);
  for (const int cap : {0, 1, 20, 299, 300, 301, 600}) {
    for (const bool answer : {false, true}) {
      RrtTree tree;
      int asked = 0;
      const Termination stop = Termination{}.iterations(cap).ask_after(300, [&] {
        ++asked;
        return answer;
      });
      const LegResult r = planner.plan(from, to, 5, tree, stop);
      const std::string what = "cap " + std::to_string(cap) + (answer ? " yes" : " no");
      EXPECT_FALSE(r.found) << what;
      EXPECT_EQ(asked, 1) << what;
      EXPECT_EQ(r.gave_up(), answer) << what;
      EXPECT_EQ(r.stopped, answer ? StopReason::kGaveUp : StopReason::kIterations) << what;
      EXPECT_EQ(r.stats.iterations, answer ? std::min(cap, 300) : cap) << what;
    }
  }
}

TEST(LegPlanner, TreeSizeCapStopsAndStillAsksTheQuestion) {
  const geometry::Scene scene = pocket_scene();
  const geometry::CSpace cspace(scene);
  const Pose2 from{1.5, 2.0, 0.0}, to{5.5, 2.0, 0.0};
  LegPlanner planner(scene, cspace);
  for (const int nodes : {1, 5, 40}) {
    int asked = 0;
    const LegResult r = planner.plan(from, to, 9, Termination{}.nodes(nodes).ask_after(300, [&] {
      ++asked;
      return false;
    }));
    EXPECT_FALSE(r.found);
    EXPECT_EQ(r.stopped, StopReason::kTreeFull) << nodes;
    EXPECT_GE(r.stats.tree_nodes, nodes);
    EXPECT_LT(r.stats.iterations, 300) << nodes;  // stopped by the tree, before the question's turn
    EXPECT_EQ(asked, 1) << nodes;
  }
}

TEST(LegPlanner, CancellationStopsTheSearchAndNeverAsksTheQuestion) {
  const geometry::Scene scene = pocket_scene();
  const geometry::CSpace cspace(scene);
  const Pose2 from{1.5, 2.0, 0.0}, to{5.5, 2.0, 0.0};
  LegPlanner planner(scene, cspace);
  std::atomic<bool> cancel{true};
  int asked = 0;
  const Termination stop = Termination{}.cancelled_by(&cancel).ask_after(0, [&] {
    ++asked;
    return true;
  });
  LegResult r = planner.plan(from, to, 3, stop);
  EXPECT_EQ(r.stopped, StopReason::kCancelled);
  EXPECT_EQ(r.stats.iterations, 0);
  EXPECT_EQ(asked, 0);
  // Not raised: the same search runs to its cap, draw for draw as without a flag.
  cancel.store(false);
  r = planner.plan(from, to, 3, Termination{}.cancelled_by(&cancel).iterations(50));
  const LegResult plain = planner.plan(from, to, 3, Termination{}.iterations(50));
  EXPECT_EQ(r.stopped, StopReason::kIterations);
  EXPECT_EQ(r.stats.iterations, 50);
  EXPECT_EQ(r.stats.tree_nodes, plain.stats.tree_nodes);
  EXPECT_EQ(r.stats.collision_checks, plain.stats.collision_checks);
}

TEST(LegPlanner, EveryLegInAnEmptyRoomIsFoundAndValid) {
  const geometry::Scene scene = base_scene({{0, 0}, {5, 0}, {5, 4}, {0, 4}});
  const geometry::CSpace cspace(scene);
  const test_support::ReferenceChecker reference(scene);
  LegPlanner planner(scene, cspace);
  std::mt19937_64 rng(13);
  for (int i = 0; i < 60; ++i) {
    const Pose2 from = test_support::random_free_pose(scene, cspace, rng);
    const Pose2 to = test_support::random_free_pose(scene, cspace, rng);
    const LegResult r = planner.plan(from, to, i);
    EXPECT_TRUE(r.found) << i << ": " << from.x << "," << from.y << "," << from.theta << " -> "
                         << to.x << "," << to.y << "," << to.theta;
    if (r.found) {
      test_support::expect_valid_path(reference, from, to, r.path, scene.wheelchair.turning_radius,
                                      "empty room leg " + std::to_string(i));
    }
  }
}
TEST(TourPlanner, ImpossibleTourEndsWithinTheCaps) {
  geometry::Scene scene = enclosed_goal_scene();
  geometry::Object target = box("target", 0.4, 0.4, {3.5, 3.5, 0.0});
  scene.objects.push_back(target);
  const geometry::CSpace cspace(scene);
  TourPlanner planner(scene, cspace, {}, 5);
  ASSERT_FALSE(planner.goals_for("door").empty());
  ASSERT_FALSE(planner.goals_for("target").empty());
  const Tour t = planner.plan({"door", "target"});
  EXPECT_FALSE(t.found);
  EXPECT_TRUE(t.legs.empty());
  EXPECT_LE(t.stats.legs_planned, planner.options().max_leg_plans);
  EXPECT_EQ(t.stats.legs_failed, t.stats.legs_planned);
  std::printf("[unsolvable] tour door->target: %d legs planned, %.1f ms\n", t.stats.legs_planned,
              t.stats.time_ms);
}
TEST(LegPlanner, SameSeedSamePathAndThreadsDoNotMatter) {
  const auto files = test_support::planning_scene_files();
  ASSERT_FALSE(files.empty());
  const geometry::Scene scene = geometry::load_scene(files.front());
  const geometry::CSpace cspace(scene);
  std::mt19937_64 rng(21);
  std::vector<std::pair<Pose2, Pose2>> queries;
  for (int i = 0; i < 24; ++i)
    queries.emplace_back(test_support::random_free_pose(scene, cspace, rng),
                         test_support::random_free_pose(scene, cspace, rng));
  auto run = [&](int first, int step, std::vector<LegResult>& out) {
    LegPlanner planner(scene, cspace);
    for (int i = first; i < static_cast<int>(queries.size()); i += step)
      out[i] = planner.plan(queries[i].first, queries[i].second, 100 + i);
  };
  std::vector<LegResult> seq(queries.size()), par(queries.size());
  run(0, 1, seq);
  std::thread t1([&] { run(0, 2, par); });
  std::thread t2([&] { run(1, 2, par); });
  t1.join();
  t2.join();
  int found = 0;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    EXPECT_EQ(seq[i].found, par[i].found);
    EXPECT_EQ(seq[i].stats.iterations, par[i].stats.iterations);
    EXPECT_EQ(seq[i].path.segments, par[i].path.segments);
    found += seq[i].found;
  }
  EXPECT_GT(found, 0);
  // A different seed explores differently (iteration counts differ somewhere).
  LegPlanner planner(scene, cspace);
  int differ = 0;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const LegResult r = planner.plan(queries[i].first, queries[i].second, 999 + i);
    differ +=
        r.stats.iterations != seq[i].stats.iterations || r.path.segments != seq[i].path.segments;
  }
  EXPECT_GT(differ, 0);
}

}  // namespace
}  // namespace hrs::planning
