// SPDX-License-Identifier: GPL-3.0-or-later
// The polish's last stage, squaring (optimize/polish.h): an object whose
// heading no preference fixes is turned square to its nearest wall, slid
// to keep its reach towards the wall: the first square heading (nearest
// first) whose tours cost no more is kept as planned, else the cheapest
// (the next cheapest when the cheapest, planned again, loses a tour),
// within the planning budget. Built rooms with the exact layout
// checks and stand-in planners; square_places() (optimize/squaring.h)
// alone on thousands of scrambled shipped layouts, checked independently
// (part of optimize_polish_test).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "optimize/polish.h"
#include "optimize/preferences.h"
#include "optimize/sequences.h"
#include "optimize/squaring.h"
#include "polish_support.h"
#include "scramble.h"

namespace hrs::optimize {
namespace {

using geometry::Pose2;
using geometry::Vec2;
using testing::exact_hooks;
using testing::movable_of;
using testing::poses_of;
using testing::polish_all_found;
using testing::two_tours_found;
using testing::violation_at;

//! The highest y of an object's footprint at its pose.
double top_of(const geometry::Object& object) {
  double top = -std::numeric_limits<double>::infinity();
  for (const Vec2& v : geometry::world_footprint(object)) top = std::max(top, v.y);
  return top;
}

// A lamp 5 cm from the top wall (its wall distance, met) at 24° to it, and
// no preference on its heading. Squared to the wall about its centre it
// would stand 6.4 cm farther off and lose its wall distance; the polish
// slides it back along the wall's normal: square, still 5 cm from the wall,
// on the same spot along it. With a fixed shelf where the slide would take
// it, the squaring is refused (turned in place it loses the wall distance).
TEST(Polish, SquaresAnObjectToItsWallKeepingItsGap) {
  for (const bool shelf : {false, true}) {
    const double half = 0.2 * (std::cos(0.4189) + std::sin(0.4189));  // 24°, its reach in y
    std::string text = R"({
      "format": "hrspace-scene/1", "name": "lamp",
      "room": {"size": [5, 4]},
      "door": {"center": [2.5, 0.0], "width": 0.9, "clear_depth": 0.3},
      "wheelchair": {"length": 1.1, "width": 0.65, "turning_radius": 0.7},
      "objects": [
        {"id": "lamp", "size": [0.4, 0.4], "pose": [2.0, Y, THETA], "wall": {"distance": 0.05}},
        {"id": "box", "size": [0.5, 0.5], "pose": [4.5, 1.5, 0], "fixed": true}SHELF
      ],
      "activity": {"transitions": {"door": {"lamp": 1.0}, "lamp": {"box": 1.0}, "box": {"lamp": 1.0}},
                   "sequences": 2, "visits": 2}
    })";
    const auto put = [&](const std::string& key, const std::string& value) {
      text.replace(text.find(key), key.size(), value);
    };
    const auto exact = [](double v) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.17g", v);
      return std::string(buf);
    };
    put("Y", exact(4.0 - 0.05 - half));
    put("THETA", exact(-std::numbers::pi / 2 + 0.4189));
    // A 5 cm block in the squared, slid lamp's top left corner, clear of
    // the lamp at 24° and of the lamp squared in place.
    put("SHELF", shelf ? R"(, {"id": "shelf", "size": [0.05, 0.05], "pose": [1.83, 3.92, 0], "fixed": true})"
                       : "");
    const geometry::Scene scene = geometry::parse_scene(text, "lamp");
    ASSERT_EQ(layout_violation(scene), "") << shelf;
    CostModel model(scene, scene_sequences(scene));
    model.set_bounded_preferences(true);
    const std::vector<bool> movable = movable_of(scene);
    std::vector<Pose2> poses = poses_of(scene);
    ASSERT_EQ(check_preferences(scene, model, poses).met, 1) << shelf;
    geometry::Scene scratch = scene;
    const PolishResult r = polish_all_found(scene, model, movable, poses, scratch);
    EXPECT_EQ(check_preferences(scene, model, poses).met, 1) << shelf;
    if (shelf) {
      EXPECT_EQ(r.squared, 0);
      EXPECT_EQ(poses[0], scene.objects[0].pose);
      continue;
    }
    EXPECT_EQ(r.squared, 1);
    EXPECT_NEAR(geometry::wrap_angle(poses[0].theta + std::numbers::pi / 2), 0.0, 1e-9);
    EXPECT_NEAR(poses[0].x, 2.0, 1e-9);
    // Its footprint's top, from the corners: 5 cm below the wall at y = 4.
    geometry::Object lamp = scene.objects[0];
    lamp.pose = poses[0];
    const double top = top_of(lamp);
    EXPECT_NEAR(top, 4.0 - 0.05, 1e-9);
    EXPECT_EQ(violation_at(scratch, poses), "");
  }
}

