// SPDX-License-Identifier: GPL-3.0-or-later
// Preferences (optimize/preferences.h): residuals against hand computation
// (an object 3° off its wall, a TV facing away, a relation distance), which
// terms count, the wall poses that preferred_poses() proposes on thousands
// of random rooms and objects, the places around a relation partner
// (relation_slides) on thousands of random layouts, and preference moves
// that never leave the layout invalid; the exchanges of places (swaps)
// against the footprints' world vertices.

#include "optimize/preferences.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "geometry/error.h"
#include "geometry/polygon_ops.h"
#include "optimize/annealer.h"
#include "optimize/design.h"
#include "optimize/sequences.h"

namespace hrs::optimize {
namespace {

using geometry::Pose2;
using geometry::Scene;
constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

//! Room 5 × 4; a desk that wants its back to a wall, a TV that wants to face
//! the bed (relation angle π, distance 2.5), a fixed shelf with a wall
//! preference (not counted) and a fixed lamp related to the shelf (not
//! counted).
Scene pref_scene() {
  const std::string text = R"({
    "format": "hrspace-scene/1", "name": "prefs",
    "room": {"size": [5, 4]},
    "door": {"center": [4.0, 0.0], "width": 0.9, "clear_depth": 0.5},
    "wheelchair": {"length": 1.1, "width": 0.65, "turning_radius": 0.7},
    "objects": [
      {"id": "desk", "size": [0.6, 1.2], "pose": [2.0, 0.3, 1.5707963267948966],
       "wall": {"distance": 0.0, "angle": 0.0}},
      {"id": "bed", "size": [2.0, 1.4], "pose": [2.5, 3.0, -1.5707963267948966]},
      {"id": "tv", "size": [0.4, 1.0], "pose": [2.5, 0.5, 1.5707963267948966]},
      {"id": "shelf", "size": [0.4, 1.0], "pose": [4.8, 2.5, 3.141592653589793], "fixed": true,
       "wall": {"distance": 0.0, "angle": 0.0}},
      {"id": "lamp", "size": [0.3, 0.3], "pose": [4.7, 3.7, 0], "fixed": true}
    ],
    "relations": [{"a": "tv", "b": "bed", "distance": 2.5, "angle": 3.141592653589793},
                  {"a": "lamp", "b": "shelf", "distance": 1.0}],
    "activity": {"transitions": {"door": {"desk": 1.0}, "desk": {"tv": 1.0}, "tv": {"desk": 1.0}},
                 "sequences": 2, "visits": 2}
  })";
  return geometry::parse_scene(text, "prefs");
}

std::vector<Pose2> poses_of(const Scene& s) {
  std::vector<Pose2> p;
  for (const auto& o : s.objects) p.push_back(o.pose);
  return p;
}

const PreferenceCheck& find(const PreferenceReport& r, const std::string& kind,
                            const std::string& object) {
  for (const auto& c : r.checks)
    if (c.kind == kind && c.object == object) return c;
  throw std::runtime_error("no check " + kind + " " + object);
}

