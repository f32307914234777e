// SPDX-License-Identifier: GPL-3.0-or-later
// The preference arrangement (optimize/arrange.h): the tour corridor and its
// count of blocked footprints against
// brute force (exact polygon overlap and segment distances) on thousands of
// random paths and objects, and arrangements of the shipped rooms that stay
// valid, lower the interior cost, leave stops and fixed objects in place
// and repeat for a seed; the layout checks' floating-point shortcuts
// against the exact predicates alone; the opening arrangement's pull
// against a direct sum.

#include "optimize/arrange.h"

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

namespace hrs::optimize {
namespace {

using geometry::Polygon;
using geometry::Pose2;
using geometry::Vec2;

double segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  const double l2 = d.x * d.x + d.y * d.y;
  const double t = l2 > 0.0 ? std::clamp(((p.x - a.x) * d.x + (p.y - a.y) * d.y) / l2, 0.0, 1.0) : 0.0;
  return std::hypot(p.x - (a.x + t * d.x), p.y - (a.y + t * d.y));
}

//! Distance between two polygons' boundaries (0 when their interiors overlap).
double polygon_gap(const Polygon& a, const Polygon& b) {
  if (geometry::interiors_overlap(a, b)) return 0.0;
  double best = 1e300;
  for (int pass = 0; pass < 2; ++pass) {
    const Polygon& p = pass == 0 ? a : b;
    const Polygon& q = pass == 0 ? b : a;
    for (const Vec2& v : p)
      for (std::size_t i = 0; i < q.size(); ++i)
        best = std::min(best, segment_distance(v, q[i], q[(i + 1) % q.size()]));
  }
  return best;
}

Polygon rectangle(const Pose2& pose, double length, double width) {
  geometry::Wheelchair box{length, width, 1.0};
  return geometry::chair_footprint(box, pose);
}

TEST(TourCorridor, AgreesWithBruteForceOnRandomPathsAndObjects) {
  std::mt19937_64 rng(20261126);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const geometry::Wheelchair chair{1.1, 0.65, 0.7};
  const double margin = 0.05;
  int blocked = 0, clear = 0, near = 0, several = 0;
  for (int c = 0; c < 3000; ++c) {
    // One found tour of two legs: straight runs with a turning heading.
    planning::Tour tour;
    tour.found = true;
    Pose2 w{6.0 * u(rng), 6.0 * u(rng), 2.0 * std::numbers::pi * u(rng)};
    for (int leg = 0; leg < 2; ++leg) {
      planning::Leg l;
      const double turn = (u(rng) - 0.5) * 0.2;
      const int steps = 1 + static_cast<int>(40 * u(rng));
      for (int s = 0; s < steps; ++s) {
        l.waypoints.push_back(w);
        w.x += 0.05 * std::cos(w.theta);
        w.y += 0.05 * std::sin(w.theta);
        w.theta += turn;
      }
      tour.legs.push_back(l);
    }
    const TourCorridor corridor(chair, {tour}, margin);
    // Random objects: rectangles and, every third case, an L-shaped footprint.
    for (int k = 0; k < 4; ++k) {
      const Pose2 at{8.0 * u(rng) - 1.0, 8.0 * u(rng) - 1.0, 2.0 * std::numbers::pi * u(rng)};
      Polygon object = rectangle(at, 0.2 + 1.8 * u(rng), 0.2 + 1.0 * u(rng));
      if (c % 3 == 0) {
        const double a = 0.3 + u(rng), b = 0.3 + u(rng);
        object.clear();
        for (const Vec2 v : {Vec2{0, 0}, Vec2{2 * a, 0}, Vec2{2 * a, b}, Vec2{a, b}, Vec2{a, 2 * b},
                             Vec2{0, 2 * b}})
          object.push_back(geometry::to_world(at, v));
      }
      double gap = 1e300;
      // Waypoints whose footprint the object comes within the margin of
      // (`touched`), and those a little farther (`fuzzy`), for blocked().
      std::size_t touched = 0, fuzzy = 0;
      for (const planning::Leg& l : tour.legs)
        for (const Pose2& p : l.waypoints) {
          const double g = polygon_gap(object, geometry::chair_footprint(chair, p));
          gap = std::min(gap, g);
          if (g <= margin) {
            ++touched;
          } else if (!(g > margin * std::numbers::sqrt2 + 1e-9 && c % 3 != 0)) {
            ++fuzzy;
          }
        }
      const bool ok = corridor.clear(object);
      // blocked() counts each footprint once, is 0 exactly when clear(), and
      // lies between the footprints surely within the margin and those
      // plus the ones near it.
      const std::size_t count = corridor.blocked(object);
      EXPECT_EQ(count == 0, ok) << "case " << c;
      EXPECT_GE(count, touched) << "case " << c;
      EXPECT_LE(count, touched + fuzzy) << "case " << c;
      if (touched > 1) ++several;
      // Sound: an object touching a chair footprint, or within the margin,
      // is never clear. Near-complete: one farther than the margin's
      // diagonal (separating axes are exact for overlap, conservative by at
      // most that for distances) and clear of the hull's extra area is clear.
      if (gap <= margin) {
        ++blocked;
        EXPECT_FALSE(ok) << "case " << c << " gap " << gap;
      } else if (gap > margin * std::numbers::sqrt2 + 1e-9 && c % 3 != 0) {
        ++clear;
        EXPECT_TRUE(ok) << "case " << c << " gap " << gap;
      } else {
        ++near;
      }
    }
  }
  EXPECT_GT(blocked, 1000);
  EXPECT_GT(clear, 1000);
  EXPECT_GT(near, 10);
  EXPECT_GT(several, 1000);
}

TEST(TourCorridor, UnfoundToursAndNoToursBlockNothing) {
  const geometry::Wheelchair chair{1.1, 0.65, 0.7};
  planning::Tour lost;
  lost.found = false;
  planning::Leg l;
  l.waypoints = {Pose2{1, 1, 0}};
  lost.legs.push_back(l);
  const TourCorridor corridor(chair, {lost});
  EXPECT_EQ(corridor.footprints(), 0u);
  EXPECT_TRUE(corridor.clear(rectangle(Pose2{1, 1, 0}, 1, 1)));
}

TEST(Arrange, ShippedRoomsStayValidLowerTheirInteriorCostAndRepeat) {
  for (const char* file : {"bedroom.json", "office.json", "living_room.json", "l_studio.json"}) {
    const geometry::Scene scene =
        geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/scenes/" + file);
    CostModel model(scene, scene_sequences(scene));
    model.set_bounded_preferences(true);
    std::vector<Pose2> input;
    std::vector<bool> movable;
    for (const auto& o : scene.objects) {
      input.push_back(o.pose);
      movable.push_back(!o.fixed);
    }
    // The first movable object stays, as a stop does in a design.
    for (std::size_t i = 0; i < movable.size(); ++i)
      if (movable[i]) {
        movable[i] = false;
        break;
      }
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
      geometry::Scene work = scene;
      int sets = 0;
      ArrangeHooks hooks;
      hooks.valid = [&](const std::vector<Pose2>& p, int moved) {
        const Pose2 old = work.objects[moved].pose;
        work.objects[moved].pose = p[moved];
        const bool ok = object_violation(work, moved).empty();
        work.objects[moved].pose = old;
        return ok;
      };
      hooks.set = [&](int o, const Pose2& to) {
        EXPECT_TRUE(movable[static_cast<std::size_t>(o)]) << file;
        work.objects[o].pose = to;
        ++sets;
      };
      hooks.preferred = [&](const std::vector<Pose2>& p, int o, std::mt19937_64& rng) {
        auto c = preferred_poses(scene, model, p, o);
        if (c.empty()) return std::optional<Pose2>();
        return std::optional<Pose2>(c[std::uniform_int_distribution<std::size_t>(0, c.size() - 1)(rng)]);
      };
      ArrangeOptions options;
      options.iterations_per_object = 60;
      AnnealOptions moves;
      const auto b = geometry::bounding_box(scene.room.polygon);
      moves.bounds = std::array<double, 4>{b.xmin, b.ymin, b.xmax, b.ymax};
      const ArrangeResult a = arrange(model, movable, input, moves, options, hooks, seed);
      const std::string what = std::string(file) + " seed " + std::to_string(seed);
      EXPECT_GT(sets, 0) << what;
      // The hooks' state is back at the input.
      for (std::size_t i = 0; i < input.size(); ++i) EXPECT_EQ(work.objects[i].pose, input[i]) << what;
      // Valid, not worse, unmoved where it must not move.
      geometry::Scene out = scene;
      for (std::size_t i = 0; i < input.size(); ++i) {
        out.objects[i].pose = a.poses[i];
        if (!movable[i]) {
          EXPECT_EQ(a.poses[i], input[i]) << what;
        }
      }
      EXPECT_EQ(layout_violation(out), "") << what;
      EXPECT_LE(a.interior_after, a.interior_before) << what;
      EXPECT_NEAR(a.interior_after, model.interior_terms(model.interior(a.poses)).total(), 1e-9)
          << what;
      // Same seed, same arrangement.
      const ArrangeResult again = arrange(model, movable, input, moves, options, hooks, seed);
      EXPECT_EQ(again.poses, a.poses) << what;
    }
  }
}