//! A bench alone in a 5 m × 4 m room's middle at 25° to the room, no
//! preference on its heading, and a fixed box: the two squaring tests' room.
geometry::Scene bench_scene() {
  return geometry::parse_scene(R"({
    "format": "hrspace-scene/1", "name": "bench",
    "room": {"size": [5, 4]},
    "door": {"center": [2.5, 0.0], "width": 0.9, "clear_depth": 0.3},
    "wheelchair": {"length": 1.1, "width": 0.65, "turning_radius": 0.7},
    "objects": [
      {"id": "bench", "size": [1.2, 0.4], "pose": [2.5, 2.2, 0.4363323129985824]},
      {"id": "box", "size": [0.5, 0.5], "pose": [4.5, 1.5, 0], "fixed": true}
    ],
    "activity": {"transitions": {"door": {"bench": 1.0}, "bench": {"box": 1.0}, "box": {"bench": 1.0}},
                 "sequences": 2, "visits": 2}
  })", "bench");
}

//! The bench's nearest square heading: its nearest wall's normal plus the
//! multiple of a quarter turn nearest its heading (not wrapped).
double nearest_square_heading(const CostModel& model, const geometry::Scene& scene) {
  const double normal = model.wall_normal_angle(model.nearest_wall(0, scene.objects[0].pose));
  const double off = geometry::wrap_angle(scene.objects[0].pose.theta - normal);
  const double quarter = std::numbers::pi / 2;
  return normal + std::round(off / quarter) * quarter;
}