TEST(Preferences, ResidualsMatchHandComputation) {
  const Scene s = pref_scene();
  const CostModel model(s, scene_sequences(s));
  std::vector<Pose2> p = poses_of(s);
  PreferenceReport r = check_preferences(s, model, p);
  // Counted: desk wall distance and angle, tv–bed distance and angle; not the
  // fixed shelf's wall terms nor the fixed lamp–shelf relation.
  EXPECT_EQ(r.total, 4);
  EXPECT_EQ(r.met, 4);
  EXPECT_NEAR(find(r, "wall_distance", "desk").residual, 0.0, 1e-12);
  EXPECT_NEAR(find(r, "relation_distance", "tv").achieved, 2.5, 1e-12);

  // The desk turned 3.5° about its centre: off its wall by 3.5° (> 3°), so
  // the angle term fails; a back corner now reaches past the wall's line,
  // so the distance term (0) is still met.
  p[0].theta = kPi / 2 + 3.5 * kDeg;
  r = check_preferences(s, model, p);
  EXPECT_NEAR(find(r, "wall_angle", "desk").residual, 3.5 * kDeg, 1e-12);
  EXPECT_FALSE(find(r, "wall_angle", "desk").met);
  EXPECT_EQ(r.met, 3);
  // 2.5° is within the 3° tolerance.
  p[0].theta = kPi / 2 - 2.5 * kDeg;
  EXPECT_TRUE(find(check_preferences(s, model, p), "wall_angle", "desk").met);
  // Moved 4 cm off the wall: met (5 cm); 6 cm: not met.
  p[0] = {2.0, 0.34, kPi / 2};
  EXPECT_NEAR(find(check_preferences(s, model, p), "wall_distance", "desk").residual, 0.04, 1e-12);
  EXPECT_TRUE(find(check_preferences(s, model, p), "wall_distance", "desk").met);
  p[0] = {2.0, 0.36, kPi / 2};
  EXPECT_FALSE(find(check_preferences(s, model, p), "wall_distance", "desk").met);

  // The TV facing away from the bed: 180° off its relation angle.
  p = poses_of(s);
  p[2].theta = -kPi / 2;
  r = check_preferences(s, model, p);
  EXPECT_NEAR(find(r, "relation_angle", "tv").residual, kPi, 1e-12);
  EXPECT_FALSE(find(r, "relation_angle", "tv").met);
  // Relation distance tolerance: max(0.1, 10 % of 2.5) = 0.25.
  p = poses_of(s);
  p[2].y = 0.5 - 0.24;
  EXPECT_TRUE(find(check_preferences(s, model, p), "relation_distance", "tv").met);
  p[2].y = 0.5 - 0.26;
  EXPECT_FALSE(find(check_preferences(s, model, p), "relation_distance", "tv").met);
}

TEST(Preferences, WallPosesMeetTheirWallOnRandomRoomsAndObjects) {
  std::mt19937_64 rng(35);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int checked = 0, slides_checked = 0;
  for (int room = 0; room < 300; ++room) {
    // A rectangle or an L of random proportions, counter-clockwise.
    const double w = 3 + 5 * u(rng), h = 3 + 4 * u(rng);
    std::string polygon;
    if (room % 2 == 0) {
      polygon = "[[0,0],[" + std::to_string(w) + ",0],[" + std::to_string(w) + "," +
                std::to_string(h) + "],[0," + std::to_string(h) + "]]";
    } else {
      const double cx = w * (0.4 + 0.3 * u(rng)), cy = h * (0.4 + 0.3 * u(rng));
      polygon = "[[0,0],[" + std::to_string(w) + ",0],[" + std::to_string(w) + "," +
                std::to_string(cy) + "],[" + std::to_string(cx) + "," + std::to_string(cy) +
                "],[" + std::to_string(cx) + "," + std::to_string(h) + "],[0," +
                std::to_string(h) + "]]";
    }
    const double depth = 0.3 + 0.9 * u(rng), width = 0.4 + 1.6 * u(rng);
    const double distance = u(rng) < 0.5 ? 0.0 : 0.3 * u(rng);
    const double angle = u(rng) < 0.5 ? 0.0 : (u(rng) < 0.5 ? kPi : kPi / 2);
    const std::string text = R"({"format": "hrspace-scene/1", "name": "r",
      "room": {"polygon": )" + polygon + R"(},
      "door": {"center": [1.0, 0.0], "width": 0.9, "clear_depth": 0.3},
      "wheelchair": {"length": 1.1, "width": 0.65, "turning_radius": 0.7},
      "objects": [{"id": "o", "size": [)" + std::to_string(depth) + "," + std::to_string(width) +
                             R"(], "pose": [1.5, 1.5, 0.3],
        "wall": {"distance": )" + std::to_string(distance) + R"(, "angle": )" +
                             std::to_string(angle) + R"(}},
        {"id": "p", "size": [0.4, 0.4], "pose": [2.2, 1.2, 0]}],
      "activity": {"transitions": {"door": {"o": 1.0}, "o": {"p": 1.0}, "p": {"o": 1.0}},
                   "sequences": 2, "visits": 2}})";
    Scene s;
    try {
      s = geometry::parse_scene(text, "random");
    } catch (const InputError&) {
      continue;  // the object overlaps the other or leaves a small L room
    }
    const CostModel model(s, scene_sequences(s));
    std::vector<Pose2> p = poses_of(s);
    for (int trial = 0; trial < 10; ++trial) {
      p[0] = {w * u(rng), h * u(rng), 2 * kPi * u(rng)};
      auto candidates = preferred_poses(s, model, p, 0);
      // The places along every wall (wall_slides) as well, nearest first.
      const auto slides = wall_slides(s, model, p, 0, 0.2);
      EXPECT_FALSE(slides.empty());
      for (std::size_t k = 1; k < slides.size(); ++k)
        EXPECT_LE(geometry::norm(slides[k - 1].position() - p[0].position()),
                  geometry::norm(slides[k].position() - p[0].position()));
      const std::size_t first_slide = candidates.size();
      candidates.insert(candidates.end(), slides.begin(), slides.end());
      for (std::size_t k = 0; k < candidates.size(); ++k) {
        const Pose2& c = candidates[k];
        // Each wall pose touches its wall's line at the wanted distance with
        // the wanted heading: then, wherever it is inside the room and its
        // wall is the nearest, both wall terms are met.
        std::vector<Pose2> q = p;
        q[0] = c;
        geometry::Object o = s.objects[0];
        o.pose = c;
        if (!geometry::polygon_inside(geometry::world_footprint(o), s.room.polygon)) continue;
        const int e = model.nearest_wall(0, c);
        const double d = model.wall_distance(geometry::world_footprint(o), e);
        if (std::abs(d - distance) > 1e-9) continue;  // another wall's pose
        const PreferenceReport r = check_preferences(s, model, q);
        EXPECT_EQ(r.met, 2) << "room " << room << " trial " << trial;
        ++checked;
        if (k >= first_slide) ++slides_checked;
      }
    }
  }
  EXPECT_GT(checked, 1000);
  EXPECT_GT(slides_checked, 5000);  // slides that reached the check
}