// The opening arrangement's pull (opening_pull) against a direct sum on
// 2000 random layouts of a rectangular room: kOpeningPull times each loose
// movable object's distance to the nearest wall, counted up to 1 m, where
// that distance is the least of the footprint's corners' distances to the
// four walls (exact for a convex footprint inside a rectangle). A fixed
// object and one with a wall distance preference add nothing.
TEST(OpeningPull, IsTheCappedWallDistanceOfTheLooseMovableObjects) {
  const geometry::Scene scene = geometry::parse_scene(R"({
    "format": "hrspace-scene/1", "name": "pull",
    "room": {"size": [5, 4]},
    "door": {"center": [2.5, 0.0], "width": 0.9, "clear_depth": 0.3},
    "wheelchair": {"length": 1.1, "width": 0.65, "turning_radius": 0.7},
    "objects": [
      {"id": "table", "size": [1.2, 0.8], "pose": [2.5, 2.0, 0.3]},
      {"id": "lamp", "size": [0.3, 0.3], "pose": [1.0, 1.0, 0.0], "wall": {"angle": 0.0}},
      {"id": "bed", "size": [2.0, 1.4], "pose": [3.5, 3.0, 0.0], "wall": {"distance": 0.0}},
      {"id": "stove", "size": [0.6, 0.6], "pose": [4.0, 1.0, 0.0], "fixed": true}
    ],
    "activity": {"transitions": {"door": {"table": 1.0}, "table": {"lamp": 1.0}, "lamp": {"table": 1.0}},
                 "sequences": 2, "visits": 2}
  })", "pull");
  CostModel model(scene, scene_sequences(scene));
  std::vector<bool> movable;
  for (const auto& o : scene.objects) movable.push_back(!o.fixed);
  const auto pull = opening_pull(scene, model, movable);
  ASSERT_TRUE(pull);
  std::mt19937_64 rng(20261129);
  std::uniform_real_distribution<double> x(0.0, 5.0), y(0.0, 4.0), a(-std::numbers::pi, std::numbers::pi);
  int checked = 0, capped = 0;
  while (checked < 2000) {
    std::vector<Pose2> poses;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) poses.push_back({x(rng), y(rng), a(rng)});
    double expected = 0.0;
    bool inside = true;
    for (const int i : {0, 1}) {  // table and lamp: no wall distance preference
      geometry::Object o = scene.objects[static_cast<std::size_t>(i)];
      o.pose = poses[static_cast<std::size_t>(i)];
      double d = 1e300;
      for (const Vec2& c : geometry::world_footprint(o)) {
        if (c.x < 0.0 || c.x > 5.0 || c.y < 0.0 || c.y > 4.0) inside = false;
        d = std::min({d, c.x, 5.0 - c.x, c.y, 4.0 - c.y});
      }
      if (d >= 1.0) ++capped;
      expected += kOpeningPull * std::min(1.0, d);
    }
    if (!inside) continue;
    ++checked;
    EXPECT_NEAR(pull(poses), expected, 1e-12) << checked;
  }
  EXPECT_GT(capped, 50);  // both sides of the cap are exercised
  // Against a wall, nothing; the cap, a quarter each.
  std::vector<Pose2> poses{{0.6, 2.0, 0.0}, {0.15, 1.0, 0.0}, {3.5, 3.0, 0.0}, {4.0, 1.0, 0.0}};
  EXPECT_NEAR(pull(poses), 0.0, 1e-12);
  poses[0] = {2.5, 2.0, 0.0};  // 1.6 m from the nearest wall
  poses[1] = {2.5, 1.0, 0.0};  // 0.85 m
  EXPECT_NEAR(pull(poses), kOpeningPull * (1.0 + 0.85), 1e-12);
  // Nothing to pull: every movable object has a wall distance preference.
  std::vector<bool> only_bed{false, false, true, false};
  EXPECT_FALSE(opening_pull(scene, model, only_bed));
}