// A bench alone in a room's middle at 25° to the room, no preference on its
// heading. A stand-in check refuses the bench at its nearest square heading
// and at the half turn from it (as a stop it would cover); the two quarter
// turns are valid, and the planner's cost depends on the heading. The
// polish plans both and keeps the cheaper, at any cost over the tilted
// layout; with a planner that loses a tour on every squared layout, it
// keeps none.
TEST(Polish, SquaresToTheCheapestHeadingWhenTheNearestIsRefused) {
  const geometry::Scene scene = bench_scene();
  ASSERT_EQ(layout_violation(scene), "");
  const CostModel model = testing::bounded_model(scene);
  const std::vector<bool> movable = movable_of(scene);
  const double quarter = std::numbers::pi / 2;
  const double refused = nearest_square_heading(model, scene);
  const auto along = [](double a, double b) { return std::abs(std::sin(a - b)) < 1e-6; };
  // The exact checks (on `scratch`), which also refuse the bench along the
  // nearest square heading: at it or at the half turn from it.
  const auto refusing = [&](geometry::Scene& scratch) {
    PolishHooks hooks = exact_hooks(scratch);
    hooks.valid = [&scratch, &along, refused](const std::vector<Pose2>& p, int moved) {
      if (along(p[0].theta, refused)) return false;
      for (std::size_t i = 0; i < p.size(); ++i) scratch.objects[i].pose = p[i];
      return object_violation(scratch, moved).empty();
    };
    return hooks;
  };
  // The planner's cost of a heading: 3 + cos(θ - phase). Both phases, so
  // that the cheaper quarter turn is planned first in one and last in the
  // other (keeping the last one planned would not pass).
  for (const double phase : {0.3, 0.3 + std::numbers::pi}) {
    const auto cost = [&](double theta) { return 3.0 + std::cos(theta - phase); };
    for (const bool lose : {false, true}) {
      const std::string what = "phase " + std::to_string(phase) + (lose ? " losing" : "");
      std::vector<Pose2> poses = poses_of(scene);
      geometry::Scene scratch = scene;
      PolishHooks hooks = refusing(scratch);
      std::vector<double> planned;  // the headings planned
      hooks.plan = [&](const std::vector<Pose2>& p) {
        planned.push_back(p[0].theta);
        CostTerms t = two_tours_found();
        t.path_length = cost(p[0].theta);
        if (lose) t.tours_found = 1;
        return t;
      };
      CostTerms terms = two_tours_found();
      terms.path_length = 1.0;  // cheaper than any squared layout
      const PolishResult r = polish(scene, model, movable, poses, terms, hooks, 50);
      // Both quarter turns planned once, then the cheaper again to keep it.
      ASSERT_GE(planned.size(), 2u) << what;
      for (const double theta : planned) EXPECT_FALSE(along(theta, refused)) << what;
      if (lose) {
        EXPECT_EQ(r.squared, 0) << what;
        EXPECT_EQ(poses, poses_of(scene)) << what;
        continue;
      }
      const double a = geometry::wrap_angle(refused + quarter),
                   b = geometry::wrap_angle(refused - quarter);
      const double cheaper = cost(a) < cost(b) ? a : b;
      ASSERT_EQ(planned.size(), 3u) << what;
      EXPECT_NEAR(geometry::wrap_angle(planned[2] - cheaper), 0.0, 1e-9) << what;
      EXPECT_EQ(r.squared, 1) << what;
      EXPECT_NEAR(geometry::wrap_angle(poses[0].theta - cheaper), 0.0, 1e-9) << what;
      EXPECT_NEAR(terms.path_length, cost(cheaper), 1e-12) << what;
      EXPECT_EQ(violation_at(scratch, poses), "") << what;
    }
  }
  // The quarter turns' costs differ (no tie for "the cheaper"); the second
  // phase reverses them, so the cheaper was planned first in one phase and
  // last in the other.
  EXPECT_GT(std::abs(std::cos(refused + quarter - 0.3) - std::cos(refused - quarter - 0.3)), 0.1);

  // The cheaper heading loses a tour when it is planned again to be kept
  // (a planner whose answer depends on what it planned before): the other
  // quarter turn is planned and kept.
  for (const double phase : {0.3, 0.3 + std::numbers::pi}) {
    const auto cost = [&](double theta) { return 3.0 + std::cos(theta - phase); };
    const double a = geometry::wrap_angle(refused + quarter),
                 b = geometry::wrap_angle(refused - quarter);
    const double cheaper = cost(a) < cost(b) ? a : b, dearer = cost(a) < cost(b) ? b : a;
    std::vector<Pose2> poses = poses_of(scene);
    geometry::Scene scratch = scene;
    PolishHooks hooks = refusing(scratch);
    std::vector<double> planned;
    hooks.plan = [&](const std::vector<Pose2>& p) {
      // `along` holds for opposite headings too; this tells the two apart.
      const auto same = [](double u, double v) { return std::abs(geometry::wrap_angle(u - v)) < 1e-6; };
      const bool again = same(p[0].theta, cheaper) &&
                         std::any_of(planned.begin(), planned.end(), [&](double t) { return same(t, cheaper); });
      planned.push_back(p[0].theta);
      CostTerms t = two_tours_found();
      t.path_length = cost(p[0].theta);
      if (again) t.tours_found = 1;
      return t;
    };
    CostTerms terms = two_tours_found();
    terms.path_length = 1.0;
    const PolishResult r = polish(scene, model, movable, poses, terms, hooks, 50);
    ASSERT_EQ(planned.size(), 4u) << phase;
    EXPECT_NEAR(geometry::wrap_angle(planned[2] - cheaper), 0.0, 1e-9) << phase;
    EXPECT_NEAR(geometry::wrap_angle(planned[3] - dearer), 0.0, 1e-9) << phase;
    EXPECT_EQ(r.squared, 1) << phase;
    EXPECT_NEAR(geometry::wrap_angle(poses[0].theta - dearer), 0.0, 1e-9) << phase;
    EXPECT_NEAR(terms.path_length, cost(dearer), 1e-12) << phase;
  }

  // The budget: with two plannings left, one heading is planned, and kept
  // as planned since it costs no more; with one left, none is planned (a
  // heading that costs more would need a second plan to be kept).
  for (const int budget : {1, 2}) {
    std::vector<Pose2> poses = poses_of(scene);
    geometry::Scene scratch = scene;
    PolishHooks hooks = refusing(scratch);
    std::vector<double> planned;
    hooks.plan = [&](const std::vector<Pose2>& p) {
      planned.push_back(p[0].theta);
      return two_tours_found();
    };
    CostTerms terms = two_tours_found();
    const PolishResult r = polish(scene, model, movable, poses, terms, hooks, budget);
    if (budget == 1) {
      EXPECT_TRUE(planned.empty());
      EXPECT_EQ(r.squared, 0);
      EXPECT_EQ(poses, poses_of(scene));
      continue;
    }
    ASSERT_EQ(planned.size(), 1u);
    EXPECT_FALSE(along(planned[0], refused));
    EXPECT_EQ(r.squared, 1);
    EXPECT_NEAR(geometry::wrap_angle(poses[0].theta - planned[0]), 0.0, 1e-12);
  }
}