TEST(Preferences, RelationSlidesMeetTheirRelationOnRandomLayouts) {
  std::mt19937_64 rng(3535);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int checked = 0, scenes = 0;
  for (int room = 0; room < 400; ++room) {
    const double w = 3 + 5 * u(rng), h = 3 + 4 * u(rng);
    const double d = 0.5 + 2.0 * u(rng);
    // Every second relation asks for an angle, every third (of the others)
    // for `a` to face `b`; the object at either end.
    const bool angle = room % 2 == 0, faces = !angle && room % 3 == 0;
    const double alpha = (u(rng) - 0.5) * 2.0 * kPi;
    const int object = room % 4 < 2 ? 0 : 1;
    std::string relation = R"({"a": "a", "b": "b", "distance": )" + std::to_string(d);
    if (angle) relation += R"(, "angle": )" + std::to_string(alpha);
    if (faces) relation += R"(, "faces": true)";
    relation += "}";
    const std::string text = R"({"format": "hrspace-scene/1", "name": "r",
      "room": {"size": [)" + std::to_string(w) + "," + std::to_string(h) + R"(]},
      "door": {"center": [0.6, 0.0], "width": 0.9, "clear_depth": 0.3},
      "wheelchair": {"length": 1.1, "width": 0.65, "turning_radius": 0.7},
      "objects": [{"id": "a", "size": [0.4, 0.4], "pose": [1.0, 2.0, 0.3]},
                  {"id": "b", "size": [0.5, 0.5], "pose": [2.2, 1.2, 0]}],
      "relations": [)" + relation + R"(],
      "activity": {"transitions": {"door": {"a": 1.0}, "a": {"b": 1.0}, "b": {"a": 1.0}},
                   "sequences": 2, "visits": 2}})";
    const Scene s = geometry::parse_scene(text, "random");
    ++scenes;
    const CostModel model(s, scene_sequences(s));
    std::vector<Pose2> p = poses_of(s);
    for (int trial = 0; trial < 5; ++trial) {
      p[0] = {w * u(rng), h * u(rng), 2 * kPi * u(rng)};
      p[1] = {w * u(rng), h * u(rng), 2 * kPi * u(rng)};
      const auto slides = relation_slides(s, p, object, 0.2);
      // About 0.2 m apart along the circle (at most ceil(2πd / 0.2) places,
      // fewer where the circle leaves the room's box; d >= 0.5 m gives at
      // least 16), nearest the current position first.
      EXPECT_LE(slides.size(), static_cast<std::size_t>(std::ceil(2 * kPi * d / 0.2)));
      for (std::size_t k = 1; k < slides.size(); ++k) {
        // Neighbouring places on the circle are one step apart or more.
        double gap = 1e300;
        for (std::size_t m = 0; m < slides.size(); ++m)
          if (m != k) gap = std::min(gap, geometry::norm(slides[m].position() - slides[k].position()));
        EXPECT_GT(gap, 0.9 * 2 * d * std::sin(kPi / std::ceil(2 * kPi * d / 0.2)));
      }
      for (std::size_t k = 1; k < slides.size(); ++k)
        EXPECT_LE(geometry::norm(slides[k - 1].position() - p[object].position()),
                  geometry::norm(slides[k].position() - p[object].position()));
      for (const Pose2& c : slides) {
        EXPECT_TRUE(c.x >= 0.0 && c.x <= w && c.y >= 0.0 && c.y <= h);
        std::vector<Pose2> q = p;
        q[static_cast<std::size_t>(object)] = c;
        const PreferenceReport r = check_preferences(s, model, q);
        // The distance is met, and so is the angle, or the facing when the
        // moved object is the one that faces; the other object's facing
        // depends on where it stands, and is not asked of the slides.
        for (const PreferenceCheck& k : r.checks) {
          if (k.kind == "relation_faces" && object == 1) continue;
          EXPECT_TRUE(k.met) << k.kind << " residual " << k.residual << " room " << room;
          if (k.kind == "relation_distance") EXPECT_NEAR(k.achieved, k.target, 1e-9);
        }
        ++checked;
      }
      // A turn the relation does not ask for keeps the current heading.
      if (!angle && !(faces && object == 0))
        for (const Pose2& c : slides) EXPECT_NEAR(c.theta, geometry::wrap_angle(p[object].theta), 1e-12);
    }
  }
  EXPECT_EQ(scenes, 400);
  EXPECT_GT(checked, 20000);
}

