// SPDX-License-Identifier: GPL-3.0-or-later
// The final polish (optimize/polish.h): on scrambled shipped rooms with a
// stand-in planner, kept moves raise the score and never lose a tour; on
// built rooms, group turns, nudges, turns in place, exchanges and
// rearrangements where each is the only move that meets a preference, and
// the cost rule of exchanges (the evictions' tests:
// polish_eviction_test.cpp; the squaring's: polish_squaring_test.cpp).
// The tests of suite PolishSweep
// (many rooms or seeds) run as their own ctest entry, labelled slow.

#include "optimize/polish.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>

#include "geometry/polygon_ops.h"
#include "optimize/design.h"
#include "optimize/preferences.h"
#include "optimize/sequences.h"
#include "optimize/tour_proxy.h"
#include "planning/goals.h"
#include "polish_support.h"
#include "scramble.h"

namespace hrs::optimize {
namespace {

using geometry::Pose2;
using geometry::Vec2;

using testing::bounded_model;
using testing::exact_hooks;
using testing::movable_of;
using testing::poses_of;
using testing::polish_all_found;
using testing::two_tours_found;
using testing::violation_at;
// The polish's score (optimize/polish.cpp), recomputed here from the report.
const auto polish_gross = testing::gross_count;
const auto polish_score = testing::score_of;

// polish() against hooks that stand in for the planner: a planned layout
// "loses a tour" on a pseudo-random third of the layouts (a hash of the
// poses), so the test sees both outcomes. On four shipped rooms with 100
// scrambled starting layouts each: the result is valid, it scores at least
// the input, a kept move always raised the score and never lost a tour, the
// objects placed through the hooks end where the returned poses say (every
// rejected move was put back), and the count of plannings stays within the
// cap.
TEST(PolishSweep, KeepsOnlyHigherScoringLayoutsThatLoseNoTour) {
  int kept = 0, slid = 0, swapped = 0, evicted = 0, rearranged = 0, turned = 0, rejected = 0,
      layouts = 0;
  for (const char* file : {"bedroom.json", "office.json", "living_room.json", "l_studio.json"}) {
    const geometry::Scene scene =
        geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/scenes/" + file);
    const CostModel model = bounded_model(scene);
    const std::vector<bool> movable = movable_of(scene);
    for (std::uint64_t seed = 1; seed <= 100; ++seed) {
      const geometry::Scene work = testing::scrambled(scene, movable, seed);
      std::vector<Pose2> poses = poses_of(work);
      ASSERT_EQ(layout_violation(work), "") << file << " seed " << seed;
      std::vector<Pose2> placed = poses;  // what place() was told
      PolishHooks hooks;
      geometry::Scene scratch = work;
      hooks.valid = [&](const std::vector<Pose2>& p, int moved) {
        for (std::size_t i = 0; i < p.size(); ++i) scratch.objects[i].pose = p[i];
        return object_violation(scratch, moved).empty();
      };
      hooks.place = [&](int o, const Pose2& to) { placed[static_cast<std::size_t>(o)] = to; };
      int planned = 0;
      bool lost_kept = false;
      CostTerms last;
      hooks.plan = [&](const std::vector<Pose2>& p) {
        ++planned;
        EXPECT_EQ(p, placed) << "plan() of a layout other than the placed one";
        last.tours_total = 10;
        last.tours_found = testing::layout_hash(p, seed) % 3 == 0 ? 9 : 10;
        if (last.tours_found < 10) ++rejected;
        return last;
      };
      hooks.kept = [&] { lost_kept = lost_kept || last.tours_found < 10; };
      CostTerms terms;
      terms.tours_total = terms.tours_found = 10;
      const PreferenceReport input = check_preferences(scene, model, poses);
      const int before = polish_score(input), gross_before = polish_gross(input);
      const int cap = 30;
      const PolishResult r = polish(scene, model, movable, poses, terms, hooks, cap);
      const std::string what = std::string(file) + " seed " + std::to_string(seed);
      const PreferenceReport output = check_preferences(scene, model, poses);
      const int after = polish_score(output);
      EXPECT_GE(after, before) << what;
      // A kept move raises the score, or (an eviction) keeps it and mends
      // a gross angle miss.
      if (r.kept + r.turned > 0) {
        EXPECT_TRUE(after > before ||
                    (r.evicted + r.rearranged > 0 && polish_gross(output) < gross_before))
            << what;
      }
      EXPECT_FALSE(lost_kept) << what;
      EXPECT_EQ(terms.tours_found, 10) << what;
      EXPECT_EQ(placed, poses) << what;
      EXPECT_EQ(planned, r.tried) << what;
      EXPECT_LE(r.tried, cap + 8) << what;  // the rearrangement's own eight
      geometry::Scene out = work;
      EXPECT_EQ(violation_at(out, poses), "") << what;
      kept += r.kept;
      slid += r.slid;
      swapped += r.swapped;
      evicted += r.evicted;
      rearranged += r.rearranged;
      turned += r.turned;
      ++layouts;
    }
  }
  std::printf(
      "%d layouts: %d moves kept (%d slid along a wall, %d exchanges, %d evictions, %d "
      "rearrangements), %d groups turned, %d planned layouts lost a tour\n",
      layouts, kept, slid, swapped, evicted, rearranged, turned, rejected);
  // The situations the test is about occurred.
  EXPECT_GT(kept, 200);
  EXPECT_GT(slid, 0);
  EXPECT_GT(evicted, 0);
  EXPECT_GT(rejected, 10);
}

// Three benches packed side by side (a turn other than a half turn makes
// one hit its neighbour), linked by relation angles 0 to each other and the
// first by π to a fixed lamp. No single bench's turn, nor a bench's with one
// partner, raises the score: each half turn meets one relation and breaks
// another. The group's half turn meets all three; the polish finds it.
TEST(Polish, TurnsAGroupLinkedByRelationAnglesAsOneBody) {
  const geometry::Scene scene = geometry::parse_scene(R"({
    "format": "hrspace-scene/1", "name": "benches",
    "room": {"size": [6, 4]},
    "door": {"center": [5.0, 0.0], "width": 0.9, "clear_depth": 0.3},
    "wheelchair": {"length": 1.1, "width": 0.65, "turning_radius": 0.7},
    "objects": [
      {"id": "a", "size": [0.4, 2.0], "pose": [2.0, 2.0, 0]},
      {"id": "b", "size": [0.4, 2.0], "pose": [2.45, 2.0, 0]},
      {"id": "c", "size": [0.4, 2.0], "pose": [2.9, 2.0, 0]},
      {"id": "lamp", "size": [0.3, 0.3], "pose": [5.0, 3.5, 0], "fixed": true}
    ],
    "relations": [{"a": "a", "b": "b", "angle": 0}, {"a": "b", "b": "c", "angle": 0},
                  {"a": "a", "b": "lamp", "angle": 3.141592653589793}],
    "activity": {"transitions": {"door": {"a": 1.0}, "a": {"c": 1.0}, "c": {"a": 1.0}},
                 "sequences": 2, "visits": 2}
  })", "benches");
  const CostModel model = bounded_model(scene);
  const std::vector<bool> movable{true, true, true, false};
  std::vector<Pose2> poses = poses_of(scene);
  const PreferenceReport before = check_preferences(scene, model, poses);
  ASSERT_EQ(before.total, 3);
  ASSERT_EQ(before.met, 2);
  geometry::Scene scratch = scene;
  PolishHooks hooks;
  hooks.valid = [&](const std::vector<Pose2>& p, int moved) {
    for (std::size_t i = 0; i < p.size(); ++i) scratch.objects[i].pose = p[i];
    return object_violation(scratch, moved).empty();
  };
  hooks.place = [](int, const Pose2&) {};
  hooks.plan = [](const std::vector<Pose2>&) {
    CostTerms t;
    t.tours_total = t.tours_found = 2;
    return t;
  };
  hooks.kept = [] {};
  CostTerms terms;
  terms.tours_total = terms.tours_found = 2;
  const PolishResult r = polish(scene, model, movable, poses, terms, hooks, 50);
  EXPECT_EQ(r.kept, 0);  // no single move or pair raised the score
  EXPECT_EQ(r.turned, 1);
  const PreferenceReport after = check_preferences(scene, model, poses);
  EXPECT_EQ(after.met, 3);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(std::abs(geometry::wrap_angle(poses[static_cast<std::size_t>(i)].theta)),
                std::numbers::pi, 1e-9);
    EXPECT_EQ(poses[static_cast<std::size_t>(i)].position(), scene.objects[static_cast<std::size_t>(i)].pose.position());
  }
}