// The same bench, every square heading valid. The square headings are
// planned nearest first, and the first whose tours are all found at no
// higher total cost is kept as it was planned (no second plan), even when
// a later one would be cheaper; the headings that cost more are put back.
// When the nearest costs no more, it is the one planning. A planner that
// answers by the order of its calls (not by heading) tells them apart.
TEST(Polish, SquaresToTheFirstHeadingThatCostsNoMore) {
  const geometry::Scene scene = bench_scene();
  ASSERT_EQ(layout_violation(scene), "");
  const CostModel model = testing::bounded_model(scene);
  const std::vector<bool> movable = movable_of(scene);
  const double nearest = geometry::wrap_angle(nearest_square_heading(model, scene));
  struct Case {
    std::vector<double> costs;  // the planner's path length at its k-th call
    std::size_t kept;           // the call whose heading is kept
  };
  // The current layout's path length is 3.
  for (const Case& c : {Case{{3.5, 3.2, 2.9, 2.5}, 2}, Case{{3.0, 2.0, 2.0, 2.0}, 0},
                        Case{{3.5, 3.0, 2.0, 2.0}, 1}}) {
    const std::string what = "kept call " + std::to_string(c.kept);
    std::vector<Pose2> poses = poses_of(scene);
    geometry::Scene scratch = scene;
    PolishHooks hooks = exact_hooks(scratch);
    std::vector<double> planned;
    std::vector<Pose2> placed = poses;  // the layout the hooks were last told
    const auto place = hooks.place;
    hooks.place = [&](int object, const Pose2& to) {
      placed[static_cast<std::size_t>(object)] = to;
      place(object, to);
    };
    hooks.plan = [&](const std::vector<Pose2>& p) {
      EXPECT_EQ(p, placed) << what << ": planned a layout other than the placed one";
      CostTerms t = two_tours_found();
      t.path_length = c.costs.at(planned.size());
      planned.push_back(p[0].theta);
      return t;
    };
    CostTerms terms = two_tours_found();
    terms.path_length = 3.0;
    const PolishResult r = polish(scene, model, movable, poses, terms, hooks, 50);
    ASSERT_EQ(planned.size(), c.kept + 1) << what;
    EXPECT_NEAR(geometry::wrap_angle(planned[0] - nearest), 0.0, 1e-9) << what;
    for (std::size_t k = 1; k < planned.size(); ++k)
      EXPECT_GT(std::abs(geometry::wrap_angle(planned[k] - planned[0])), 1.0) << what;
    EXPECT_EQ(r.squared, 1) << what;
    EXPECT_EQ(r.tried, static_cast<int>(c.kept) + 1) << what;
    EXPECT_NEAR(geometry::wrap_angle(poses[0].theta - planned[c.kept]), 0.0, 1e-12) << what;
    EXPECT_EQ(terms.path_length, c.costs[c.kept]) << what;
    EXPECT_EQ(placed, poses) << what << ": the hooks were left at another layout";
    EXPECT_EQ(violation_at(scratch, poses), "") << what;
  }
}

