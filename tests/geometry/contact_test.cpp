// SPDX-License-Identifier: GPL-3.0-or-later
// Contact with walls and furniture is valid (geometry/polygon_ops.h,
// kContactTolerance): the tolerant predicates on hand cases, every object of
// every shipped scene moved flush against each wall (and into its corners)
// at exact and typed headings, a footprint 0.01 m past a wall refused with
// the wall and the amount, and the "home office" of the issue.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "geometry/error.h"
#include "geometry/polygon_ops.h"
#include "geometry/scene.h"
#include "optimize/design.h"
#include "tests/geometry/scene_fixture.h"

namespace hrs::geometry {
namespace {

using scene_fixture::scene_files;
constexpr double kPi = std::numbers::pi;

Polygon square(double x0, double y0, double side) {
  return {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
}

// ---- the predicates ------------------------------------------------------------

TEST(ContactPredicates, InsideWithinTheTolerance) {
  const Polygon room = square(0, 0, 5);
  EXPECT_FALSE(protrusion(square(0, 0, 1), room));     // flush in the corner
  EXPECT_FALSE(protrusion(square(-4e-6, 2, 1), room));  // 4 µm past x = 0
  EXPECT_FALSE(protrusion(square(-4e-6, -4e-6, 1), room));  // 4 µm past both walls
  const auto out = protrusion(square(-0.01, 2, 1), room);
  ASSERT_TRUE(out);
  EXPECT_NEAR(out->amount, 0.01, 1e-12);
  EXPECT_EQ(out->edge, 3u);  // from (0,5) to (0,0)
  EXPECT_EQ(sticks_out_text(*out, room), "sticks out 0.01 m past the wall from (0,5) to (0,0)");
  const auto barely = protrusion(square(-2e-5, 2, 1), room);
  ASSERT_TRUE(barely);
  EXPECT_GT(barely->amount, kContactTolerance);
}

TEST(ContactPredicates, WallCornerPokingIntoAFootprintIsRefused) {
  // An L-shaped room: its reflex corner (2, 2) pokes 0.05 m into the square,
  // whose own corners all lie inside the room.
  const Polygon room = {{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}};
  const Polygon diamond = {{2.05, 1.5}, {2.55, 2.05}, {2.0, 2.55}, {1.5, 2.0}};
  const auto out = protrusion(diamond, room);
  ASSERT_TRUE(out);
  EXPECT_GT(out->amount, kContactTolerance);
}

TEST(ContactPredicates, OverlapWithinTheTolerance) {
  const Polygon a = square(0, 0, 1);
  EXPECT_FALSE(overlap_depth(a, square(1, 0, 1)));         // side to side
  EXPECT_FALSE(overlap_depth(a, square(1 - 5e-6, 0.3, 1)));  // 5 µm into it
  const auto deep = overlap_depth(a, square(0.95, 0.3, 1));
  ASSERT_TRUE(deep);
  EXPECT_NEAR(*deep, 0.05, 1e-9);
  EXPECT_TRUE(overlap_depth(a, square(1 - 2e-5, 0.3, 1)));
  EXPECT_TRUE(overlap_depth(a, square(0.2, 0.2, 0.5)));  // one inside the other
  // The exact predicates are unchanged: contact there is still exact.
  EXPECT_FALSE(polygon_inside(square(-4e-6, 2, 1), square(0, 0, 5)));
  EXPECT_TRUE(interiors_overlap(a, square(1 - 5e-6, 0.3, 1)));
}

// ---- shipped scenes: flush against every wall ---------------------------------

struct Heading {
  double exact;  //!< used to place the object flush
  double typed;  //!< written in the scene, as a person types it
};

const std::vector<Heading>& headings() {
  static const std::vector<Heading> h = [] {
    std::vector<Heading> out;
    for (int k = -3; k <= 4; ++k) out.push_back({k * kPi / 4, k * kPi / 4});
    for (Heading t : {Heading{kPi / 2, 1.5708}, Heading{kPi, 3.14159}, Heading{-kPi / 2, -1.5708},
                      Heading{-kPi, -3.14159}, Heading{kPi / 2, 1.57080}, Heading{kPi / 4, 0.7854}})
      out.push_back(t);
    return out;
  }();
  return h;
}

Polygon scaled(const Polygon& p, Vec2 centre, double f) {
  Polygon out;
  for (Vec2 v : p) out.push_back(centre + f * (v - centre));
  return out;
}

//! Independent of the tolerance: the object placed at the exact heading,
//! shrunk by 0.1 % about its centre, lies strictly in the room and clear of
//! everything the reader checks it against.
bool clearly_free(const Scene& scene, std::size_t k) {
  const Object& o = scene.objects[k];
  const Polygon fp = scaled(world_footprint(o), o.pose.position(), 0.999);
  if (!polygon_inside(fp, scene.room.polygon)) return false;
  for (std::size_t j = 0; j < scene.objects.size(); ++j)
    if (j != k && interiors_overlap(fp, world_footprint(scene.objects[j]))) return false;
  if (interiors_overlap(fp, door_clear_zone(scene))) return false;
  return !interiors_overlap(fp, chair_footprint(scene.wheelchair, door_start_pose(scene)));
}

std::string reader_error(const Scene& scene) {
  try {
    (void)parse_scene(write_scene(scene), "moved.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// overlap_beyond_contact() takes a shortcut for convex pairs (a common point
// deeper than the tolerance); it must answer as overlap_depth() does. 6000
// seeded pairs: rectangles at random (most apart or deeply overlapping),
// flush against each other within ±30 µm along a shared edge (contact and
// shallow overlaps, the tolerance's edge), crossing like a plus sign, and
// an L-shaped (non-convex) footprint against a rectangle.
Polygon rectangle(Vec2 c, double hw, double hh, double theta) {
  const double co = std::cos(theta), si = std::sin(theta);
  Polygon out;
  for (const Vec2 v : {Vec2{-hw, -hh}, Vec2{hw, -hh}, Vec2{hw, hh}, Vec2{-hw, hh}})
    out.push_back({c.x + co * v.x - si * v.y, c.y + si * v.x + co * v.y});
  return out;
}

TEST(ContactPredicates, QuickOverlapAnswersAsTheExactOne) {
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double offsets[] = {-3e-5, -1.2e-5, -8e-6, -2e-6, 0.0, 3e-6, 2e-5};
  int overlapping = 0, apart = 0;
  for (int c = 0; c < 6000; ++c) {
    const double theta = 2.0 * kPi * unit(rng);
    const Vec2 ca{4.0 * unit(rng), 4.0 * unit(rng)};
    const double hw = 0.1 + 1.2 * unit(rng), hh = 0.1 + 1.2 * unit(rng);
    const Polygon a = rectangle(ca, hw, hh, theta);
    Polygon b;
    const Vec2 ax{std::cos(theta), std::sin(theta)}, ay{-ax.y, ax.x};
    switch (c % 4) {
      case 0:  // anywhere near, any heading
        b = rectangle({ca.x + 3.0 * unit(rng) - 1.5, ca.y + 3.0 * unit(rng) - 1.5},
                      0.1 + 1.2 * unit(rng), 0.1 + 1.2 * unit(rng), 2.0 * kPi * unit(rng));
        break;
      case 1: {  // flush against a's right side, shifted along it
        const double bw = 0.1 + unit(rng), bh = 0.1 + unit(rng);
        const double gap = offsets[rng() % 7];
        const Vec2 cb = ca + (hw + bw + gap) * ax + (2.0 * unit(rng) - 1.0) * (hh + bh) * ay;
        b = rectangle(cb, bw, bh, theta + (rng() % 2 ? kPi : 0.0));
        break;
      }
      case 2:  // a plus sign: long and thin across a's middle
        b = rectangle(ca + (0.2 * unit(rng) - 0.1) * ax, 0.02 + 0.05 * unit(rng),
                      hh + 0.5 * unit(rng), theta + 0.3 * unit(rng) - 0.15);
        break;
      default: {  // an L (not convex) near a
        const Vec2 o = ca + (2.0 * unit(rng) - 1.0) * ax + (2.0 * unit(rng) - 1.0) * ay;
        b = {o, o + 1.0 * ax, o + 1.0 * ax + 0.4 * ay, o + 0.4 * ax + 0.4 * ay,
             o + 0.4 * ax + 1.0 * ay, o + 1.0 * ay};
        break;
      }
    }
    const bool exact = overlap_depth(a, b).has_value();
    ASSERT_EQ(overlap_beyond_contact(a, b), exact) << "case " << c;
    ASSERT_EQ(overlap_beyond_contact(b, a), overlap_depth(b, a).has_value()) << "case " << c;
    (exact ? overlapping : apart) += 1;
  }
  EXPECT_GT(overlapping, 1500);
  EXPECT_GT(apart, 1500);
}

TEST(ContactScenes, FlushAgainstEveryWallValidates) {
  int checked = 0, refused_checked = 0;
  for (const auto& path : scene_files()) {
    const Scene scene = load_scene(path.string());
    const Polygon& room = scene.room.polygon;
    for (std::size_t k = 0; k < scene.objects.size(); ++k) {
      for (std::size_t w = 0; w < room.size(); ++w) {
        const Vec2 a = room[w], b = room[(w + 1) % room.size()];
        const double length = norm(b - a);
        const Vec2 d = (1.0 / length) * (b - a), n{-d.y, d.x};  // n: into the room
        for (const Heading& h : headings()) {
          Object o = scene.objects[k];
          o.pose = {0, 0, h.exact};
          const Polygon r = rotated_footprint(o);
          double back = -1e300, lo = 1e300, hi = -1e300;
          for (Vec2 v : r) {
            back = std::max(back, -dot(v, n));
            lo = std::min(lo, dot(v, d));
            hi = std::max(hi, dot(v, d));
          }
          // Middle of the wall, and into the corner at either end.
          for (double along : {0.5 * length, -lo, length - hi}) {
            const Vec2 p = a + along * d + back * n;
            Scene moved = scene;
            moved.objects[k].pose = {p.x, p.y, h.exact};
            if (!clearly_free(moved, k)) continue;
            moved.objects[k].pose.theta = h.typed;
            const std::string where = path.filename().string() + ": " + o.id + " on wall " +
                                      std::to_string(w) + " at heading " +
                                      std::to_string(h.typed) + ", along " + std::to_string(along);
            EXPECT_EQ(reader_error(moved), "") << where;
            EXPECT_EQ(optimize::object_violation(moved, static_cast<int>(k)), "") << where;
            ++checked;
            if (along != 0.5 * length) continue;
            // 0.01 m past the wall: refused, naming the wall and the amount.
            const Vec2 q = p - 0.01 * n;
            moved.objects[k].pose = {q.x, q.y, h.typed};
            const std::string error = reader_error(moved);
            char wall[128];
            std::snprintf(wall, sizeof wall, "sticks out 0.01 m past the wall from (%.6g,%.6g) to (%.6g,%.6g)",
                          a.x, a.y, b.x, b.y);
            EXPECT_NE(error.find("/objects/" + std::to_string(k) + "/pose"), std::string::npos)
                << where << ": " << error;
            EXPECT_NE(error.find(wall), std::string::npos) << where << ": " << error;
            EXPECT_NE(optimize::object_violation(moved, static_cast<int>(k)).find(wall),
                      std::string::npos)
                << where;
            ++refused_checked;
          }
        }
      }
    }
  }
  // Most placements are free: the test must not pass by skipping them.
  EXPECT_GT(checked, 1000);
  EXPECT_GT(refused_checked, 300);
}

// ---- the home office of the issue --------------------------------------------

const char* const kHomeOffice = R"({
  "format": "hrspace-scene/1",
  "name": "home office",
  "room": { "size": [5, 4] },
  "door": { "center": [0, 2], "width": 0.9 },
  "wheelchair": { "length": 1.1, "width": 0.65, "turning_radius": 0.7 },
  "objects": [
    { "id": "desk", "size": [0.6, 1.2], "pose": [2.5, 0.3, -1.5708] },
    { "id": "sink", "size": [0.6, 0.5], "pose": [4.0, 0.3, 1.5707963267948966], "fixed": true },
    { "id": "shelf", "size": [0.35, 1.0], "pose": [4.825, 3.0, 3.14159] },
    { "id": "bed", "size": [2.0, 1.6], "pose": [2.5, 3.0, -1.5708] }
  ],
  "activity": { "transitions": { "door": { "desk": 0.5, "sink": 0.5 },
                                 "desk": { "sink": 1.0 }, "sink": { "desk": 1.0 } } }
})";

TEST(ContactScenes, HomeOfficeValidatesOnFirstTry) {
  const Scene s = parse_scene(kHomeOffice, "home_office.json");
  // The typed heading moves the desk's corner a few µm past y = 0 and the
  // sink's corner rounds to -3.7e-17: contact, not a violation.
  EXPECT_LT(bounding_box(world_footprint(s.objects[0])).ymin, 0.0);
  EXPECT_FALSE(polygon_inside(world_footprint(s.objects[0]), s.room.polygon));
  EXPECT_EQ(optimize::layout_violation(s), "");
  EXPECT_TRUE(degree_like_angles(s, "home_office.json").empty());
}

TEST(ContactScenes, HeadingsInDegreesAreFlagged) {
  Scene s = parse_scene(kHomeOffice, "home_office.json");
  s.objects[2].pose.theta = 180.0;  // a legal heading, but it looks like degrees
  const auto warnings = degree_like_angles(s, "home_office.json");
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("home_office.json: /objects/2/pose/2: angle 180"), std::string::npos)
      << warnings[0];
  // A heading in degrees that puts the desk out of the room says so.
  s = parse_scene(kHomeOffice, "home_office.json");
  s.objects[0].pose.theta = -90.0;
  const std::string error = reader_error(s);
  EXPECT_NE(error.find("sticks out"), std::string::npos) << error;
  EXPECT_NE(error.find("radians are expected"), std::string::npos) << error;
}

}  // namespace
}  // namespace hrs::geometry