// Three square stools in a row, linked by relation angles 0; the first
// wants its wall angle towards the bottom wall, its nearest, and stands a
// quarter turn off it with the others turned as it is. Every relation
// angle is met, so only the wall angle is unmet: turning the first alone,
// or with one partner, breaks a relation by 90°. The group's quarter turn,
// anchored on the first's wall heading, meets all three.
TEST(Polish, TurnsAGroupAsOneBodyForAMembersWallAngle) {
  const geometry::Scene scene = geometry::parse_scene(R"({
    "format": "hrspace-scene/1", "name": "stools",
    "room": {"size": [6, 4]},
    "door": {"center": [5.0, 0.0], "width": 0.9, "clear_depth": 0.3},
    "wheelchair": {"length": 1.1, "width": 0.65, "turning_radius": 0.7},
    "objects": [
      {"id": "a", "size": [0.4, 0.4], "pose": [2.0, 1.3, 0], "wall": {"angle": 0}},
      {"id": "b", "size": [0.4, 0.4], "pose": [2.5, 1.3, 0]},
      {"id": "c", "size": [0.4, 0.4], "pose": [3.0, 1.3, 0]}
    ],
    "relations": [{"a": "a", "b": "b", "angle": 0}, {"a": "b", "b": "c", "angle": 0}],
    "activity": {"transitions": {"door": {"a": 1.0}, "a": {"c": 1.0}, "c": {"a": 1.0}},
                 "sequences": 2, "visits": 2}
  })", "stools");
  const CostModel model = bounded_model(scene);
  const std::vector<bool> movable{true, true, true};
  std::vector<Pose2> poses = poses_of(scene);
  const PreferenceReport before = check_preferences(scene, model, poses);
  ASSERT_EQ(before.total, 3);
  ASSERT_EQ(before.met, 2);
  ASSERT_NEAR(before.worst_angle, std::numbers::pi / 2, 1e-9);
  geometry::Scene scratch = scene;
  const PolishResult r = polish_all_found(scene, model, movable, poses, scratch);
  EXPECT_EQ(r.turned, 1);
  EXPECT_EQ(r.kept, 0);
  const PreferenceReport after = check_preferences(scene, model, poses);
  EXPECT_EQ(after.met, 3);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(geometry::wrap_angle(poses[static_cast<std::size_t>(i)].theta - std::numbers::pi / 2),
                0.0, 1e-9);
    EXPECT_EQ(poses[static_cast<std::size_t>(i)].position(),
              scene.objects[static_cast<std::size_t>(i)].pose.position());
  }
}