// A bench 2 cm from the top wall (its wall distance, met) at 40° to the
// wall's normal. Turned square about its centre, its long side would stand
// along the normal and reach 2.4 cm beyond the wall; the slide takes it back
// by the whole reach, not only by its old gap: square, 2 cm from the wall.
TEST(Polish, SquaresALongObjectThatItsTurnPushesThroughTheWall) {
  const double tilt = 0.6981317007977318;  // 40°
  const double theta = -std::numbers::pi / 2 + tilt;
  char text[2048];
  const auto scene_at = [&](double y) {
    std::snprintf(text, sizeof text, R"({
    "format": "hrspace-scene/1", "name": "bench",
    "room": {"size": [5, 4]},
    "door": {"center": [2.5, 0.0], "width": 0.9, "clear_depth": 0.3},
    "wheelchair": {"length": 1.1, "width": 0.65, "turning_radius": 0.7},
    "objects": [
      {"id": "bench", "size": [1.2, 0.3], "pose": [2.0, %.17g, %.17g], "wall": {"distance": 0.02}},
      {"id": "box", "size": [0.5, 0.5], "pose": [4.5, 1.5, 0], "fixed": true}
    ],
    "activity": {"transitions": {"door": {"bench": 1.0}, "bench": {"box": 1.0}, "box": {"bench": 1.0}},
                 "sequences": 2, "visits": 2}
  })", y, theta);
    return geometry::parse_scene(text, "bench");
  };
  // The bench's half-extent in y at its heading, from its footprint.
  geometry::Object probe = scene_at(2.0).objects[0];
  probe.pose = {0.0, 0.0, theta};
  const double reach = top_of(probe);
  const geometry::Scene scene = scene_at(4.0 - 0.02 - reach);
  ASSERT_EQ(layout_violation(scene), "");
  // The premise: turned in place, the bench crosses the wall by more than
  // its 2 cm gap.
  geometry::Object turned = scene.objects[0];
  turned.pose.theta = -std::numbers::pi / 2;
  ASSERT_GT(top_of(turned), 4.0 + 0.02);
  CostModel model(scene, scene_sequences(scene));
  model.set_bounded_preferences(true);
  std::vector<Pose2> poses = poses_of(scene);
  ASSERT_EQ(check_preferences(scene, model, poses).met, 1);
  geometry::Scene scratch = scene;
  PolishHooks hooks = exact_hooks(scratch);
  std::vector<double> planned;
  hooks.plan = [&](const std::vector<Pose2>& p) {
    planned.push_back(p[0].theta);
    return two_tours_found();
  };
  CostTerms terms = two_tours_found();
  const PolishResult r = polish(scene, model, movable_of(scene), poses, terms, hooks, 50);
  EXPECT_EQ(r.squared, 1);
  EXPECT_EQ(planned.size(), 1u);  // the nearest heading fits: no other is planned
  EXPECT_NEAR(geometry::wrap_angle(poses[0].theta + std::numbers::pi / 2), 0.0, 1e-9);
  EXPECT_NEAR(poses[0].x, 2.0, 1e-9);
  geometry::Object bench = scene.objects[0];
  bench.pose = poses[0];
  EXPECT_NEAR(top_of(bench), 4.0 - 0.02, 1e-9);
  EXPECT_EQ(check_preferences(scene, model, poses).met, 1);
  EXPECT_EQ(violation_at(scratch, poses), "");
}

