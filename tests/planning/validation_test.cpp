// SPDX-License-Identifier: GPL-3.0-or-later
// Continuous checks of paths (free prefix, certified prefix), kept leg
// measurements against fresh ones, and path shortcuts, each against the
// exact reference.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "geometry/cspace.h"
#include "geometry/random.h"
#include "geometry/scene.h"
#include "planning/leg_measures.h"
#include "planning/metrics.h"
#include "planning/motion_validator.h"
#include "planning/path_ops.h"
#include "planning/path_shortening.h"
#include "planning/rrt.h"
#include "tests/support/paths.h"

namespace hrs::planning {
namespace {

using geometry::Pose2;
using hrs::uniform01;
using namespace hrs::test_support;

TEST(MotionValidator, FreePrefixIsFreeAndStopsAtABlockedPiece) {
  for (const std::string& file : test_support::planning_scene_files()) {
    const geometry::Scene scene = geometry::load_scene(file);
    const geometry::CSpace cspace(scene);
    const double r = scene.wheelchair.turning_radius;
    MotionValidator v(cspace, r);
    const test_support::ReferenceChecker reference(scene);
    std::mt19937_64 rng(3);
    int blocked = 0;
    for (int i = 0; i < 100; ++i) {
      const Pose2 a = test_support::random_free_pose(scene, cspace, rng);
      const Pose2 b = test_support::random_free_pose(scene, cspace, rng);
      const rs::Path path = rs::shortest_path(a, b, r);
      const double s = v.free_prefix(a, path, 0.1);
      ASSERT_LE(s, path.length() + 1e-12);
      // Whole free implies every piece free (the converse may fail: shorter
      // arcs get tighter conservative covers).
      if (v.path_free(a, path)) {
        EXPECT_GE(s, path.length() - 1e-9) << file;
      }
      if (s < path.length() - 1e-9) ++blocked;
      // The prefix is free by the exact reference, poses every 1 mm.
      for (const Pose2& q : rs::sample(a, subpath(path, 0, s), 0.001)) {
        if (!reference.pose_free(q)) {
          ADD_FAILURE() << file << ": prefix pose in collision " << q.x << "," << q.y << ","
                        << q.theta;
          break;
        }
      }
    }
    EXPECT_GT(blocked, 0) << file << ": no blocked path among 100: the test checks nothing";
  }
}
// The re-certification of found tours (planning::recheck_tour) bisects a
// piece the continuous check cannot certify. It may certify more than the
// plain 5 cm cut, never a motion the exact reference finds blocked.
TEST(MotionValidator, CertifiedPrefixCertifiesMoreButNothingBlocked) {
  int refined = 0, blocked = 0;
  for (const std::string& file : test_support::planning_scene_files()) {
    const geometry::Scene scene = geometry::load_scene(file);
    const geometry::CSpace cspace(scene);
    const double r = scene.wheelchair.turning_radius;
    MotionValidator v(cspace, r);
    const test_support::ReferenceChecker reference(scene);
    std::mt19937_64 rng(8);
    for (int i = 0; i < 120; ++i) {
      const Pose2 a = test_support::random_free_pose(scene, cspace, rng);
      const Pose2 b = test_support::random_free_pose(scene, cspace, rng);
      const rs::Path path = rs::shortest_path(a, b, r);
      const double plain = v.free_prefix(a, path, 0.05);
      const double certified = v.certified_prefix(a, path, 0.05);
      ASSERT_GE(certified, plain - 1e-12) << file;
      ASSERT_LE(certified, path.length() + 1e-12) << file;
      if (certified > plain + 1e-12) ++refined;
      if (certified < path.length() - 1e-9) ++blocked;
      // The certified prefix is free by the exact reference, every 1 mm.
      for (const Pose2& q : rs::sample(a, subpath(path, 0, certified), 0.001)) {
        if (!reference.pose_free(q)) {
          ADD_FAILURE() << file << ": certified pose in collision " << q.x << "," << q.y << ","
                        << q.theta;
          break;
        }
      }
    }
  }
  EXPECT_GT(blocked, 0) << "no blocked path: the test checks nothing";
  std::printf("certified_prefix went past free_prefix on %d paths, %d paths blocked\n", refined,
              blocked);
}
// LegMeasures (technique `metrics`) answers bit for bit what measuring afresh
// answers, across random object moves, moves undone, and legs whose path
// changed; every way of answering (stored, updated, afresh; a certification
// kept after moves out of reach) occurs.
TEST(LegMeasures, EqualToFreshMeasurementsAcrossRandomMoves) {
  LegMeasures::Counters total;
  long cases = 0;
  for (const std::string& file : test_support::planning_scene_files()) {
    geometry::Scene scene = geometry::load_scene(file);
    geometry::CSpace cspace(scene);
    const double r = scene.wheelchair.turning_radius;
    LegMeasures measures(scene, cspace, r, scene.weights.clearance_width);
    MotionValidator validator(cspace, r);
    std::mt19937_64 rng(31);
    const int n = static_cast<int>(scene.objects.size());
    std::vector<Leg> legs(24);
    auto new_path = [&](Leg& leg) {
      leg.from = test_support::random_free_pose(scene, cspace, rng);
      leg.path = rs::shortest_path(leg.from, test_support::random_free_pose(scene, cspace, rng), r);
    };
    for (std::size_t i = 0; i < legs.size(); ++i) {
      legs[i].key = LegKey{static_cast<int>(i) % (n + 1) - 1, static_cast<int>(i / 2), 0, 0};
      new_path(legs[i]);
    }
    std::vector<std::pair<int, Pose2>> undo;
    for (int step = 0; step < 150; ++step) {
      const double action = uniform01(rng);
      if (action < 0.3) {  // move an object anywhere in the room
        const int k = static_cast<int>(rng() % static_cast<std::uint64_t>(n));
        undo.emplace_back(k, cspace.object_pose(k));
        cspace.move_object(k, test_support::random_pose(scene, rng));
      } else if (action < 0.5) {  // nudge an object, as the annealer does
        const int k = static_cast<int>(rng() % static_cast<std::uint64_t>(n));
        Pose2 p = cspace.object_pose(k);
        undo.emplace_back(k, p);
        p.x += 0.3 * (2 * uniform01(rng) - 1);
        p.y += 0.3 * (2 * uniform01(rng) - 1);
        p.theta = geometry::wrap_angle(p.theta + 0.3 * (2 * uniform01(rng) - 1));
        cspace.move_object(k, p);
      } else if (action < 0.7 && !undo.empty()) {  // a rejected move: back to the old pose
        cspace.move_object(undo.back().first, undo.back().second);
        undo.pop_back();
      } else if (action < 0.85) {  // a leg served by another path now
        new_path(legs[rng() % legs.size()]);
      }
      for (int q = 0; q < 8; ++q, ++cases) {
        Leg& leg = legs[rng() % legs.size()];
        measures.measure(leg, kWaypointStep);
        const std::vector<Pose2> waypoints = waypoints_of(leg.from, leg.path, kWaypointStep);
        const PathMetrics fresh = measure(cspace, waypoints, leg.path.length(), scene.weights.clearance_width);
        ASSERT_EQ(leg.waypoints, waypoints) << file << " step " << step;
        ASSERT_EQ(leg.metrics.length, fresh.length);
        ASSERT_EQ(leg.metrics.rotation, fresh.rotation);
        ASSERT_EQ(leg.metrics.clearance, fresh.clearance) << file << " step " << step;
        ASSERT_EQ(leg.metrics.min_clearance, fresh.min_clearance) << file << " step " << step;
        ASSERT_EQ(leg.metrics.clearance_deficit, fresh.clearance_deficit);
        ASSERT_EQ(leg.metrics.waypoints, fresh.waypoints);
        ASSERT_EQ(measures.certified_prefix(leg, 0.05),
                  validator.certified_prefix(leg.from, leg.path, 0.05))
            << file << " step " << step;
      }
    }
    const LegMeasures::Counters c = measures.counters();
    total.metrics_same += c.metrics_same;
    total.metrics_updated += c.metrics_updated;
    total.metrics_fresh += c.metrics_fresh;
    total.certified_same += c.certified_same;
    total.certified_kept += c.certified_kept;
    total.certified_fresh += c.certified_fresh;
  }
  EXPECT_GT(total.metrics_same, 100u);
  EXPECT_GT(total.metrics_updated, 1000u);
  EXPECT_GT(total.metrics_fresh, 100u);
  EXPECT_GT(total.certified_same, 100u);
  EXPECT_GT(total.certified_kept, 300u);
  EXPECT_GT(total.certified_fresh, 300u);
  std::printf(
      "%ld legs measured: metrics stored %lu, updated %lu, afresh %lu; certified stored "
      "%lu, kept after moves out of reach %lu, afresh %lu\n",
      cases, static_cast<unsigned long>(total.metrics_same),
      static_cast<unsigned long>(total.metrics_updated),
      static_cast<unsigned long>(total.metrics_fresh),
      static_cast<unsigned long>(total.certified_same),
      static_cast<unsigned long>(total.certified_kept),
      static_cast<unsigned long>(total.certified_fresh));
}
// shorten_path (the proposed planner's shortcuts): on RRT legs of every
// scene the result ends where the leg ends, is never longer, and is free by
// the exact reference every 1 mm; and it shortens most detours.
TEST(ShortenPath, SameEndsNeverLongerAndFreeByTheReference) {
  int legs = 0, shorter = 0;
  double before = 0, after = 0;
  for (const std::string& file : test_support::planning_scene_files()) {
    const geometry::Scene scene = geometry::load_scene(file);
    const geometry::CSpace cspace(scene);
    const double r = scene.wheelchair.turning_radius;
    const test_support::ReferenceChecker reference(scene);
    LegPlanner planner(scene, cspace);
    MotionValidator v(cspace, r);
    std::mt19937_64 rng(21);
    for (int i = 0; i < 40; ++i) {
      const Pose2 a = test_support::random_free_pose(scene, cspace, rng);
      const Pose2 b = test_support::random_free_pose(scene, cspace, rng);
      const LegResult leg = planner.plan(a, b, 100 + i);
      if (!leg.found) continue;
      ++legs;
      const rs::Path p = shorten_path(a, leg.path, v, 0.25);
      const Pose2 end = rs::end_pose(a, p);
      ASSERT_LT(std::hypot(end.x - b.x, end.y - b.y), 1e-6) << file;
      ASSERT_LT(std::abs(geometry::wrap_angle(end.theta - b.theta)), 1e-6) << file;
      ASSERT_LE(p.length(), leg.path.length() + 1e-9) << file;
      before += leg.path.length();
      after += p.length();
      if (p.length() < leg.path.length() - 1e-3) ++shorter;
      for (const Pose2& q : rs::sample(a, p, 0.001)) {
        if (!reference.pose_free(q)) {
          ADD_FAILURE() << file << ": shortened path in collision at " << q.x << "," << q.y;
          break;
        }
      }
    }
  }
  EXPECT_GT(legs, 100);
  EXPECT_GT(shorter, legs / 4) << "shortcuts shortened almost nothing";
  std::printf("shorten_path: %d of %d legs shorter, total length %.1f m -> %.1f m\n", shorter, legs,
              before, after);
}

}  // namespace
}  // namespace hrs::planning