//! Two desks of one size: `far` wants to stand 0.75 m from a fixed lamp in
//! a corner, and `near`, which wants nothing, holds the only place there.
geometry::Scene desks_scene() {
  return geometry::parse_scene(R"({
    "format": "hrspace-scene/1", "name": "desks",
    "room": {"size": [6, 4]},
    "door": {"center": [5.0, 0.0], "width": 0.9, "clear_depth": 0.3},
    "wheelchair": {"length": 1.1, "width": 0.65, "turning_radius": 0.7},
    "objects": [
      {"id": "lamp", "size": [0.3, 0.3], "pose": [0.3, 3.7, 0], "fixed": true},
      {"id": "near", "size": [0.6, 1.0], "pose": [1.0, 3.5, 0]},
      {"id": "far", "size": [0.6, 1.0], "pose": [4.5, 2.0, 0]}
    ],
    "relations": [{"a": "far", "b": "lamp", "distance": 0.75}],
    "activity": {"transitions": {"door": {"near": 1.0}, "near": {"far": 1.0}, "far": {"near": 1.0}},
                 "sequences": 2, "visits": 2}
  })", "desks");
}

// A bench along the wall wants a quarter turn to a fixed lamp. Turned in
// place it crosses the wall (it wants no wall, and nothing else moves). The
// polish nudges it off the wall, by at most 30 cm, and keeps it: the
// single-object pass does, since it nudges every preferred pose that does
// not fit (before, only the group turn did).
TEST(Polish, AnObjectThatNoLongerFitsOnceTurnedIsNudged) {
  const geometry::Scene scene = geometry::parse_scene(R"({
    "format": "hrspace-scene/1", "name": "bench",
    "room": {"size": [6, 4]},
    "door": {"center": [5.0, 0.0], "width": 0.9, "clear_depth": 0.3},
    "wheelchair": {"length": 1.1, "width": 0.65, "turning_radius": 0.7},
    "objects": [
      {"id": "bench", "size": [1.0, 0.5], "pose": [3.0, 0.3, 0]},
      {"id": "lamp", "size": [0.3, 0.3], "pose": [0.5, 3.5, 0], "fixed": true}
    ],
    "relations": [{"a": "bench", "b": "lamp", "angle": 1.5707963267948966}],
    "activity": {"transitions": {"door": {"bench": 1.0}, "bench": {"lamp": 1.0}, "lamp": {"bench": 1.0}},
                 "sequences": 2, "visits": 2}
  })", "bench");
  const CostModel model = bounded_model(scene);
  const std::vector<bool> movable{true, false};
  std::vector<Pose2> poses = poses_of(scene);
  ASSERT_EQ(check_preferences(scene, model, poses).met, 0);
  // Turned in place, the bench leaves the room.
  geometry::Scene turned = scene;
  turned.objects[0].pose.theta = std::numbers::pi / 2;
  ASSERT_NE(object_violation(turned, 0), "");
  geometry::Scene scratch = scene;
  const PolishResult r = polish_all_found(scene, model, movable, poses, scratch);
  EXPECT_EQ(r.kept, 1);
  EXPECT_EQ(r.turned, 0);
  EXPECT_EQ(check_preferences(scene, model, poses).met, 1);
  const double moved = std::hypot(poses[0].x - 3.0, poses[0].y - 0.3);
  EXPECT_GT(moved, 0.0);
  EXPECT_LE(moved, 0.3 + 1e-9);
  geometry::Scene out = scene;
  out.objects[0].pose = poses[0];
  EXPECT_EQ(layout_violation(out), "");
}