//! object_violation() with the exact predicates only (no shortcut).
bool exactly_valid(const geometry::Scene& scene, int index) {
  const auto fp = geometry::world_footprint(scene.objects[static_cast<std::size_t>(index)]);
  if (geometry::protrusion(fp, scene.room.polygon)) return false;
  if (geometry::overlap_depth(fp, geometry::door_clear_zone(scene))) return false;
  for (std::size_t j = 0; j < scene.objects.size(); ++j)
    if (static_cast<int>(j) != index &&
        geometry::overlap_depth(fp, geometry::world_footprint(scene.objects[j])))
      return false;
  return true;
}

TEST(LayoutChecks, ShortcutsNeverChangeAnAnswer) {
  // object_violation() and object_fits() skip an exact predicate when a
  // floating-point test proves its answer (inside a convex room, polygons apart or in contact
  // along an axis). Against the exact predicates alone, on random poses of
  // the shipped rooms' objects (a convex room and an L-shaped one), many
  // of them flush against a wall or against another object, or just past.
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int checked = 0, invalid = 0, flush = 0;
  for (const char* file : {"bedroom.json", "l_studio.json", "office.json"}) {
    const geometry::Scene scene =
        geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/scenes/" + file);
    const geometry::Box box = geometry::bounding_box(scene.room.polygon);
    for (int c = 0; c < 1500; ++c) {
      geometry::Scene work = scene;
      const int i = static_cast<int>(u(rng) * static_cast<double>(scene.objects.size()));
      geometry::Object& o = work.objects[static_cast<std::size_t>(i)];
      const double quarter = std::floor(4.0 * u(rng)) * std::numbers::pi / 2;
      o.pose = {box.xmin + u(rng) * (box.xmax - box.xmin), box.ymin + u(rng) * (box.ymax - box.ymin),
                u(rng) < 0.7 ? quarter : 2.0 * std::numbers::pi * u(rng)};
      const int kind = c % 3;
      // Flush (or off by a hair) against the room's bounding box or another object.
      const auto fp = geometry::world_footprint(o);
      const geometry::Box b = geometry::bounding_box(fp);
      const double hair = (u(rng) - 0.5) * 4.0 * geometry::kContactTolerance;
      if (kind == 1) {
        o.pose.x += (box.xmin - b.xmin) + hair;
        ++flush;
      } else if (kind == 2) {
        const auto& other = work.objects[static_cast<std::size_t>(
            (i + 1) % static_cast<int>(work.objects.size()))];
        const geometry::Box ob = geometry::bounding_box(geometry::world_footprint(other));
        o.pose.x += (ob.xmax - b.xmin) + hair;
        ++flush;
      }
      const bool fast = object_violation(work, i).empty();
      ASSERT_EQ(fast, exactly_valid(work, i)) << file << " case " << c << " object " << o.id;
      // object_fits() adds a shortcut for deep overlaps of convex footprints.
      ASSERT_EQ(object_fits(work, i), fast) << file << " case " << c << " object " << o.id;
      ++checked;
      invalid += fast ? 0 : 1;
    }
  }
  EXPECT_EQ(checked, 4500);
  EXPECT_GT(invalid, 500);
  EXPECT_LT(invalid, 4400);
  EXPECT_GT(flush, 2000);
}

}  // namespace
}  // namespace hrs::optimize