TEST(Preferences, RelationSlidesAreEmptyForAWallObjectOrWithoutADistance) {
  const Scene s = pref_scene();
  const CostModel model(s, scene_sequences(s));
  const std::vector<Pose2> p = poses_of(s);
  // The desk has a wall distance; the bed's relation has a distance (tv);
  // the fixed lamp's relation too; the shelf has a wall preference.
  EXPECT_TRUE(relation_slides(s, p, 0, 0.2).empty());
  EXPECT_FALSE(relation_slides(s, p, 2, 0.2).empty());
  EXPECT_FALSE(relation_slides(s, p, 1, 0.2).empty());
  EXPECT_FALSE(relation_slides(s, p, 4, 0.2).empty());
  EXPECT_TRUE(relation_slides(s, p, 3, 0.2).empty());
  EXPECT_TRUE(relation_slides(s, p, 2, 0.0).empty());
  // A relation with an angle and no distance gives no circle.
  Scene no_distance = s;
  no_distance.relations = {{"tv", "bed", std::nullopt, kPi}};
  EXPECT_TRUE(relation_slides(no_distance, p, 2, 0.2).empty());
  EXPECT_TRUE(relation_slides(no_distance, p, 1, 0.2).empty());
}

TEST(Preferences, GroupTurnsMeetEveryRelationAngleOfAConsistentGroup) {
  // Random groups of 2-5 objects linked by relation angles taken from
  // hidden headings (a random tree, sometimes one more edge closing a
  // cycle: consistent by construction), turned at random. Some turn of the
  // group meets every relation angle without moving a free object, and
  // every turn puts a wall object against a wall at its wanted heading.
  std::mt19937_64 rng(3535);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int cases = 0, walled = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const int n = 2 + static_cast<int>(u(rng) * 4);
    const bool wall = u(rng) < 0.5;  // object 0 wants its back to a wall
    std::vector<double> hidden;
    std::string objects, relations;
    for (int i = 0; i < n; ++i) {
      hidden.push_back(wall && i == 0 ? kPi / 2 * std::floor(4 * u(rng)) : 2 * kPi * u(rng) - kPi);
      const double x = 1.0 + 1.5 * i, y = 2.0 + 1.5 * (i % 2);
      objects += std::string(i ? "," : "") + R"({"id": "o)" + std::to_string(i) +
                 R"(", "size": [0.4, 0.6], "pose": [)" + std::to_string(x) + "," +
                 std::to_string(y) + "," + std::to_string(2 * kPi * u(rng) - kPi) + "]" +
                 (wall && i == 0 ? R"(, "wall": {"distance": 0.0, "angle": 0.0})" : "") + "}";
    }
    auto relate = [&](int a, int b) {
      relations += std::string(relations.empty() ? "" : ",") + R"({"a": "o)" + std::to_string(a) +
                   R"(", "b": "o)" + std::to_string(b) + R"(", "angle": )" +
                   std::to_string(geometry::wrap_angle(hidden[a] - hidden[b])) + "}";
    };
    for (int i = 1; i < n; ++i) relate(i, static_cast<int>(u(rng) * i));
    if (n >= 3 && u(rng) < 0.5) relate(0, n - 1);
    const std::string text = R"({"format": "hrspace-scene/1", "name": "g",
      "room": {"size": [9, 5]},
      "door": {"center": [8.0, 0.0], "width": 0.9, "clear_depth": 0.3},
      "wheelchair": {"length": 1.1, "width": 0.65, "turning_radius": 0.7},
      "objects": [)" + objects + R"(], "relations": [)" + relations + R"(],
      "activity": {"transitions": {"door": {"o0": 1.0}, "o0": {"o1": 1.0}, "o1": {"o0": 1.0}},
                   "sequences": 2, "visits": 2}})";
    const Scene s = geometry::parse_scene(text, "group");
    const CostModel model(s, scene_sequences(s));
    const std::vector<Pose2> p = poses_of(s);
    const std::vector<bool> movable(s.objects.size(), true);
    const auto groups = heading_groups(s);
    ASSERT_EQ(groups.size(), 1u);
    ASSERT_EQ(groups[0].size(), static_cast<std::size_t>(n));
    bool all_met = false;
    for (const GroupMove& move : group_turns(s, model, p, movable, groups[0])) {
      std::vector<Pose2> q = p;
      for (const auto& [k, pose] : move) {
        q[static_cast<std::size_t>(k)] = pose;
        if (k == 0 && wall) {
          // Against a wall at its wanted heading (the wall's normal).
          bool on_some_wall = false;
          for (int e = 0; e < 4; ++e)
            on_some_wall |= std::abs(geometry::wrap_angle(pose.theta - model.wall_normal_angle(e))) < 1e-9;
          EXPECT_TRUE(on_some_wall) << "trial " << trial;
          ++walled;
        } else {
          EXPECT_EQ(pose.position().x, p[static_cast<std::size_t>(k)].x);
          EXPECT_EQ(pose.position().y, p[static_cast<std::size_t>(k)].y);
        }
      }
      bool met = true;
      for (const PreferenceCheck& c : check_preferences(s, model, q).checks)
        if (c.kind == "relation_angle") met &= c.residual < 1e-5;  // angles written to 1e-6
      all_met |= met;
    }
    EXPECT_TRUE(all_met) << "trial " << trial << ": " << relations;
    ++cases;
  }
  EXPECT_EQ(cases, 2000);
  EXPECT_GT(walled, 500);
}