// A bed in the room's middle faces its nearest wall (the bottom one) side on
// (90° off its wall angle), and fixed shelves 0.5 m deep line the walls
// but for the door and its corner, too small for the bed, so no pose at its
// wall distance is free, not even nudged by 30 cm, and
// nothing else moves. Turned in place to the heading the bottom wall asks
// for, it meets the angle and stays where it is (the distance stays unmet).
TEST(Polish, TurnsInPlaceWhereNoSpotAtItsWallIsFree) {
  const geometry::Scene scene = geometry::parse_scene(R"({
    "format": "hrspace-scene/1", "name": "lined",
    "room": {"size": [5, 4]},
    "door": {"center": [4.0, 0.0], "width": 0.9, "clear_depth": 0.3},
    "wheelchair": {"length": 1.1, "width": 0.65, "turning_radius": 0.7},
    "objects": [
      {"id": "bed", "size": [2.0, 1.4], "pose": [2.5, 1.9, 0], "wall": {"distance": 0, "angle": 0}},
      {"id": "bottom", "size": [3.5, 0.5], "pose": [1.75, 0.25, 0], "fixed": true},
      {"id": "top", "size": [5.0, 0.5], "pose": [2.5, 3.75, 0], "fixed": true},
      {"id": "left", "size": [0.5, 3.0], "pose": [0.25, 2.0, 0], "fixed": true},
      {"id": "right", "size": [0.5, 2.2], "pose": [4.75, 2.4, 0], "fixed": true}
    ],
    "activity": {"transitions": {"door": {"bed": 1.0}, "bed": {"top": 1.0}, "top": {"bed": 1.0}},
                 "sequences": 2, "visits": 2}
  })", "lined");
  ASSERT_EQ(layout_violation(scene), "");
  const CostModel model = bounded_model(scene);
  const std::vector<bool> movable{true, false, false, false, false};
  std::vector<Pose2> poses = poses_of(scene);
  const PreferenceReport before = check_preferences(scene, model, poses);
  ASSERT_EQ(before.total, 2);
  ASSERT_EQ(before.met, 0);
  ASSERT_NEAR(before.worst_angle, std::numbers::pi / 2, 1e-9);
  geometry::Scene scratch = scene;
  const PolishResult r = polish_all_found(scene, model, movable, poses, scratch);
  EXPECT_EQ(r.kept, 1);
  EXPECT_EQ(r.slid + r.swapped + r.turned, 0);
  EXPECT_EQ(poses[0].position(), scene.objects[0].pose.position());
  EXPECT_NEAR(geometry::wrap_angle(poses[0].theta), std::numbers::pi / 2, 1e-9);
  const PreferenceReport after = check_preferences(scene, model, poses);
  EXPECT_EQ(after.met, 1);
  EXPECT_NEAR(after.worst_angle, 0.0, 1e-9);
  EXPECT_EQ(violation_at(scratch, poses), "");
}