// square_places() on scrambled shipped layouts (axis-parallel rooms, so a
// square heading is a multiple of 90°), for every movable object whose
// heading no preference fixes: every place returned is valid under the
// exact layout checks, square, scores no lower (a fresh report), stands
// where the object stood or moved along one axis only (the slide along the
// wall's normal), keeps the footprint's least signed distance to one
// wall's line when it moved (the slide's purpose), and the headings come nearest first, each at
// most once; an object already square gets none.
TEST(Squaring, SquarePlacesAreValidSquareAndScoreNoLower) {
  int objects = 0, places = 0, slid = 0, already = 0;
  for (const char* file : {"bedroom.json", "office.json", "living_room.json", "l_studio.json"}) {
    const geometry::Scene scene =
        geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/scenes/" + file);
    const CostModel model = testing::bounded_model(scene);
    const std::vector<bool> movable = movable_of(scene);
    // The least signed distance of a footprint's corners to the line of
    // wall e (positive inside; brute force over the corners).
    const auto line_gap = [&](const geometry::Object& o, std::size_t e) {
      const geometry::Polygon& room = scene.room.polygon;
      const Vec2 a = room[e], b = room[(e + 1) % room.size()];
      const double len = std::hypot(b.x - a.x, b.y - a.y);
      // Counter-clockwise rooms: the inside is to the left of a -> b.
      const double nx = -(b.y - a.y) / len, ny = (b.x - a.x) / len;
      double gap = std::numeric_limits<double>::infinity();
      for (const Vec2& v : geometry::world_footprint(o))
        gap = std::min(gap, (v.x - a.x) * nx + (v.y - a.y) * ny);
      return gap;
    };
    for (std::uint64_t seed = 1; seed <= 250; ++seed) {
      // Scrambled, then each free heading turned to a uniform angle (kept
      // where valid): the scramble turns by quarters only.
      const geometry::Scene work = testing::askew_free_headings(
          scene, testing::scrambled(scene, movable, seed), movable, seed);
      const std::vector<Pose2> poses = poses_of(work);
      const PreferenceReport report = check_preferences(scene, model, poses);
      geometry::Scene scratch = work;
      const auto valid = exact_hooks(scratch).valid;
      for (std::size_t i = 0; i < poses.size(); ++i) {
        const int object = static_cast<int>(i);
        if (!movable[i] || heading_fixed(scene, object)) continue;
        const std::string at = std::string(file) + " seed " + std::to_string(seed) + " " +
                               scene.objects[i].id;
        ++objects;
        const double quarters = poses[i].theta / (std::numbers::pi / 2);
        const bool square = std::abs(quarters - std::round(quarters)) < 1e-4;
        const std::vector<SquarePlace> found = square_places(scene, model, poses, object, report, valid);
        if (square) {
          ++already;
          EXPECT_TRUE(found.empty()) << at;
          continue;
        }
        double last_turn = -1.0;
        std::vector<double> headings;
        for (const SquarePlace& sq : found) {
          ++places;
          std::vector<Pose2> p = poses;
          p[i] = sq.pose;
          EXPECT_EQ(violation_at(work, p), "") << at;
          const double q = sq.pose.theta / (std::numbers::pi / 2);
          EXPECT_NEAR(q, std::round(q), 1e-9) << at;
          const PreferenceReport r = check_preferences(scene, model, p);
          EXPECT_EQ(r.met, sq.report.met) << at;
          EXPECT_GE(testing::score_of(r), testing::score_of(report)) << at;
          const double dx = std::abs(sq.pose.x - poses[i].x), dy = std::abs(sq.pose.y - poses[i].y);
          EXPECT_TRUE(dx < 1e-12 || dy < 1e-12) << at;  // along one axis only
          if (dx >= 1e-12 || dy >= 1e-12) {
            // Slid: some wall, the one it slid from, keeps its line gap.
            ++slid;
            geometry::Object before = scene.objects[i], after = scene.objects[i];
            before.pose = poses[i];
            after.pose = sq.pose;
            bool kept_gap = false;
            for (std::size_t e = 0; e < scene.room.polygon.size(); ++e)
              kept_gap = kept_gap || std::abs(line_gap(after, e) - line_gap(before, e)) < 1e-9;
            EXPECT_TRUE(kept_gap) << at;
          }
          const double turn = std::abs(geometry::wrap_angle(sq.pose.theta - poses[i].theta));
          EXPECT_GE(turn, last_turn - 1e-12) << at;
          last_turn = turn;
          for (const double h : headings)
            EXPECT_GT(std::abs(geometry::wrap_angle(h - sq.pose.theta)), 1.0) << at;
          headings.push_back(sq.pose.theta);
        }
      }
    }
  }
  std::printf("%d objects with a free heading: %d already square, %d places (%d slid)\n", objects,
              already, places, slid);
  EXPECT_GT(objects, 1000);
  EXPECT_GT(places, 1000);
  EXPECT_GT(slid, 100);
}

}  // namespace
}  // namespace hrs::optimize
