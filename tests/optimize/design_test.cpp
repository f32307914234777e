// SPDX-License-Identifier: GPL-3.0-or-later
// Design outputs checked independently of the annealer: the written layout
// is a valid scene with every object inside the room, no overlaps, the door
// zone free, fixed objects and all sizes unchanged, and every tour of
// tours.json re-validated against the final layout. Determinism: the same
// seed gives byte-identical layout.json and tours.json with 1 and 2 threads.
#include "optimize/design.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <nlohmann/json.hpp>
#include <sstream>

#include "geometry/cspace.h"
#include "geometry/polygon_ops.h"
#include "optimize/design_io.h"
#include "rs/reeds_shepp.h"
#include "tests/support/paths.h"
#include "tests/support/scratch.h"

namespace hrs::optimize {
namespace {

using geometry::Polygon;
using geometry::Scene;
using geometry::Vec2;
using nlohmann::json;

const std::string kBedroom = std::string(HRSPACE_SOURCE_DIR) + "/scenes/bedroom.json";

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

rs::Path path_of(const json& leg, double radius) {
  rs::Path path;
  path.radius = radius;
  for (const auto& s : leg["segments"]) {
    const std::string steer = s["steer"];
    path.segments.push_back(
        {static_cast<rs::Steer>(steer[0]), s["gear"].get<int>(), s["length"].get<double>()});
  }
  return path;
}

geometry::Pose2 pose_of(const json& j) { return {j[0], j[1], j[2]}; }

// Checks a written design against the input scene without using the
// optimizer: returns the number of tours found.
int check_design_dir(const Scene& input, const std::filesystem::path& dir) {
  const Scene out = geometry::load_scene((dir / "layout.json").string());
  EXPECT_EQ(out.name, input.name);
  EXPECT_EQ(out.room, input.room);
  EXPECT_EQ(out.door, input.door);
  EXPECT_EQ(out.wheelchair, input.wheelchair);
  EXPECT_EQ(out.relations, input.relations);
  EXPECT_EQ(out.activity, input.activity);
  EXPECT_EQ(out.weights, input.weights);
  EXPECT_EQ(out.objects.size(), input.objects.size());
  const Polygon zone = geometry::door_clear_zone(out);
  for (std::size_t i = 0; i < out.objects.size(); ++i) {
    const auto& o = out.objects[i];
    const auto& in = input.objects[i];
    EXPECT_EQ(o.id, in.id);
    EXPECT_EQ(o.size, in.size) << o.id;
    EXPECT_EQ(o.footprint, in.footprint) << o.id;
    EXPECT_EQ(o.fixed, in.fixed);
    EXPECT_EQ(o.wall, in.wall);
    EXPECT_EQ(o.approach, in.approach);
    if (in.fixed) {
      EXPECT_EQ(o.pose, in.pose) << "fixed object " << o.id << " moved";
    }
    const Polygon fp = geometry::world_footprint(o);
    // Contact within geometry::kContactTolerance is valid (as in the reader).
    EXPECT_TRUE(geometry::inside_with_contact(fp, out.room.polygon)) << o.id << " outside the room";
    EXPECT_FALSE(geometry::overlap_beyond_contact(fp, zone)) << o.id << " in the door zone";
    for (std::size_t j = i + 1; j < out.objects.size(); ++j)
      EXPECT_FALSE(
          geometry::overlap_beyond_contact(fp, geometry::world_footprint(out.objects[j])))
          << o.id << " overlaps " << out.objects[j].id;
  }

  // Tours, re-validated in the final layout by the exact CGAL reference
  // (tests/support), independent of the production C-space.
  const test_support::ReferenceChecker reference(out);
  const double radius = out.wheelchair.turning_radius;
  const json tours = json::parse(read(dir / "tours.json"));
  EXPECT_EQ(tours["tours"].size(), static_cast<std::size_t>(out.activity.sequences));
  int found = 0;
  for (const auto& t : tours["tours"]) {
    const auto seq = t["sequence"].get<std::vector<std::string>>();
    EXPECT_EQ(seq.front(), "door");
    EXPECT_GT(t["likelihood"].get<double>(), 0.0);
    if (!t["found"].get<bool>()) {
      EXPECT_TRUE(t["legs"].empty());
      continue;
    }
    ++found;
    EXPECT_EQ(t["legs"].size(), seq.size() - 1);
    geometry::Pose2 at = geometry::door_start_pose(out);
    double length = 0.0;
    for (std::size_t i = 0; i < t["legs"].size(); ++i) {
      const auto& leg = t["legs"][i];
      const auto from = pose_of(leg["from"]), to = pose_of(leg["to"]);
      EXPECT_NEAR(from.x, at.x, 1e-9);
      EXPECT_NEAR(from.y, at.y, 1e-9);
      EXPECT_NEAR(geometry::wrap_angle(from.theta - at.theta), 0.0, 1e-9);
      const rs::Path path = path_of(leg, radius);
      const auto end = rs::pose_at(from, path, path.length());
      EXPECT_NEAR(end.x, to.x, 1e-6);
      EXPECT_NEAR(end.y, to.y, 1e-6);
      EXPECT_NEAR(geometry::wrap_angle(end.theta - to.theta), 0.0, 1e-6);
      // Free by the exact reference at every pose 5 mm apart.
      test_support::expect_valid_path(
          reference, from, to, path, radius,
          "leg " + std::to_string(i) + " (" + seq[i] + " -> " + seq[i + 1] + ")", 0.005);
      // The leg ends at the object of the sequence: the chair stops `gap` away.
      const int obj = out.find_object(seq[i + 1]);
      EXPECT_GE(obj, 0);
      if (obj < 0) return -1;
      const double l = out.wheelchair.length / 2, w = out.wheelchair.width / 2;
      const Polygon chair{geometry::to_world(to, {-l, -w}), geometry::to_world(to, {l, -w}),
                          geometry::to_world(to, {l, w}), geometry::to_world(to, {-l, w})};
      const double gap = out.objects[obj].approach_or_default().gap;
      EXPECT_NEAR(geometry::polygon_distance(chair, geometry::world_footprint(out.objects[obj])), gap, 0.02)
          << "leg " << i << " does not stop at " << seq[i + 1];
      length += path.length();
      at = to;
    }
    EXPECT_NEAR(t["metrics"]["length"].get<double>(), length, 1e-6);
  }
  return found;
}

TEST(Design, OutputsAreValidIndependentlyOfTheAnnealer) {
  const Scene scene = geometry::load_scene(kBedroom);
  DesignOptions options;
  options.planner = hrs::optimize::PlannerConfig::from_preset("baseline");
  options.seed = 2;  // a seed whose 25 iterations reach found tours, so they are checked
  options.iterations = 25;
  options.threads = 2;
  const auto result = design(scene, options);
  EXPECT_TRUE(result.valid);
  EXPECT_EQ(result.proposals, 25);
  EXPECT_LE(result.final.total(), result.initial.total() + 1e-12);
  const auto dir = test_support::scratch_path("design_test");
  std::filesystem::remove_all(dir);
  write_design(result, {2, "baseline", 25}, dir);
  const int found = check_design_dir(scene, dir);
  EXPECT_EQ(found, result.final.tours_found);
  // The paper's bedroom is tourable: some tours are found.
  EXPECT_GT(found, 0);
  const json report = json::parse(read(dir / "report.json"));
  EXPECT_EQ(report["trace"].size(), 25u);
  EXPECT_NEAR(report["cost"]["final"].get<double>(), result.final.total(), 1e-12);
  EXPECT_LE(report["time_s"]["planning"].get<double>(), report["time_s"]["total"].get<double>());
  // The three phases add up to the total (the clock is read between them);
  // the grid fills run within them.
  const json& t = report["time_s"];
  const double total = t["total"].get<double>();
  for (const char* phase : {"setup", "annealing", "finish", "grid"}) EXPECT_GE(t[phase].get<double>(), 0.0);
  EXPECT_GT(t["setup"].get<double>(), 0.0);
  EXPECT_GT(t["annealing"].get<double>(), 0.0);
  EXPECT_NEAR(t["setup"].get<double>() + t["annealing"].get<double>() + t["finish"].get<double>(),
              total, 1e-3 * total + 1e-4);
  EXPECT_LE(t["grid"].get<double>(), total);
  const std::string svg = read(dir / "design.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  for (const auto& o : scene.objects) EXPECT_NE(svg.find(">" + o.id + "<"), std::string::npos);
}

TEST(Design, SameSeedGivesByteIdenticalFilesWithOneAndTwoThreads) {
  const Scene scene = geometry::load_scene(kBedroom);
  std::string layout[2], tours[2];
  for (int t = 0; t < 2; ++t) {
    DesignOptions options;
    options.planner = hrs::optimize::PlannerConfig::from_preset("baseline");
    options.seed = 11;
    options.iterations = 6;
    options.threads = t + 1;
    const auto r = design(scene, options);
    EXPECT_EQ(r.threads, t + 1);
    layout[t] = geometry::write_scene(r.layout);
    tours[t] = tours_document(r);
  }
  EXPECT_EQ(layout[0], layout[1]);
  EXPECT_EQ(tours[0], tours[1]);
}

// The default preset rejects proposals early, cancelling the tours not yet
// started, so the last proposal's tours have a tail that depends on the
// threads' timing. The arrangement and the polish must start from the best
// layout's tours. Before they did, the default design of this zoo room
// (`hrspace generate --seed 7 --count 16 --objects 10-36`, room 4; 18
// objects) differed in 4 of 10 two-thread runs. A race shows only by
// chance, so several two-thread runs are compared with a one-thread run.
TEST(Design, DefaultPresetIsIdenticalWithOneAndTwoThreads) {
  {
    const Scene scene =
        geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/tests/optimize/zoo_7_4.json");
    const char* room = "zoo_7_4";
    std::string layout[4], tours[4];
    for (int run = 0; run < 4; ++run) {
      DesignOptions options;
      options.planner = hrs::optimize::PlannerConfig::from_preset("default");
      options.seed = 1;
      options.threads = run == 0 ? 1 : 2;
      const auto r = design(scene, options);
      // The situation the test is about: proposals rejected early (their
      // tours cancelled), then an arrangement and a polish.
      EXPECT_GT(r.early.proposals, 0);
      EXPECT_EQ(r.threads, options.threads);
      EXPECT_GT(r.arrange.proposals, 0);
      layout[run] = geometry::write_scene(r.layout);
      tours[run] = tours_document(r);
    }
    for (int run = 1; run < 4; ++run) {
      EXPECT_EQ(layout[0], layout[run]) << room << " run " << run;
      EXPECT_EQ(tours[0], tours[run]) << room << " run " << run;
    }
  }
}

// The opening arrangement (PlannerConfig::prefer): the annealing starts
// from the arranged layout only when it tours at least the input's tours
// for a lower total cost; the `paper` preset has none. Short runs of the
// shipped rooms and the zoo rooms kept here.
TEST(Design, OpeningArrangementIsKeptOnlyWhenItToursAsWellForLess) {
  int kept = 0, refused = 0;
  for (const char* file : {"scenes/bedroom.json", "scenes/office.json", "scenes/living_room.json",
                           "tests/optimize/zoo_1_320.json", "tests/optimize/zoo_1_408.json",
                           "tests/optimize/zoo_7_1.json"}) {
    const Scene scene = geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/" + file);
    for (const char* preset : {"default", "paper"}) {
      DesignOptions options;
      options.planner = hrs::optimize::PlannerConfig::from_preset(preset);
      options.seed = 3;
      options.iterations = 5;
      const auto r = design(scene, options);
      const auto& o = r.opening;
      const std::string what = std::string(file) + " " + preset;
      EXPECT_EQ(o.ran, std::string(preset) == "default") << what;
      if (!o.ran) continue;
      EXPECT_GT(o.proposals, 0) << what;
      if (o.kept) {
        ++kept;
        EXPECT_GE(o.tours_found_after, o.tours_found_before) << what;
        EXPECT_LT(o.cost_after, o.cost_before) << what;
      } else if (o.cost_after != o.cost_before || o.tours_found_after != o.tours_found_before) {
        ++refused;
        EXPECT_TRUE(o.tours_found_after < o.tours_found_before || o.cost_after >= o.cost_before) << what;
      }
    }
  }
  EXPECT_GT(kept, 0);  // the rule is exercised on its accepting side
  std::printf("opening arrangements kept %d, refused %d\n", kept, refused);
  // With no proposal (or none better), the design's best is the start, kept
  // or not, with its terms and all its tours (the opening's rounds once
  // made the start look like a proposal: no tours, cost 0).
  for (const int iterations : {0, 6}) {
    const Scene scene = geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/scenes/bedroom.json");
    DesignOptions options;
    options.planner = hrs::optimize::PlannerConfig::from_preset("baseline");
    options.planner.escape = false;
    options.seed = 3;
    options.iterations = iterations;
    options.threads = 2;
    const auto r = design(scene, options);
    EXPECT_TRUE(r.opening.ran) << iterations;
    EXPECT_EQ(r.tours.size(), r.sequences.size()) << iterations;
    EXPECT_EQ(r.final.tours_total, static_cast<int>(r.sequences.size())) << iterations;
    EXPECT_GT(r.final.total(), 0.0) << iterations;
  }
}

TEST(Design, InvalidStartingLayoutIsSeparatedOrReportedInvalid) {
  // Two movable objects start overlapping (allowed by the format): the
  // design separates them before the annealing, so the result is valid.
  Scene scene = geometry::load_scene(kBedroom);
  const int lamp = scene.find_object("lamp"), dresser = scene.find_object("dresser");
  scene.objects[lamp].pose = {scene.objects[dresser].pose.x - 0.1, scene.objects[dresser].pose.y,
                              0.0};
  ASSERT_FALSE(layout_violation(scene).empty());
  DesignOptions options;
  options.planner = hrs::optimize::PlannerConfig::from_preset("baseline");
  options.iterations = 40;
  const auto r = design(scene, options);
  EXPECT_GE(r.unblock.separated, 1);
  EXPECT_TRUE(r.valid);
  EXPECT_EQ(layout_violation(r.layout), "");
  // The lamp and the dresser no longer overlap (checked on their footprints).
  EXPECT_FALSE(geometry::interiors_overlap(geometry::world_footprint(r.layout.objects[lamp]),
                                           geometry::world_footprint(r.layout.objects[dresser])));
  // Without escape nothing separates them: the run reports what it got.
  options.planner.escape = false;
  const auto plain = design(scene, options);
  EXPECT_EQ(plain.unblock.separated, 0);
  if (!plain.valid) {
    EXPECT_NE(layout_violation(plain.layout), "");
  }
}

TEST(Design, CrowdedInvalidLayoutIsSeparatedByDisplacingSmallerObjects) {
  // The bedroom strewn with small boxes on a lattice 1.1 m apart: no spot of
  // the room holds the bed (checked below by brute force at 5 cm and every
  // quarter turn), and the bed starts on the fixed closet. Separating it
  // needs boxes moved out of its way: the bed takes a spot the boxes hold,
  // then they find spots of their own.
  Scene scene = geometry::load_scene(kBedroom);
  const int bed = scene.find_object("bed");
  int boxes = 0;
  for (double x = 0.3; x < 4.5; x += 1.1)
    for (double y = 0.3; y < 4.0; y += 1.1) {
      geometry::Object box;
      box.id = "box_" + std::to_string(boxes);
      box.footprint = {{-0.175, -0.175}, {0.175, -0.175}, {0.175, 0.175}, {-0.175, 0.175}};
      box.pose = {x, y, 0.0};
      scene.objects.push_back(box);
      const int k = static_cast<int>(scene.objects.size()) - 1;
      // Keep the boxes that are valid among the others without the bed.
      Scene probe = scene;
      probe.objects.erase(probe.objects.begin() + bed);
      if (object_violation(probe, k - 1).empty())
        ++boxes;
      else
        scene.objects.pop_back();
    }
  ASSERT_GE(boxes, 10);
  scene.objects[bed].pose = {1.2, 2.6, 0.0};
  ASSERT_NE(object_violation(scene, bed).find("closet"), std::string::npos)
      << object_violation(scene, bed);
  {
    Scene probe = scene;
    int free_spots = 0;
    for (double x = 0.0; x <= 4.5; x += 0.05)
      for (double y = 0.0; y <= 4.0; y += 0.05)
        for (int q = 0; q < 4; ++q) {
          probe.objects[bed].pose = {x, y, q * std::numbers::pi / 2};
          free_spots += object_violation(probe, bed).empty() ? 1 : 0;
        }
    ASSERT_EQ(free_spots, 0) << "the lattice leaves the bed a spot";
  }
  DesignOptions options;
  options.planner = hrs::optimize::PlannerConfig::from_preset("default");
  options.iterations = 10;
  const auto r = design(scene, options);
  EXPECT_GE(r.unblock.separated, 2);
  EXPECT_EQ(r.unblock.left_invalid, "");  // valid before the annealing
  EXPECT_TRUE(r.valid);
  EXPECT_EQ(layout_violation(r.layout), "");
  for (std::size_t i = 0; i < r.layout.objects.size(); ++i)
    EXPECT_EQ(object_violation(r.layout, static_cast<int>(i)), "") << r.layout.objects[i].id;
}

TEST(Design, SeparationEndsWithThePassThatPlacesNothing) {
  // A bed nearly as large as the room: with the fixed closet it fits
  // nowhere, and the objects it lies on find no spot beside it. The first
  // pass places nothing, so the layout is as it was and a second pass would
  // repeat the same scans: the separation stops there, and says why.
  Scene scene = geometry::load_scene(kBedroom);
  const int bed = scene.find_object("bed");
  scene.objects[bed].footprint = {{-2.1, -1.9}, {2.1, -1.9}, {2.1, 1.9}, {-2.1, 1.9}};
  scene.objects[bed].pose = {2.25, 2.0, 0.0};
  ASSERT_NE(object_violation(scene, bed), "");
  DesignOptions options;
  options.planner = hrs::optimize::PlannerConfig::from_preset("default");
  options.iterations = 5;
  const auto r = design(scene, options);
  EXPECT_EQ(r.unblock.separated, 0);
  EXPECT_EQ(r.unblock.separation_passes, 1);
  EXPECT_NE(r.unblock.left_invalid, "");
  EXPECT_FALSE(r.valid);
}

TEST(Design, ContactSheetCellsAreSizedFromTheDrawnCanvases) {
  // Two rooms of different sizes: the picture's size is the room's canvas
  // (design_picture), and the sheet's cells are as large as the largest.
  DesignResult small, large;
  small.layout = geometry::load_scene(kBedroom);
  large.layout = small.layout;
  for (auto& v : large.layout.room.polygon) v = {2.0 * v.x, 1.5 * v.y};
  const Picture a = design_picture(small, "a"), b = design_picture(large, "b");
  EXPECT_EQ(a.svg, design_svg(small, "a"));
  // Width grows by the room's extra 4.5 m, height by its extra 2 m, at
  // one scale: the canvases differ by exactly that.
  ASSERT_GT(a.width, 0.0);
  EXPECT_NEAR((b.width - a.width) / 4.5, (b.height - a.height) / 2.0, 1e-9);
  const std::string sheet = contact_sheet_svg({a, b, a}, 2);
  const auto attr = [&](std::size_t from, const std::string& name) {
    const auto p = sheet.find(name + "=\"", from);
    return std::stod(sheet.substr(p + name.size() + 2));
  };
  EXPECT_NEAR(attr(0, "width"), 2 * b.width, 0.01);
  EXPECT_NEAR(attr(0, "height"), 2 * b.height, 0.01);
  // The second picture sits one cell right; the third starts the second
  // row, one cell down.
  std::vector<std::size_t> at{0};
  for (int k = 0; k < 3; ++k) at.push_back(sheet.find("<svg x=", at.back() + 1));
  ASSERT_NE(at[3], std::string::npos);
  EXPECT_NEAR(attr(at[2], "x"), b.width, 0.01);
  EXPECT_NEAR(attr(at[2], "y"), 0.0, 0.01);
  EXPECT_NEAR(attr(at[3], "x"), 0.0, 0.01);
  EXPECT_NEAR(attr(at[3], "y"), b.height, 0.01);
}

// `file`'s scene as drawn on a plan turned by `degrees` about the origin:
// the room, the door, every pose (and the door's start pose, when given)
// turned; sizes, preferences and the AO graph as they were.
Scene turned_scene(const std::string& file, double degrees) {
  json j = json::parse(read(file));
  const double a = degrees * std::numbers::pi / 180.0, c = std::cos(a), s = std::sin(a);
  const auto turn = [&](json& p) {
    const double x = p[0].get<double>(), y = p[1].get<double>();
    p[0] = c * x - s * y;
    p[1] = s * x + c * y;
    if (p.size() == 3) p[2] = p[2].get<double>() + a;
  };
  json& room = j["room"];
  if (room.contains("size")) {
    const double w = room["size"][0].get<double>(), h = room["size"][1].get<double>();
    room.erase("size");
    room["polygon"] = json::array({{0.0, 0.0}, {w, 0.0}, {w, h}, {0.0, h}});
  }
  for (json& v : room["polygon"]) turn(v);
  turn(j["door"]["center"]);
  if (j["door"].contains("start")) turn(j["door"]["start"]);
  for (json& o : j["objects"]) turn(o["pose"]);
  return geometry::parse_scene(j.dump(), file);
}

// A plan need not be drawn with its walls on the axes. The same room turned
// by 30° and 90° designs as well as the axis-parallel one (seed 1, default
// preset): every tour found, by the exact reference in the written files,
// and at most one preference fewer met than the axis-parallel design
// (measured: every bedroom design meets 10 of 10, every office design 11
// of 11; docs/BENCHMARKS.md, 2026-11-30, "plans drawn at an angle").
TEST(Design, RoomsDrawnAtAnAngleDesignAsWellAsAxisParallelOnes) {
  for (const char* name : {"bedroom", "office"}) {
    const std::string file = std::string(HRSPACE_SOURCE_DIR) + "/scenes/" + name + ".json";
    int axis_met = -1;
    for (const double degrees : {0.0, 30.0, 90.0}) {
      const Scene scene = turned_scene(file, degrees);
      DesignOptions options;
      options.seed = 1;
      options.threads = 2;
      const auto r = design(scene, options);
      const std::string label = std::string(name) + " turned " + std::to_string(static_cast<int>(degrees)) + "°";
      ASSERT_TRUE(r.valid) << label;
      const auto dir = test_support::scratch_path("design_turned");
      std::filesystem::remove_all(dir);
      write_design(r, {1, "default", options.iterations}, dir);
      const int found = check_design_dir(scene, dir);
      EXPECT_EQ(found, scene.activity.sequences) << label;
      EXPECT_EQ(r.final.tours_found, found) << label;
      std::printf("%s: cost %.4f, tours %d/%d, preferences %d/%d\n", label.c_str(), r.final.total(),
                  found, scene.activity.sequences, r.preferences.met, r.preferences.total);
      if (degrees == 0.0) axis_met = r.preferences.met;
      EXPECT_GE(r.preferences.met, axis_met - 1) << label << ": " << r.preferences.met << " of "
                                                 << r.preferences.total << " met";
    }
  }
}

TEST(Design, StopFlagEndsTheRunAndKeepsTheBest) {
  const Scene scene = geometry::load_scene(kBedroom);
  std::atomic<bool> stop{false};
  DesignOptions options;
  options.planner = hrs::optimize::PlannerConfig::from_preset("baseline");
  options.iterations = 100;
  int calls = 0;
  const auto r = design(scene, options, &stop, [&](const DesignStep&) {
    if (++calls == 3) stop.store(true);
  });
  EXPECT_TRUE(r.stopped);
  EXPECT_EQ(r.proposals, 3);
  EXPECT_TRUE(r.valid);
}

}  // namespace
}  // namespace hrs::optimize