// desks_scene(): the pose that meets the relation (on the line to the
// lamp) overlaps `near`, and `far` has no wall to slide along; only
// exchanging the two desks meets it. The polish finds the exchange, and `near` ends where
// `far` stood.
TEST(Polish, ExchangesPlacesWhenTheWantedPlaceIsHeld) {
  const geometry::Scene scene = desks_scene();
  const CostModel model = bounded_model(scene);
  const std::vector<bool> movable{false, true, true};
  std::vector<Pose2> poses = poses_of(scene);
  ASSERT_EQ(check_preferences(scene, model, poses).met, 0);
  geometry::Scene scratch = scene;
  const PolishResult r = polish_all_found(scene, model, movable, poses, scratch);
  EXPECT_EQ(r.swapped, 1);
  EXPECT_EQ(r.slid, 0);
  EXPECT_EQ(check_preferences(scene, model, poses).met, 1);
  EXPECT_NEAR(geometry::norm(poses[2].position() - Vec2{1.0, 3.5}), 0.0, 1e-9);
  EXPECT_NEAR(geometry::norm(poses[1].position() - Vec2{4.5, 2.0}), 0.0, 1e-9);
  EXPECT_EQ(violation_at(scratch, poses), "");
}

// The same room, but the planner stands in for one whose tours through the
// exchanged desks are longer: the exchange meets the relation, but costs
// more, so it is not kept, and neither is the last pass's eviction nor a
// rearrangement for a higher score.
TEST(Polish, KeepsNoExchangeThatRaisesTheTotalCost) {
  const geometry::Scene scene = desks_scene();
  const CostModel model = bounded_model(scene);
  const std::vector<bool> movable{false, true, true};
  std::vector<Pose2> poses = poses_of(scene);
  const std::vector<Pose2> input = poses;
  geometry::Scene scratch = scene;
  PolishHooks hooks = exact_hooks(scratch);
  int planned = 0;
  hooks.plan = [&](const std::vector<Pose2>&) {
    ++planned;
    CostTerms t;
    t.tours_total = t.tours_found = 2;
    t.path_length = 5.0;  // longer than the input's
    return t;
  };
  CostTerms terms;
  terms.tours_total = terms.tours_found = 2;
  terms.path_length = 1.0;
  const PolishResult r = polish(scene, model, movable, poses, terms, hooks, 50);
  // `far` has no wall to slide along and its pose toward the lamp overlaps
  // `near`: the two exchanges with `near` (back to back and reference
  // points, the same here) are planned once per pass; then the last pass
  // plans two evictions of `near` from that pose, refused at the higher
  // cost too; before those, the rearrangement for a higher score plans
  // one layout per chain at most (8), refused at the higher cost as well.
  EXPECT_GE(planned, 6 + 1);
  EXPECT_LE(planned, 6 + 8);
  EXPECT_EQ(r.tried, planned);
  EXPECT_EQ(r.swapped, 0);
  EXPECT_EQ(r.evicted, 0);
  EXPECT_EQ(r.rearranged, 0);
  EXPECT_EQ(poses, input);
}

// A desk on the top wall must share the fixed wardrobe's heading (relation
// angle 0), so it belongs on the bottom wall, whose only free span a bed
// holds, side by side with a dresser and a nightstand that want to stand
// beside it with its heading (relations with distance and angle 0). The desk
// there overlaps one or two of the three; moving those away (an eviction)
// leaves the third turned from the moved bed, or the bed turned from both,
// and exchanging places turns the bed round: no move of one to three objects
// that the earlier stages make lowers the count of gross misses. The
// rearrangement does: the bed to another wall, its dresser and nightstand
// after it, the desk to the bottom wall.
geometry::Scene shared_wall_scene() {
  return geometry::parse_scene(R"({
    "format": "hrspace-scene/1", "name": "shared wall",
    "room": {"size": [6, 4]},
    "door": {"center": [5.0, 4.0], "width": 0.9, "clear_depth": 0.3},
    "wheelchair": {"length": 1.1, "width": 0.65, "turning_radius": 0.7},
    "objects": [
      {"id": "wardrobe", "size": [0.6, 1.2], "pose": [0.9, 0.3, 1.5707963267948966], "fixed": true},
      {"id": "bed", "size": [2.0, 1.4], "pose": [3.0, 1.0, 1.5707963267948966],
       "wall": {"distance": 0, "angle": 0}},
      {"id": "dresser", "size": [0.5, 0.8], "pose": [1.9, 0.25, 1.5707963267948966],
       "wall": {"distance": 0, "angle": 0}},
      {"id": "desk", "size": [0.6, 1.2], "pose": [2.0, 3.7, -1.5707963267948966],
       "wall": {"distance": 0, "angle": 0}},
      {"id": "nightstand", "size": [0.4, 0.4], "pose": [3.9, 0.2, 1.5707963267948966],
       "wall": {"distance": 0, "angle": 0}},
      {"id": "shelf", "size": [0.5, 1.9], "pose": [5.05, 0.25, 1.5707963267948966], "fixed": true}
    ],
    "relations": [{"a": "desk", "b": "wardrobe", "angle": 0},
                  {"a": "bed", "b": "dresser", "distance": 1.3314, "angle": 0},
                  {"a": "bed", "b": "nightstand", "distance": 1.2042, "angle": 0}],
    "activity": {"transitions": {"door": {"bed": 1.0}, "bed": {"desk": 1.0}, "desk": {"bed": 1.0}},
                 "sequences": 2, "visits": 2}
  })", "shared wall");
}

