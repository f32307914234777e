// Fast planning suites: the kd-tree against a linear scan, the free prefix of
// the motion validator, goal poses around objects, unsolvable queries that
// must end within the caps, determinism and thread independence.

#include <gtest/gtest.h>

#include <cstdio>

#include <chrono>
#include <cmath>
#include <numbers>
#include <random>
#include <thread>

#include "geometry/cspace.h"
#include "geometry/scene.h"
#include "planning/goals.h"
#include "planning/leg_measures.h"
#include "planning/metrics.h"
#include "planning/motion_validator.h"
#include "planning/nearest.h"
#include "planning/path_ops.h"
#include "planning/reuse.h"
#include "planning/rrt.h"
#include "planning/tour.h"
#include "tests/planning/support.h"

namespace hrs::planning {
namespace {

using geometry::Pose2;
using geometry::Vec2;
using testing::unit01;

geometry::Object box(const std::string& id, double depth, double width, Pose2 pose) {
  geometry::Object o;
  o.id = id;
  o.size = std::array<double, 2>{depth, width};
  o.footprint = {{-depth / 2, -width / 2},
                 {depth / 2, -width / 2},
                 {depth / 2, width / 2},
                 {-depth / 2, width / 2}};
  o.pose = pose;
  return o;
}

geometry::Scene base_scene(geometry::Polygon room) {
  geometry::Scene s;
  s.name = "test";
  s.room.polygon = std::move(room);
  s.door = {{2.0, 0.0}, 0.9, 1.2, std::nullopt};
  s.wheelchair = {1.1, 0.65, 0.7};
  return s;
}

//! A 7 x 7 room whose middle (4.2 x 4.2) is fenced in by four pieces of furniture.
geometry::Scene enclosed_goal_scene() {
  geometry::Scene s = base_scene({{0, 0}, {7, 0}, {7, 7}, {0, 7}});
  s.objects = {box("south", 0.2, 4.6, {3.5, 1.3, std::numbers::pi / 2}),
               box("north", 0.2, 4.6, {3.5, 5.7, -std::numbers::pi / 2}),
               box("west", 0.2, 4.4, {1.3, 3.5, 0.0}), box("east", 0.2, 4.4, {5.7, 3.5, 0.0})};
  return s;
}

//! A 4 x 4 room with a 2 x 2 pocket behind a 0.4 m neck (the chair is 0.65 m wide).
geometry::Scene pocket_scene() {
  return base_scene({{0, 0},
                     {4, 0},
                     {4, 1.8},
                     {4.5, 1.8},
                     {4.5, 1.0},
                     {6.5, 1.0},
                     {6.5, 3.0},
                     {4.5, 3.0},
                     {4.5, 2.2},
                     {4, 2.2},
                     {4, 4},
                     {0, 4}});
}

TEST(PoseNearest, KdTreeMatchesLinearScanIncludingHeadingWrap) {
  std::mt19937_64 rng(7);
  PoseNearest tree(0.7);
  std::vector<Pose2> poses;
  for (int i = 0; i < 4000; ++i) {
    // Half the headings crowd around ±pi, where wrap-around matters.
    const double t = (i % 2) ? std::numbers::pi * (2 * unit01(rng) - 1)
                             : geometry::wrap_angle(std::numbers::pi + 0.3 * (2 * unit01(rng) - 1));
    poses.push_back({5 * unit01(rng), 4 * unit01(rng), t});
    tree.insert(poses.back(), 1000 + i);
  }
  std::vector<std::int32_t> got;
  for (int q = 0; q < 400; ++q) {
    const Pose2 query{5 * unit01(rng), 4 * unit01(rng),
                      (q % 2) ? 3.1 + 0.04 * unit01(rng) : -3.14 + 6.28 * unit01(rng)};
    const std::size_t k = 1 + q % 12;
    std::vector<std::pair<double, int>> all;
    for (int i = 0; i < static_cast<int>(poses.size()); ++i)
      all.emplace_back(tree.distance(query, poses[i]), i);
    std::sort(all.begin(), all.end());
    tree.nearest(query, k, got);
    ASSERT_EQ(got.size(), k);
    for (std::size_t j = 0; j < k; ++j) EXPECT_EQ(got[j], 1000 + all[j].second) << q << " " << j;
  }
}

// Removals prune whole subtrees once none of their poses is live: answers
// must still equal a linear scan over the live poses, through thousands of
// interleaved inserts, removals (some repeated, some of unknown ids) and
// queries, down to a tree with no live pose at all.
TEST(PoseNearest, RemovalsMatchLinearScanOverLivePoses) {
  std::mt19937_64 rng(11);
  PoseNearest tree(0.7);
  std::vector<Pose2> poses;
  std::vector<bool> live;
  std::vector<std::int32_t> got;
  int checked = 0;
  for (int step = 0; step < 12000; ++step) {
    const double u = unit01(rng);
    if (step < 6000 && u < 0.5) {
      poses.push_back({4 * unit01(rng), 4 * unit01(rng), std::numbers::pi * (2 * unit01(rng) - 1)});
      live.push_back(true);
      tree.insert(poses.back(), static_cast<std::int32_t>(poses.size() - 1));
    } else if (u < 0.8 && !poses.empty()) {
      // Remove the live pose nearest a random point (clusters of removals,
      // like the planner's goal attempts), or an id again, or an unknown id.
      const Pose2 at{4 * unit01(rng), 4 * unit01(rng), 0.0};
      int pick = -1;
      double best = 1e300;
      for (std::size_t i = 0; i < poses.size(); ++i)
        if (live[i] && tree.distance(at, poses[i]) < best)
          best = tree.distance(at, poses[i]), pick = static_cast<int>(i);
      if (pick >= 0) {
        tree.remove(pick);
        live[pick] = false;
        tree.remove(pick);  // removing twice changes nothing
      }
      tree.remove(static_cast<std::int32_t>(poses.size() + 5));
    } else {
      const Pose2 query{4 * unit01(rng), 4 * unit01(rng), std::numbers::pi * (2 * unit01(rng) - 1)};
      const std::size_t k = 1 + step % 10;
      std::vector<std::pair<double, int>> all;
      for (std::size_t i = 0; i < poses.size(); ++i)
        if (live[i]) all.emplace_back(tree.distance(query, poses[i]), static_cast<int>(i));
      std::sort(all.begin(), all.end());
      tree.nearest(query, k, got);
      ASSERT_EQ(got.size(), std::min(k, all.size())) << step;
      for (std::size_t j = 0; j < got.size(); ++j) ASSERT_EQ(got[j], all[j].second) << step;
      ++checked;
    }
  }
  EXPECT_GT(checked, 2000);
  EXPECT_EQ(std::count(live.begin(), live.end(), true), 0);  // drained to empty
}

TEST(PoseNearest, DistanceWrapsHeading) {
  PoseNearest n(0.5);
  EXPECT_NEAR(n.distance({0, 0, 3.1}, {0, 0, -3.1}), 0.5 * (2 * std::numbers::pi - 6.2), 1e-12);
  EXPECT_NEAR(n.distance({0, 0, 0}, {3, 4, 0}), 5.0, 1e-12);
}

TEST(PathOps, SubpathPiecesConcatenateToThePath) {
  rs::Path p{
      {{rs::Steer::kLeft, 1, 0.7}, {rs::Steer::kStraight, -1, 1.2}, {rs::Steer::kRight, 1, 0.4}},
      0.7};
  rs::Path joined{{}, 0.7};
  for (double s = 0; s < p.length(); s += 0.33)
    for (const auto& seg : subpath(p, s, std::min(s + 0.33, p.length())).segments)
      append_segment(joined.segments, seg);
  ASSERT_EQ(joined.segments.size(), p.segments.size());
  for (std::size_t i = 0; i < p.segments.size(); ++i) {
    EXPECT_EQ(joined.segments[i].steer, p.segments[i].steer);
    EXPECT_EQ(joined.segments[i].gear, p.segments[i].gear);
    EXPECT_NEAR(joined.segments[i].length, p.segments[i].length, 1e-12);
  }
}

TEST(MotionValidator, FreePrefixIsFreeAndStopsAtABlockedPiece) {
  for (const std::string& file : testing::planning_scene_files()) {
    const geometry::Scene scene = geometry::load_scene(file);
    const geometry::CSpace cspace(scene);
    const double r = scene.wheelchair.turning_radius;
    MotionValidator v(cspace, r);
    const testing::ReferenceChecker reference(scene);
    std::mt19937_64 rng(3);
    int blocked = 0;
    for (int i = 0; i < 100; ++i) {
      const Pose2 a = testing::random_free_pose(scene, cspace, rng);
      const Pose2 b = testing::random_free_pose(scene, cspace, rng);
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

// The re-certification of found tours (optimize::recheck_tour) bisects a
// piece the continuous check cannot certify. It may certify more than the
// plain 5 cm cut, never a motion the exact reference finds blocked.
TEST(MotionValidator, CertifiedPrefixCertifiesMoreButNothingBlocked) {
  int refined = 0, blocked = 0;
  for (const std::string& file : testing::planning_scene_files()) {
    const geometry::Scene scene = geometry::load_scene(file);
    const geometry::CSpace cspace(scene);
    const double r = scene.wheelchair.turning_radius;
    MotionValidator v(cspace, r);
    const testing::ReferenceChecker reference(scene);
    std::mt19937_64 rng(8);
    for (int i = 0; i < 120; ++i) {
      const Pose2 a = testing::random_free_pose(scene, cspace, rng);
      const Pose2 b = testing::random_free_pose(scene, cspace, rng);
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
  for (const std::string& file : testing::planning_scene_files()) {
    geometry::Scene scene = geometry::load_scene(file);
    geometry::CSpace cspace(scene);
    const double r = scene.wheelchair.turning_radius;
    LegMeasures measures(cspace, r);
    MotionValidator validator(cspace, r);
    std::mt19937_64 rng(31);
    const int n = static_cast<int>(scene.objects.size());
    std::vector<Leg> legs(24);
    auto new_path = [&](Leg& leg) {
      leg.from = testing::random_free_pose(scene, cspace, rng);
      leg.path = rs::shortest_path(leg.from, testing::random_free_pose(scene, cspace, rng), r);
    };
    for (std::size_t i = 0; i < legs.size(); ++i) {
      legs[i].key = LegKey{static_cast<int>(i) % (n + 1) - 1, static_cast<int>(i / 2), 0, 0};
      new_path(legs[i]);
    }
    std::vector<std::pair<int, Pose2>> undo;
    for (int step = 0; step < 150; ++step) {
      const double action = testing::unit01(rng);
      if (action < 0.3) {  // move an object anywhere in the room
        const int k = static_cast<int>(rng() % static_cast<std::uint64_t>(n));
        undo.emplace_back(k, cspace.object_pose(k));
        cspace.move_object(k, testing::random_pose(scene, rng));
      } else if (action < 0.5) {  // nudge an object, as the annealer does
        const int k = static_cast<int>(rng() % static_cast<std::uint64_t>(n));
        Pose2 p = cspace.object_pose(k);
        undo.emplace_back(k, p);
        p.x += 0.3 * (2 * testing::unit01(rng) - 1);
        p.y += 0.3 * (2 * testing::unit01(rng) - 1);
        p.theta = geometry::wrap_angle(p.theta + 0.3 * (2 * testing::unit01(rng) - 1));
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
        const PathMetrics fresh = measure(cspace, waypoints, leg.path.length());
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

TEST(GoalPoses, FaceTheCentreLieOnAllowedSidesAtTheGapAndAreFree) {
  for (const std::string& file : testing::planning_scene_files()) {
    const geometry::Scene scene = geometry::load_scene(file);
    const geometry::CSpace cspace(scene);
    const testing::ExactReference reference(scene);
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
      const geometry::Object& o = scene.objects[i];
      const auto goals = goal_poses(scene, o, o.pose, cspace);
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
    const auto t0 = std::chrono::steady_clock::now();
    const LegResult r = planner.plan(c.from, c.to, 11);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_FALSE(r.found) << c.name;
    EXPECT_TRUE(r.stats.iterations == opt.max_iterations || r.stats.tree_nodes >= opt.max_nodes)
        << c.name;
    EXPECT_LT(s, 20.0) << c.name;
    std::printf("[unsolvable] %s: %d iterations, %d nodes, %llu checks, %.1f ms\n", c.name,
                r.stats.iterations, r.stats.tree_nodes,
                static_cast<unsigned long long>(r.stats.collision_checks), r.stats.time_ms);
  }
}

TEST(LegPlanner, EveryLegInAnEmptyRoomIsFoundAndValid) {
  const geometry::Scene scene = base_scene({{0, 0}, {5, 0}, {5, 4}, {0, 4}});
  const geometry::CSpace cspace(scene);
  const testing::ReferenceChecker reference(scene);
  LegPlanner planner(scene, cspace);
  std::mt19937_64 rng(13);
  for (int i = 0; i < 60; ++i) {
    const Pose2 from = testing::random_free_pose(scene, cspace, rng);
    const Pose2 to = testing::random_free_pose(scene, cspace, rng);
    const LegResult r = planner.plan(from, to, i);
    EXPECT_TRUE(r.found) << i << ": " << from.x << "," << from.y << "," << from.theta << " -> "
                         << to.x << "," << to.y << "," << to.theta;
    if (r.found) {
      testing::expect_valid_path(reference, from, to, r.path, scene.wheelchair.turning_radius,
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
  const auto files = testing::planning_scene_files();
  ASSERT_FALSE(files.empty());
  const geometry::Scene scene = geometry::load_scene(files.front());
  const geometry::CSpace cspace(scene);
  std::mt19937_64 rng(21);
  std::vector<std::pair<Pose2, Pose2>> queries;
  for (int i = 0; i < 24; ++i)
    queries.emplace_back(testing::random_free_pose(scene, cspace, rng),
                         testing::random_free_pose(scene, cspace, rng));
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

// shorten_path (the proposed planner's shortcuts): on RRT legs of every
// scene the result ends where the leg ends, is never longer, and is free by
// the exact reference every 1 mm; and it shortens most detours.
TEST(ShortenPath, SameEndsNeverLongerAndFreeByTheReference) {
  int legs = 0, shorter = 0;
  double before = 0, after = 0;
  for (const std::string& file : testing::planning_scene_files()) {
    const geometry::Scene scene = geometry::load_scene(file);
    const geometry::CSpace cspace(scene);
    const double r = scene.wheelchair.turning_radius;
    const testing::ReferenceChecker reference(scene);
    LegPlanner planner(scene, cspace);
    MotionValidator v(cspace, r);
    std::mt19937_64 rng(21);
    for (int i = 0; i < 40; ++i) {
      const Pose2 a = testing::random_free_pose(scene, cspace, rng);
      const Pose2 b = testing::random_free_pose(scene, cspace, rng);
      const LegResult leg = planner.plan(a, b, 100 + i);
      if (!leg.found) continue;
      ++legs;
      const rs::Path p = shorten_path(a, leg.path, v, 0.25);
      const Pose2 end = final_pose(a, p);
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
