// SPDX-License-Identifier: GPL-3.0-or-later
// Tours (slow): in every scene, sequences drawn from the AO graph are toured
// and every found tour is checked: legs join exactly, the first starts at the
// door, every stop is one of the object's goal poses, faces the object's
// centre and lies on an allowed side; paths are free by the exact reference;
// waypoints and metrics agree with the paths. Also the JSON shapes of
// docs/design-notes.md "Output shapes" and determinism from the seed.

#include <gtest/gtest.h>

#include <cstdio>
#include <nlohmann/json.hpp>
#include <random>

#include "geometry/cspace.h"
#include "geometry/scene.h"
#include "planning/goals.h"
#include "planning/tour.h"
#include "planning/tour_json.h"
#include "tests/support/paths.h"

namespace hrs::planning {
namespace {

using geometry::Pose2;

//! A random walk on the AO graph from the door (self-transitions skipped).
std::vector<std::string> random_sequence(const geometry::Scene& scene, int visits,
                                         std::mt19937_64& rng) {
  std::vector<std::string> seq{"door"};
  while (static_cast<int>(seq.size()) <= visits) {
    const auto row = scene.activity.transitions.find(seq.back());
    std::vector<std::string> next;
    if (row != scene.activity.transitions.end())
      for (const auto& [id, p] : row->second)
        if (id != seq.back() && p > 0 && id != "door") next.push_back(id);
    if (next.empty())
      for (const auto& o : scene.objects)
        if (o.id != seq.back()) next.push_back(o.id);
    seq.push_back(next[rng() % next.size()]);
  }
  return seq;
}

TEST(TourPlanner, FoundToursJoinStopFacingObjectsOnAllowedSidesAndAreFree) {
  const auto files = test_support::planning_scene_files();
  ASSERT_FALSE(files.empty());
  int found_anywhere = 0;
  for (const std::string& file : files) {
    const geometry::Scene scene = geometry::load_scene(file);
    const geometry::CSpace cspace(scene);
    const test_support::ReferenceChecker reference(scene);
    const double radius = scene.wheelchair.turning_radius;
    std::mt19937_64 rng(99);
    int found = 0, total = 0;
    double time_ms = 0;
    for (int k = 0; k < 12; ++k) {
      const auto seq = random_sequence(scene, scene.activity.visits, rng);
      TourPlanner planner(scene, cspace, {}, 40 + k);
      const Tour tour = planner.plan(seq);
      ++total;
      time_ms += tour.stats.time_ms;
      EXPECT_EQ(tour.sequence, seq);
      EXPECT_LE(tour.stats.legs_planned, planner.options().max_leg_plans);
      if (!tour.found) {
        EXPECT_TRUE(tour.legs.empty());
        continue;
      }
      ++found;
      ASSERT_EQ(tour.legs.size(), seq.size() - 1) << file;
      EXPECT_EQ(tour.legs.front().from, geometry::door_start_pose(scene)) << file;
      double length = 0, rotation = 0;
      for (std::size_t i = 0; i < tour.legs.size(); ++i) {
        const Leg& leg = tour.legs[i];
        const std::string what = scene.name + " " + leg.from_id + "->" + leg.to_id;
        EXPECT_EQ(leg.from_id, seq[i]);
        EXPECT_EQ(leg.to_id, seq[i + 1]);
        if (i > 0) {
          EXPECT_EQ(leg.from, tour.legs[i - 1].to) << what;  // joins exactly
        }
        // The stop is one of the object's goal poses, facing its centre.
        const int obj = scene.find_object(leg.to_id);
        ASSERT_GE(obj, 0);
        const geometry::Object& o = scene.objects[obj];
        const auto goals = planner.goals_for(leg.to_id);
        EXPECT_TRUE(std::any_of(goals.begin(), goals.end(), [&](const GoalPose& g) {
          return g.pose == leg.to;
        })) << what;
        const geometry::Vec2 d = o.pose.position() - leg.to.position();
        EXPECT_NEAR(geometry::wrap_angle(std::atan2(d.y, d.x) - leg.to.theta), 0.0, 1e-9) << what;
        const auto approach = o.approach_or_default();
        EXPECT_TRUE(approach.sides[static_cast<int>(side_of(o, o.pose, leg.to.position()))])
            << what;
        test_support::expect_valid_path(reference, leg.from, leg.to, leg.path, radius, what);
        // Waypoints: from `from` to `to`, at most 5 cm apart.
        ASSERT_FALSE(leg.waypoints.empty());
        EXPECT_LE(test_support::pose_error(leg.waypoints.front(), leg.from), 1e-12) << what;
        EXPECT_LE(test_support::pose_error(leg.waypoints.back(), leg.to), 1e-6) << what;
        for (std::size_t w = 1; w < leg.waypoints.size(); ++w) {
          EXPECT_LE(geometry::norm(leg.waypoints[w].position() - leg.waypoints[w - 1].position()),
                    kWaypointStep + 1e-9)
              << what;
          rotation +=
              std::abs(geometry::wrap_angle(leg.waypoints[w].theta - leg.waypoints[w - 1].theta));
        }
        length += leg.path.length();
      }
      EXPECT_NEAR(tour.metrics.length, length, 1e-9);
      EXPECT_NEAR(tour.metrics.rotation, rotation, 1e-9);
      EXPECT_GT(tour.metrics.clearance, 0.0);
      EXPECT_GE(tour.metrics.clearance, tour.metrics.min_clearance);
    }
    std::printf("[tours] %-20s %2d/%2d found, mean %.1f ms per tour\n", scene.name.c_str(), found,
                total, time_ms / total);
    found_anywhere += found;
  }
  // The initial bedroom layouts leave the bed without a reachable goal pose
  // (the optimizer's job); the other scenes must give checkable tours.
  EXPECT_GE(found_anywhere, 12);
}

//! Two planners with one seed give the same tour, and its JSON has the
//! design's shapes; checked on a tour that is found, so that the
//! comparisons cover legs.
void expect_same_tour_and_json(const geometry::Scene& scene, const geometry::CSpace& cspace,
                               const std::vector<std::string>& seq, const Tour& ta) {
  TourPlanner b(scene, cspace, {}, 7);
  const Tour tb = b.plan(seq);
  ASSERT_TRUE(tb.found);
  ASSERT_EQ(ta.legs.size(), tb.legs.size());
  ASSERT_FALSE(ta.legs.empty());
  for (std::size_t i = 0; i < ta.legs.size(); ++i) {
    EXPECT_EQ(ta.legs[i].path.segments, tb.legs[i].path.segments);
    EXPECT_EQ(ta.legs[i].to, tb.legs[i].to);
  }
  const auto j = nlohmann::json::parse(tours_json({ta}, {0.25}));
  const auto& t = j.at("tours").at(0);
  EXPECT_EQ(t.at("sequence").get<std::vector<std::string>>(), seq);
  EXPECT_EQ(t.at("likelihood").get<double>(), 0.25);
  EXPECT_TRUE(t.at("found").get<bool>());
  for (const char* m : {"length", "rotation", "clearance"})
    EXPECT_TRUE(t.at("metrics").contains(m));
  ASSERT_EQ(t.at("legs").size(), ta.legs.size());
  const auto& leg = t.at("legs").at(0);
  EXPECT_EQ(leg.at("from").size(), 3u);
  EXPECT_EQ(leg.at("to").size(), 3u);
  EXPECT_FALSE(leg.at("waypoints").empty());
  ASSERT_FALSE(leg.at("segments").empty());
  for (const auto& s : leg.at("segments")) {
    const std::string steer = s.at("steer");
    EXPECT_TRUE(steer == "L" || steer == "S" || steer == "R");
    EXPECT_TRUE(s.at("gear") == 1 || s.at("gear") == -1);
    EXPECT_GE(s.at("length").get<double>(), 0.0);
  }
  // The `plan` object, for the tour's first leg.
  LegPlanner planner(scene, cspace);
  const Pose2 from = geometry::door_start_pose(scene);
  const Pose2 to = ta.legs.front().to;
  const LegResult r = planner.plan(from, to, 3);
  const auto p = nlohmann::json::parse(plan_json(from, to, r, scene.wheelchair.turning_radius));
  for (const char* f : {"found", "from", "to", "radius", "length", "segments", "waypoints",
                        "iterations", "time_ms"})
    EXPECT_TRUE(p.contains(f)) << f;
  EXPECT_EQ(p.at("found").get<bool>(), r.found);
  if (r.found) {
    EXPECT_NEAR(p.at("length").get<double>(), r.path.length(), 1e-12);
  }
}

TEST(TourPlanner, SameSeedSameTourAndJsonHasTheDesignShapes) {
  const auto files = test_support::planning_scene_files();
  ASSERT_FALSE(files.empty());
  // The first scene, in file order, whose seeded draw of three objects the
  // planner finds (the shipped bedroom's is not: its bed has no reachable
  // goal pose until a design moves it).
  for (const auto& file : files) {
    const geometry::Scene scene = geometry::load_scene(file);
    const geometry::CSpace cspace(scene);
    std::mt19937_64 rng(5);
    const auto seq = random_sequence(scene, 3, rng);
    TourPlanner a(scene, cspace, {}, 7);
    const Tour ta = a.plan(seq);
    if (!ta.found) continue;
    RecordProperty("scene", scene.name);
    expect_same_tour_and_json(scene, cspace, seq, ta);
    return;
  }
  FAIL() << "no scene's seeded tour of three objects was found";
}

}  // namespace
}  // namespace hrs::planning