TEST(PolishSweep, RearrangesSeveralObjectsWhenNoSingleMoveMendsAGrossAngleMiss) {
  const geometry::Scene scene = shared_wall_scene();
  ASSERT_EQ(layout_violation(scene), "");
  const CostModel model = bounded_model(scene);
  const std::vector<bool> movable = movable_of(scene);
  std::vector<Pose2> poses = poses_of(scene);
  const PreferenceReport before = check_preferences(scene, model, poses);
  ASSERT_EQ(polish_gross(before), 1);  // the desk's heading against the wardrobe's
  ASSERT_EQ(before.met, before.total - 1);
  // The chains are seeded (PolishHooks::seed): over 10 seeds, nothing but
  // the rearrangement is kept, and where it is, the desk stands on the
  // bottom wall with no gross miss left, in a valid layout, after one
  // planning per chain at most.
  int rearranged = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    std::vector<Pose2> p = poses;
    geometry::Scene scratch = scene;
    PolishHooks hooks = exact_hooks(scratch);
    hooks.seed = seed;
    int planned = 0;
    hooks.plan = [&](const std::vector<Pose2>&) {
      ++planned;
      return two_tours_found();
    };
    CostTerms terms = two_tours_found();
    const PolishResult r = polish(scene, model, movable, p, terms, hooks, 50);
    const std::string what = "seed " + std::to_string(seed);
    EXPECT_EQ(r.slid + r.swapped + r.evicted + r.turned, 0) << what;
    EXPECT_EQ(planned, r.tried) << what;
    const PreferenceReport after = check_preferences(scene, model, p);
    if (r.rearranged == 0) {
      EXPECT_EQ(p, poses) << what;
      continue;
    }
    ++rearranged;
    EXPECT_EQ(r.rearranged, 1) << what;
    EXPECT_EQ(r.kept, 1) << what;  // the rearrangement alone
    EXPECT_EQ(polish_gross(after), 0) << what;
    EXPECT_GE(polish_score(after), polish_score(before)) << what;
    EXPECT_NEAR(geometry::wrap_angle(p[3].theta - std::numbers::pi / 2), 0.0, 1e-9) << what;
    EXPECT_NEAR(p[3].y, 0.3, 1e-9) << what;
    EXPECT_EQ(violation_at(scratch, p), "") << what;
  }
  std::printf("rearranged with %d of 10 seeds\n", rearranged);
  EXPECT_GE(rearranged, 9);  // 9 when this test was written
}

// The same room with a planner that loses a tour on every moved layout:
// the rearrangements are planned (one per chain at most) and refused.
TEST(Polish, KeepsNoRearrangementThatLosesATour) {
  const geometry::Scene scene = shared_wall_scene();
  const CostModel model = bounded_model(scene);
  const std::vector<bool> movable = movable_of(scene);
  std::vector<Pose2> poses = poses_of(scene);
  const std::vector<Pose2> input = poses;
  geometry::Scene scratch = scene;
  PolishHooks hooks = exact_hooks(scratch);
  hooks.seed = 1;
  int planned = 0;
  hooks.plan = [&](const std::vector<Pose2>&) {
    ++planned;
    CostTerms t = two_tours_found();
    t.tours_found = 1;
    return t;
  };
  CostTerms terms = two_tours_found();
  const PolishResult r = polish(scene, model, movable, poses, terms, hooks, 50);
  EXPECT_GE(planned, 1);
  EXPECT_LE(planned, 8);  // one per chain
  EXPECT_EQ(r.kept + r.rearranged, 0);
  EXPECT_EQ(poses, input);
  EXPECT_EQ(terms.tours_found, 2);
}