// swaps() against the footprints' world vertices, on 4000 random pairs of
// rectangles and triangles at random poses: back to back, each object takes
// the other's heading, and its footprint's extent along that heading starts
// where the other's started (the back line a wall object keeps), centred
// across it the same way; centre for centre, the reference points are
// exchanged and the headings kept.
TEST(Preferences, SwapsPutEachBackWhereTheOthersWas) {
  std::mt19937_64 rng(3535);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  // The extent [min, max] of `poly`'s projections on direction `d`.
  const auto extent = [](const geometry::Polygon& poly, geometry::Vec2 d) {
    double lo = 1e300, hi = -1e300;
    for (const geometry::Vec2& v : poly) {
      lo = std::min(lo, v.x * d.x + v.y * d.y);
      hi = std::max(hi, v.x * d.x + v.y * d.y);
    }
    return std::pair{lo, hi};
  };
  int cases = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const auto shape = [&](const std::string& id, double x, double y) {
      const std::string pose = "[" + std::to_string(x) + "," + std::to_string(y) + "," +
                               std::to_string(2 * kPi * u(rng) - kPi) + "]";
      if (u(rng) < 0.3) {
        // A triangle whose reference point is off its box's centre.
        return R"({"id": ")" + id + R"(", "pose": )" + pose + R"(, "polygon": [[)" +
               std::to_string(-0.2 - 0.5 * u(rng)) + "," + std::to_string(-0.1 - 0.4 * u(rng)) +
               "],[" + std::to_string(0.1 + 0.5 * u(rng)) + "," + std::to_string(-0.1 - 0.2 * u(rng)) +
               "],[" + std::to_string(0.05 * u(rng)) + "," + std::to_string(0.2 + 0.5 * u(rng)) + "]]}";
      }
      return R"({"id": ")" + id + R"(", "pose": )" + pose + R"(, "size": [)" +
             std::to_string(0.2 + 1.0 * u(rng)) + "," + std::to_string(0.3 + 1.8 * u(rng)) + "]}";
    };
    const std::string text = R"({"format": "hrspace-scene/1", "name": "swap",
      "room": {"size": [12, 12]},
      "door": {"center": [6.0, 0.0], "width": 0.9, "clear_depth": 0.3},
      "wheelchair": {"length": 1.1, "width": 0.65, "turning_radius": 0.7},
      "objects": [)" + shape("a", 2.0 + 3 * u(rng), 2.0 + 8 * u(rng)) + "," +
                             shape("b", 7.0 + 3 * u(rng), 2.0 + 8 * u(rng)) + R"(],
      "activity": {"transitions": {"door": {"a": 1.0}, "a": {"b": 1.0}, "b": {"a": 1.0}},
                   "sequences": 2, "visits": 2}})";
    const Scene s = geometry::parse_scene(text, "swap");
    const std::vector<Pose2> p = poses_of(s);
    const std::vector<GroupMove> moves = swaps(s, p, 0, 1);
    ASSERT_EQ(moves.size(), 2u);
    for (const GroupMove& m : moves) {
      ASSERT_EQ(m.size(), 2u);
      EXPECT_EQ(m[0].first, 0);
      EXPECT_EQ(m[1].first, 1);
    }
    for (int k = 0; k < 2; ++k) {
      // Object k at its back-to-back pose against the other, `o`, as it was.
      const int o = 1 - k;
      const Pose2 to = moves[0][static_cast<std::size_t>(k)].second;
      EXPECT_NEAR(std::abs(geometry::wrap_angle(to.theta - p[static_cast<std::size_t>(o)].theta)), 0.0,
                  1e-12);
      geometry::Object moved = s.objects[static_cast<std::size_t>(k)];
      moved.pose = to;
      const geometry::Polygon now = geometry::world_footprint(moved);
      const geometry::Polygon was = geometry::world_footprint(s.objects[static_cast<std::size_t>(o)]);
      const double t = p[static_cast<std::size_t>(o)].theta;
      const geometry::Vec2 front{std::cos(t), std::sin(t)}, left{-std::sin(t), std::cos(t)};
      EXPECT_NEAR(extent(now, front).first, extent(was, front).first, 1e-9) << "trial " << trial;
      const auto [l0, l1] = extent(now, left);
      const auto [w0, w1] = extent(was, left);
      EXPECT_NEAR(0.5 * (l0 + l1), 0.5 * (w0 + w1), 1e-9) << "trial " << trial;
      // Centre for centre.
      const Pose2 c = moves[1][static_cast<std::size_t>(k)].second;
      EXPECT_EQ(c.position(), p[static_cast<std::size_t>(o)].position());
      EXPECT_EQ(c.theta, p[static_cast<std::size_t>(k)].theta);
      ++cases;
    }
  }
  EXPECT_EQ(cases, 8000);
}

