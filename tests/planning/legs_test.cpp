// SPDX-License-Identifier: GPL-3.0-or-later
// Leg planner over hundreds of random queries in every scene of scenes/
// (slow). Every returned path starts and ends at the requested poses, is made
// of RS segments of the scene's radius, its length is the sum of its segments,
// and it is collision free by the exact reference (poses every 1 mm). Also
// prints the success rate and per-leg times on 200 object-to-object legs per
// scene (goal poses around two different objects).

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <random>

#include "geometry/cspace.h"
#include "geometry/scene.h"
#include "planning/goals.h"
#include "planning/rrt.h"
#include "planning/tour.h"
#include "tests/support/paths.h"

namespace hrs::planning {
namespace {

using geometry::Pose2;

struct Summary {
  int queries = 0, found = 0;
  std::vector<double> times_ms;
  std::size_t poses_checked = 0;
  void print(const char* what, const std::string& scene) const {
    std::vector<double> t = times_ms;
    std::sort(t.begin(), t.end());
    const double mean =
        std::accumulate(t.begin(), t.end(), 0.0) / std::max<std::size_t>(1, t.size());
    std::printf(
        "[%s] %-20s %3d/%3d found (%.1f%%), time ms: mean %.2f, median %.2f, p95 %.2f, max %.2f"
        " (%zu reference poses)\n",
        what, scene.c_str(), found, queries, 100.0 * found / std::max(1, queries), mean,
        t.empty() ? 0 : t[t.size() / 2], t.empty() ? 0 : t[t.size() * 95 / 100],
        t.empty() ? 0 : t.back(), poses_checked);
  }
};

std::string scene_name(const std::string& file) {
  return std::filesystem::path(file).stem().string();
}

TEST(LegPlanner, RandomLegsAreValidPathsInEveryScene) {
  const auto files = test_support::planning_scene_files();
  ASSERT_FALSE(files.empty());
  for (const std::string& file : files) {
    const geometry::Scene scene = geometry::load_scene(file);
    const geometry::CSpace cspace(scene);
    const test_support::ReferenceChecker reference(scene);
    const double radius = scene.wheelchair.turning_radius;
    LegPlanner planner(scene, cspace);
    std::mt19937_64 rng(2024);
    Summary sum;
    for (int i = 0; i < 200; ++i) {
      const Pose2 from = test_support::random_free_pose(scene, cspace, rng);
      const Pose2 to = test_support::random_free_pose(scene, cspace, rng);
      const LegResult r = planner.plan(from, to, 1000 + i);
      ++sum.queries;
      sum.times_ms.push_back(r.stats.time_ms);
      EXPECT_LE(r.stats.iterations, planner.options().max_iterations);
      if (!r.found) continue;
      ++sum.found;
      sum.poses_checked += test_support::expect_valid_path(
          reference, from, to, r.path, radius, scene_name(file) + " leg " + std::to_string(i));
    }
    sum.print("random legs", scene_name(file));
    // Random poses may lie in pockets no path reaches (measured 47 % solved
    // in the small bedroom, 95-98 % elsewhere); a broken planner falls below.
    EXPECT_GE(sum.found, sum.queries / 4) << file;
  }
}

TEST(LegPlanner, ObjectToObjectLegsSuccessAndTime) {
  const auto files = test_support::planning_scene_files();
  ASSERT_FALSE(files.empty());
  for (const std::string& file : files) {
    const geometry::Scene scene = geometry::load_scene(file);
    const geometry::CSpace cspace(scene);
    const test_support::ReferenceChecker reference(scene);
    const double radius = scene.wheelchair.turning_radius;
    std::vector<std::vector<GoalPose>> goals;
    std::vector<int> usable;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
      goals.push_back(goal_poses(scene, scene.objects[i], scene.objects[i].pose, cspace));
      if (!goals.back().empty()) usable.push_back(static_cast<int>(i));
    }
    ASSERT_GE(usable.size(), 2u) << file;
    LegPlanner planner(scene, cspace);
    std::mt19937_64 rng(77);
    Summary sum;
    for (int i = 0; i < 200; ++i) {
      const int a = usable[rng() % usable.size()];
      int b = a;
      while (b == a) b = usable[rng() % usable.size()];
      const Pose2 from = goals[a][rng() % goals[a].size()].pose;
      const Pose2 to = goals[b][rng() % goals[b].size()].pose;
      const LegResult r = planner.plan(from, to, 5000 + i);
      ++sum.queries;
      sum.times_ms.push_back(r.stats.time_ms);
      if (!r.found) continue;
      ++sum.found;
      sum.poses_checked += test_support::expect_valid_path(
          reference, from, to, r.path, radius,
          scene_name(file) + " " + scene.objects[a].id + "->" + scene.objects[b].id);
    }
    sum.print("object legs", scene_name(file));
    // The initial bedrooms are cramped (measured 16-30 % solved); others 89 %+.
    EXPECT_GT(sum.found, 0) << file;
  }
}

}  // namespace
}  // namespace hrs::planning