// The shorter-tour rearrangement on the shipped rooms, with a stand-in
// planner whose path cost is the tour proxy itself: a layout with the same
// score and shorter tours is kept, at a lower total cost, and only then;
// with a planner whose cost never falls, nothing is kept by it, and it
// plans at most one layout per chain and round; with a tour unfound it
// does not run.
TEST(Polish, KeepsAShorterTourLayoutOnlyAtALowerCost) {
  int shortened = 0;
  for (const char* file : {"bedroom.json", "office.json", "living_room.json"}) {
    const geometry::Scene scene =
        geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/scenes/" + file);
    const CostModel model = bounded_model(scene);
    std::vector<std::vector<planning::GoalPose>> local;
    for (const auto& o : scene.objects) local.push_back(planning::local_goal_poses(scene, o));
    const TourProxy proxy(scene, model, local);
    const std::vector<bool> movable = movable_of(scene);
    for (const bool falls : {true, false}) {
      const std::string what = std::string(file) + (falls ? " (proxy cost)" : " (constant cost)");
      std::vector<Pose2> poses = poses_of(scene);
      const std::vector<Pose2> input = poses;
      const PreferenceReport before = check_preferences(scene, model, poses);
      geometry::Scene scratch = scene;
      PolishHooks hooks = exact_hooks(scratch);
      hooks.seed = 1;
      hooks.tour_proxy = [&](const std::vector<Pose2>& p) { return proxy.value(p); };
      const auto cost_of = [&](const std::vector<Pose2>& p) {
        CostTerms t = two_tours_found();
        t.path_length = falls ? proxy.value(p) : 10.0;
        return t;
      };
      int planned = 0;
      hooks.plan = [&](const std::vector<Pose2>& p) {
        ++planned;
        return cost_of(p);
      };
      CostTerms terms = cost_of(poses);
      const double cost0 = terms.total();
      // No planning budget for the other stages: only the rearrangements'
      // allowances plan.
      const PolishResult r = polish(scene, model, movable, poses, terms, hooks, 0);
      const PreferenceReport after = check_preferences(scene, model, poses);
      EXPECT_GE(after.met - testing::gross_count(after), before.met - testing::gross_count(before))
          << what;
      EXPECT_EQ(violation_at(scene, poses), "") << what;
      if (!falls) {
        EXPECT_EQ(r.shortened, 0) << what;
        EXPECT_EQ(terms.total(), cost0) << what;
        EXPECT_LE(planned, 8 + 8 + 8) << what;  // three goals' chains, one round each
        continue;
      }
      if (r.shortened > 0) {
        ++shortened;
        EXPECT_NE(poses, input) << what;
        EXPECT_LT(terms.total(), cost0) << what;
        EXPECT_DOUBLE_EQ(terms.total(), proxy.value(poses)) << what;
      }
      EXPECT_LE(r.shortened, 2) << what;  // kShorterRounds
    }
  }
  EXPECT_GE(shortened, 2);
  // With a tour unfound, the chains do not run: the proxy is never asked.
  const geometry::Scene scene =
      geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/scenes/bedroom.json");
  const CostModel model = bounded_model(scene);
  std::vector<Pose2> poses = poses_of(scene);
  geometry::Scene scratch = scene;
  PolishHooks hooks = exact_hooks(scratch);
  int asked = 0;
  hooks.tour_proxy = [&](const std::vector<Pose2>&) { return 1.0 / ++asked; };
  const auto one_of_two = [](const std::vector<Pose2>&) {
    CostTerms t = two_tours_found();
    t.tours_found = 1;
    t.unfound_penalty = 100.0;
    return t;
  };
  hooks.plan = one_of_two;
  CostTerms terms = one_of_two(poses);
  const PolishResult r = polish(scene, model, movable_of(scene), poses, terms, hooks, 0);
  EXPECT_EQ(r.shortened, 0);
  EXPECT_EQ(asked, 0);
}

}  // namespace
}  // namespace hrs::optimize
