// SPDX-License-Identifier: GPL-3.0-or-later
// ReachGate (planning/reach_gate.h) against the planner: in random layouts
// of the shipped scenes, a leg the baseline found (inside a tour, or alone
// between random free poses) is never refused, and every waypoint of a found
// path that starts in the door's reachable set stays in it (a collision-free
// path never leaves its component); tours planned with the gate equal tours
// planned without it. The gate follows the C-space's layout (after
// invalidate() it equals a fresh fill of a fresh grid). A sealed case: in
// scenes/l_studio.json's initial layout the door's pocket is walled off, so
// every leg from the door to the TV or the bed is refused, a long RRT finds
// none (from the door, whose pose is wedged, nor from the back of the dining
// table inside the pocket), and blockage() grades walled-off stops in
// [1/2, 1] and reachable ones 0.

#include "planning/reach_gate.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "geometry/cspace.h"
#include "geometry/free_grid.h"
#include "geometry/random.h"
#include "planning/rrt.h"
#include "planning/tour.h"
#include "tests/support/paths.h"

namespace hrs::planning {
namespace {

using geometry::Pose2;
using geometry::Scene;

//! Moves 1–2 movable objects of `work` and `cspace` together: a nudge, or
//! (one time in four) a relocation anywhere in the room's box with any
//! heading. Overlaps are allowed: the C-space and the gate take any layout,
//! and relocations are what wall parts of the room off.
void random_moves(Scene& work, geometry::CSpace& cspace, std::mt19937_64& rng) {
  std::vector<int> movable;
  for (std::size_t i = 0; i < work.objects.size(); ++i)
    if (!work.objects[i].fixed) movable.push_back(static_cast<int>(i));
  const int moves = 1 + static_cast<int>(rng() % 2);
  for (int m = 0; m < moves; ++m) {
    const int i = movable[rng() % movable.size()];
    Pose2 p = work.objects[i].pose;
    if (rng() % 4 == 0) {
      p = test_support::random_pose(work, rng);
    } else {
      p.x += 0.4 * (2 * uniform01(rng) - 1);
      p.y += 0.4 * (2 * uniform01(rng) - 1);
      p.theta = geometry::wrap_angle(p.theta + 0.5 * (2 * uniform01(rng) - 1));
    }
    work.objects[i].pose = p;
    cspace.move_object(i, p);
  }
}

//! "door" and three distinct random object ids.
std::vector<std::string> random_sequence(const Scene& scene, std::mt19937_64& rng) {
  std::vector<std::string> ids;
  for (const auto& o : scene.objects) ids.push_back(o.id);
  std::shuffle(ids.begin(), ids.end(), rng);
  std::vector<std::string> seq{std::string(geometry::kStartNodeId)};
  for (std::size_t i = 0; i < ids.size() && i < 3; ++i) seq.push_back(ids[i]);
  return seq;
}

struct Counts {
  int legs = 0;            //!< found legs checked
  int legs_in_door = 0;    //!< of which start in the door's reachable set
  int waypoints = 0;       //!< waypoints checked against the set
  int refused_pairs = 0;   //!< random pairs the gate refused (none found)
  int tours_found = 0, tours_unfound = 0;
};

//! The checks on one found path from `from` to `to`.
void check_found(const ReachGate& gate, const Pose2& from, const Pose2& to,
                 const std::vector<Pose2>& waypoints, const std::string& what, Counts& n) {
  ++n.legs;
  ASSERT_FALSE(gate.refuses(from, to)) << what << ": a found leg is refused";
  const geometry::ReachableSet* reach = gate.door_reach();
  ASSERT_NE(reach, nullptr) << what;
  if (!reach->contains(from)) {
    // A path never crosses between components either way.
    EXPECT_FALSE(reach->contains(to)) << what;
    return;
  }
  ++n.legs_in_door;
  for (const Pose2& w : waypoints) {
    ++n.waypoints;
    ASSERT_TRUE(reach->contains(w)) << what << ": waypoint (" << w.x << ", " << w.y << ", "
                                    << w.theta << ") leaves the door's reachable set";
  }
}

TEST(ReachGate, NeverRefusesAFoundLegAndFoundPathsStayInTheDoorsReachableSet) {
  Counts n;
  const std::vector<std::string> files{"bedroom.json", "office.json", "small_bedroom.json",
                                       "living_room.json", "narrow_passage.json",
                                       "crowded_living.json", "l_studio.json"};
  for (std::size_t f = 0; f < files.size(); ++f) {
    Scene work = test_support::shipped_scene(files[f]);
    geometry::CSpace cspace(work);
    ReachGate gate(work, cspace);
    TourPlanner plain(work, cspace, {}, 1);
    TourHooks gated_hooks;
    gated_hooks.gate = &gate;
    TourPlanner gated(work, cspace, {}, 1, gated_hooks);
    LegPlanner legs(work, cspace);
    std::mt19937_64 rng(700 + f);
    for (int layout = 0; layout < 5; ++layout) {
      if (layout > 0) {
        random_moves(work, cspace, rng);
        gate.invalidate();
      }
      const std::string where = files[f] + " layout " + std::to_string(layout);
      // Tours of random sequences, with and without the gate: the same tours.
      for (int t = 0; t < 2; ++t) {
        const auto seq = random_sequence(work, rng);
        const std::uint64_t seed = 1000 * f + 10 * layout + t;
        plain.set_seed(seed);
        gated.set_seed(seed);
        const Tour a = plain.plan(seq);
        const Tour b = gated.plan(seq);
        const std::string what = where + " tour " + std::to_string(t);
        ASSERT_EQ(a.found, b.found) << what << ": the gate changed the tour";
        ASSERT_EQ(a.legs.size(), b.legs.size()) << what;
        for (std::size_t i = 0; i < a.legs.size(); ++i) {
          EXPECT_EQ(a.legs[i].from, b.legs[i].from) << what;
          EXPECT_EQ(a.legs[i].to, b.legs[i].to) << what;
          EXPECT_EQ(a.legs[i].path.segments, b.legs[i].path.segments) << what;
        }
        EXPECT_EQ(a.stats.legs_failed, b.stats.legs_failed) << what;
        (a.found ? n.tours_found : n.tours_unfound) += 1;
        for (std::size_t i = 0; i < a.legs.size(); ++i)
          check_found(gate, a.legs[i].from, a.legs[i].to, a.legs[i].waypoints,
                      what + " leg " + std::to_string(i), n);
      }
      // Single legs: from the door to goal poses of random objects, and
      // between random free poses; paths walked every 1 cm.
      const TourPlanner& goals = plain;
      for (int i = 0; i < 6; ++i) {
        Pose2 from, to;
        if (i < 3) {
          from = geometry::door_start_pose(work);
          const auto g = goals.goals_for(work.objects[rng() % work.objects.size()].id);
          if (g.empty() || !cspace.is_free(from)) continue;
          to = g[rng() % g.size()].pose;
        } else {
          from = test_support::random_free_pose(work, cspace, rng);
          to = test_support::random_free_pose(work, cspace, rng);
        }
        const LegResult r = legs.plan(from, to, 50 + i);
        const std::string what = where + " single leg " + std::to_string(i);
        if (!r.found) {
          n.refused_pairs += gate.refuses(from, to) ? 1 : 0;
          continue;
        }
        check_found(gate, from, to, rs::sample(from, r.path, 0.01), what, n);
      }
    }
  }
  std::printf("found legs %d (%d from the door's set, %d waypoints); tours found %d, unfound %d; "
              "unfound single legs refused %d\n",
              n.legs, n.legs_in_door, n.waypoints, n.tours_found, n.tours_unfound,
              n.refused_pairs);
  EXPECT_GT(n.legs, 100);
  EXPECT_GT(n.legs_in_door, 80);
  EXPECT_GT(n.tours_found, 20);
  EXPECT_GT(n.refused_pairs, 0) << "the gate never refused a leg: the checks say little";
}

TEST(ReachGate, FollowsTheCSpacesLayoutAfterInvalidate) {
  // After moves and invalidate(), the door's reachable set is a fresh fill
  // of a fresh grid of the moved scene; without invalidate() it is kept.
  Scene work = test_support::shipped_scene("bedroom.json");
  geometry::CSpace cspace(work);
  ReachGate gate(work, cspace);
  std::mt19937_64 rng(31);
  const Pose2 door = geometry::door_start_pose(work);
  int differing = 0;
  for (int layout = 0; layout < 4; ++layout) {
    const geometry::ReachableSet* before = gate.door_reach();
    ASSERT_NE(before, nullptr);
    std::vector<char> was;
    std::vector<Pose2> probes;
    for (int i = 0; i < 20000; ++i) probes.push_back(test_support::random_pose(work, rng));
    for (const Pose2& p : probes) was.push_back(before->contains(p));
    random_moves(work, cspace, rng);
    // Not invalidated: the same answers.
    const geometry::ReachableSet* stale = gate.door_reach();
    for (std::size_t i = 0; i < probes.size(); ++i)
      ASSERT_EQ(stale->contains(probes[i]), was[i] != 0) << "layout " << layout;
    gate.invalidate();
    const geometry::FreeGrid grid(work, ReachGateOptions{}.grid);
    geometry::ReachableSet fresh;
    fresh.fill(grid, door);
    const geometry::ReachableSet* now = gate.door_reach();
    for (std::size_t i = 0; i < probes.size(); ++i) {
      ASSERT_EQ(now->contains(probes[i]), fresh.contains(probes[i])) << "layout " << layout;
      differing += now->contains(probes[i]) != (was[i] != 0);
      EXPECT_EQ(now->distance_to(probes[i]), fresh.distance_to(probes[i]));
    }
  }
  EXPECT_GT(differing, 0) << "the moves never changed the door's reachable set";
  EXPECT_EQ(gate.fills(), 5u);
}

TEST(ReachGate, SealedDoorOfTheLStudioRefusesTvAndBedAndNoLongRrtFindsThem) {
  const Scene scene = test_support::shipped_scene("l_studio.json");
  const geometry::CSpace cspace(scene);
  const ReachGate gate(scene, cspace);
  const TourPlanner tours(scene, cspace);
  const Pose2 door = geometry::door_start_pose(scene);
  ASSERT_TRUE(cspace.is_free(door));
  ASSERT_NE(gate.door_reach(), nullptr);
  EXPECT_TRUE(gate.door_reach()->contains(door));
  EXPECT_FALSE(gate.refuses(door, door));
  EXPECT_GT(gate.door_reach()->column_share(), 0.0);
  EXPECT_LT(gate.door_reach()->column_share(), 0.2) << "the door's pocket is small";
  for (const std::string id : {"tv", "bed"}) {
    const std::vector<GoalPose> goals = tours.goals_for(id);
    ASSERT_FALSE(goals.empty()) << id;
    for (const GoalPose& g : goals) {
      EXPECT_TRUE(gate.refuses(door, g.pose)) << id << " slot " << g.slot;
      EXPECT_TRUE(gate.refuses(g.pose, door)) << id << " slot " << g.slot;
    }
    const double b = gate.blockage(goals);
    EXPECT_GE(b, 0.5) << id;
    EXPECT_LE(b, 1.0) << id;
    std::printf("l_studio: blockage of %s %.4f (%zu goal poses)\n", id.c_str(), b, goals.size());
  }
  // The back of the dining table is inside the door's pocket.
  const std::vector<GoalPose> table = tours.goals_for("dining_table");
  EXPECT_TRUE(std::any_of(table.begin(), table.end(),
                          [&](const GoalPose& g) { return !gate.refuses(door, g.pose); }));
  EXPECT_EQ(gate.blockage(table), 0.0);
  EXPECT_EQ(gate.blockage({}), 1.0);

  // `hrspace plan`-style long RRTs from the door to the TV's and the bed's
  // nearest goal pose (by RS length) find nothing.
  PlannerOptions long_run;
  long_run.max_iterations = 20'000;
  long_run.max_nodes = 200'000;
  LegPlanner planner(scene, cspace, long_run);
  for (const std::string id : {"tv", "bed"}) {
    const std::vector<GoalPose> goals = tours.goals_for(id);
    const auto nearest = std::min_element(
        goals.begin(), goals.end(), [&](const GoalPose& a, const GoalPose& b) {
          return rs::shortest_length(door, a.pose, planner.radius()) <
                 rs::shortest_length(door, b.pose, planner.radius());
        });
    const LegResult r = planner.plan(door, nearest->pose, 20261123);
    EXPECT_FALSE(r.found) << "door -> " << id << " was found, yet refused";
    std::printf("l_studio: door -> %s: RRT of %d iterations, %d nodes, found %d\n", id.c_str(),
                r.stats.iterations, r.stats.tree_nodes, r.found ? 1 : 0);
    // The door's pose is wedged (the tree may not grow from it); a goal pose
    // of the dining table inside the door's reachable set is also refused
    // towards the TV or the bed, and no long RRT from it finds the leg.
    for (const GoalPose& t : table) {
      if (!gate.door_reach()->contains(t.pose)) continue;
      EXPECT_TRUE(gate.refuses(t.pose, nearest->pose)) << id;
      const LegResult from_table = planner.plan(t.pose, nearest->pose, 7);
      EXPECT_FALSE(from_table.found) << "dining table -> " << id << " was found, yet refused";
      std::printf("l_studio: dining table slot %d -> %s: RRT of %d iterations, %d nodes, found %d\n",
                  t.slot, id.c_str(), from_table.stats.iterations, from_table.stats.tree_nodes,
                  from_table.found ? 1 : 0);
      break;
    }
  }
}

TEST(ReachGate, BlockageIsZeroExactlyWhenTheDoorReachesAGoalAndElseInHalfToOne) {
  int zero = 0, graded = 0;
  for (const std::string file : {"bedroom.json", "l_studio.json", "crowded_living.json"}) {
    Scene work = test_support::shipped_scene(file);
    geometry::CSpace cspace(work);
    ReachGate gate(work, cspace);
    const TourPlanner tours(work, cspace);
    const geometry::Box box = geometry::bounding_box(work.room.polygon);
    const double diagonal = std::hypot(box.xmax - box.xmin, box.ymax - box.ymin);
    std::mt19937_64 rng(17);
    for (int layout = 0; layout < 25; ++layout) {
      if (layout > 0) {
        random_moves(work, cspace, rng);
        gate.invalidate();
      }
      const geometry::ReachableSet* reach = gate.door_reach();
      ASSERT_NE(reach, nullptr);
      for (const auto& o : work.objects) {
        const std::vector<GoalPose> goals = tours.goals_for(o.id);
        const double b = gate.blockage(goals);
        const std::string what = file + " layout " + std::to_string(layout) + " " + o.id;
        if (goals.empty()) {
          EXPECT_EQ(b, 1.0) << what;
          continue;
        }
        const bool reached = std::any_of(goals.begin(), goals.end(),
                                         [&](const GoalPose& g) { return reach->contains(g.pose); });
        if (reached) {
          EXPECT_EQ(b, 0.0) << what;
          ++zero;
          continue;
        }
        ++graded;
        EXPECT_GE(b, 0.5) << what;
        EXPECT_LE(b, 1.0) << what;
        double d = std::numeric_limits<double>::infinity();
        for (const GoalPose& g : goals) d = std::min(d, reach->distance_to(g.pose));
        EXPECT_NEAR(b, 0.5 + 0.5 * std::min(1.0, d / diagonal), 1e-12) << what;
      }
    }
  }
  std::printf("stops reached %d, graded %d\n", zero, graded);
  EXPECT_GT(zero, 50);
  EXPECT_GT(graded, 10);
}

}  // namespace
}  // namespace hrs::planning