// The annealer with preference moves keeps its state valid: a proposal the
// validity check refuses is never costed or applied, and a rejected one is
// undone (the callbacks below apply and undo moves on `work`, which the
// exact checks then re-read after every iteration). The validity check is
// the product's own, so this tests the chain's protocol, not the pose
// generators; that they give valid poses often enough shows in the count of
// preference moves made (an invalid draw is redrawn, then replaced by an
// ordinary move), which must exceed 500 of the 1350 iterations that ask for
// one.
TEST(Preferences, PreferenceMovesNeverLeaveTheLayoutInvalid) {
  for (const char* file : {"bedroom.json", "office.json", "living_room.json", "l_studio.json"}) {
    const Scene scene = geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/scenes/" + file);
    CostModel model(scene, scene_sequences(scene));
    model.set_bounded_preferences(true);
    Scene work = scene;
    std::vector<bool> movable;
    for (const auto& o : scene.objects) movable.push_back(!o.fixed);
    AnnealOptions options;
    options.iterations = 1500;
    options.preference_probability = 0.9;
    options.t_start = 0.5;
    options.t_end = 0.01;
    int preference_moves = 0, accepted = 0;
    AnnealCallbacks cb;
    cb.move_valid = [&](const std::vector<Pose2>& p, int moved) {
      const Pose2 old = work.objects[moved].pose;
      work.objects[moved].pose = p[moved];
      const bool ok = object_violation(work, moved).empty();
      work.objects[moved].pose = old;
      return ok;
    };
    cb.cost = [&](const std::vector<Pose2>& p, const Move& m, const Acceptance&) {
      if (m.object >= 0) work.objects[m.object].pose = m.to;
      const auto in = model.interior(p);
      return in.distance + in.rotation;
    };
    cb.rejected = [&](const Move& m) { work.objects[m.object].pose = m.from; };
    cb.preferred = [&](const std::vector<Pose2>& p, int o, std::mt19937_64& rng) {
      auto c = preferred_poses(scene, model, p, o);
      if (auto slot = wall_slot(scene, o, rng)) c.push_back(*slot);
      if (c.empty()) return std::optional<Pose2>();
      return std::optional<Pose2>(c[std::uniform_int_distribution<std::size_t>(0, c.size() - 1)(rng)]);
    };
    cb.progress = [&](const TraceEntry& e) {
      if (e.preference) ++preference_moves;
      if (e.accepted) ++accepted;
      // The chain's state is `work`: after every iteration it is valid.
      ASSERT_EQ(layout_violation(work), "") << file << " iteration " << e.iteration;
    };
    std::mt19937_64 rng(7);
    const AnnealResult r = anneal(poses_of(scene), movable, options, cb, rng);
    EXPECT_GT(preference_moves, 500) << file;
    EXPECT_GT(accepted, 20) << file;
    // Preference moves find the preferences: the best layout meets more than
    // the input's (the shipped inputs meet most, so at least as many).
    const PreferenceReport before = check_preferences(scene, model, poses_of(scene));
    const PreferenceReport after = check_preferences(scene, model, r.best);
    EXPECT_GE(after.met, before.met) << file;
  }
}

}  // namespace
}  // namespace hrs::optimize
