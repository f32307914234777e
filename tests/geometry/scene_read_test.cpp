// SPDX-License-Identifier: GPL-3.0-or-later
// Reading scene files (`hrspace-scene/1`): the base scene's fields and the
// defaults of absent optional fields, and the shipped scene files in scenes/
// (their door clear zones, start poses and the variants they pair up as).

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "geometry/polygon_ops.h"
#include "geometry/scene.h"
#include "tests/geometry/scene_fixture.h"

namespace hrs::geometry {
namespace {

using scene_fixture::base;
using scene_fixture::erase;
using scene_fixture::Json;
using scene_fixture::parse;
using scene_fixture::scene_files;

TEST(SceneParse, BaseSceneIsValid) {
  const Scene s = parse(base());
  EXPECT_EQ(s.name, "base");
  ASSERT_EQ(s.objects.size(), 4u);
  EXPECT_EQ(s.objects[1].id, "shelf");
  EXPECT_TRUE(s.objects[1].fixed);
  EXPECT_FALSE(s.objects[0].fixed);
  EXPECT_EQ(s.objects[2].footprint.size(), 3u);
  EXPECT_FALSE(s.objects[2].size.has_value());
  EXPECT_EQ(s.activity.transitions.at("shelf").at("plant"), 0.3);
  EXPECT_EQ(s.activity.sequences, 4);
  EXPECT_EQ(s.weights.path[1], 2.0);
  EXPECT_EQ(s.relations[0].weight, 0.5);
  EXPECT_FALSE(s.relations[0].angle.has_value());
  EXPECT_EQ(s.find_object("table"), 3);
  EXPECT_EQ(s.find_object("door"), -1);
  // size [depth, width]: depth along local x (front), width along local y.
  const Polygon desk = s.objects[0].footprint;
  EXPECT_EQ(desk, (Polygon{{-0.4, -0.8}, {0.4, -0.8}, {0.4, 0.8}, {-0.4, 0.8}}));
}

TEST(SceneParse, DefaultsApplyWhenOptionalFieldsAreAbsent) {
  Json j = base();
  erase(j, "/door", "clear_depth");
  erase(j, "", "weights");
  erase(j, "/activity", "sequences");
  erase(j, "/activity", "visits");
  erase(j, "", "relations");
  const Scene s = parse(j);
  EXPECT_EQ(s.door.clear_depth, 1.2);
  EXPECT_EQ(s.weights, Weights{});
  EXPECT_EQ(s.activity.sequences, 10);
  EXPECT_EQ(s.activity.visits, 3);
  EXPECT_FALSE(s.objects[3].approach.has_value());
  EXPECT_EQ(s.objects[3].approach_or_default(), Approach{});
}

// ---- scene files --------------------------------------------------------------

TEST(SceneFiles, DoorClearZoneIsFreeOfFurniture) {
  for (const auto& path : scene_files()) {
    const Scene scene = load_scene(path.string());
    const Polygon zone = door_clear_zone(scene);
    EXPECT_TRUE(polygon_inside(zone, scene.room.polygon)) << path;
    for (const Object& o : scene.objects) {
      EXPECT_FALSE(interiors_overlap(world_footprint(o), zone)) << path << ": " << o.id;
    }
  }
}

TEST(SceneFiles, DefaultStartFootprintLiesInTheDoorClearZone) {
  // The zone is kept free of furniture, so the chair can always start there.
  for (const auto& path : scene_files()) {
    const Scene scene = load_scene(path.string());
    Object chair;
    chair.footprint = {{-0.5 * scene.wheelchair.length, -0.5 * scene.wheelchair.width},
                       {0.5 * scene.wheelchair.length, -0.5 * scene.wheelchair.width},
                       {0.5 * scene.wheelchair.length, 0.5 * scene.wheelchair.width},
                       {-0.5 * scene.wheelchair.length, 0.5 * scene.wheelchair.width}};
    chair.pose = door_start_pose(scene);
    EXPECT_TRUE(polygon_inside(world_footprint(chair), door_clear_zone(scene))) << path;
  }
}

TEST(SceneFiles, SmallBedroomHasWallsTwentyPercentShorter) {
  const Scene big = load_scene(HRSPACE_SOURCE_DIR "/scenes/bedroom.json");
  const Scene small = load_scene(HRSPACE_SOURCE_DIR "/scenes/small_bedroom.json");
  EXPECT_NEAR(signed_area(small.room.polygon), 0.64 * signed_area(big.room.polygon), 1e-9);
  EXPECT_NEAR(small.door.center.x, 0.8 * big.door.center.x, 1e-9);
  ASSERT_EQ(small.objects.size(), big.objects.size());
  for (std::size_t i = 0; i < big.objects.size(); ++i) {
    EXPECT_EQ(small.objects[i].id, big.objects[i].id);
    EXPECT_EQ(small.objects[i].footprint, big.objects[i].footprint);
  }
}

TEST(SceneFiles, OfficeVariantsDifferInTheFrequentTable) {
  const Scene a = load_scene(HRSPACE_SOURCE_DIR "/scenes/office.json");
  const Scene b = load_scene(HRSPACE_SOURCE_DIR "/scenes/office_round_table.json");
  EXPECT_EQ(a.objects, b.objects);
  auto inflow = [](const Scene& s, const std::string& id) {
    double sum = 0.0;
    for (const auto& [from, row] : s.activity.transitions) {
      if (const auto it = row.find(id); it != row.end()) sum += it->second;
    }
    return sum;
  };
  EXPECT_GT(inflow(a, "office_table"), inflow(a, "round_table"));
  EXPECT_GT(inflow(b, "round_table"), inflow(b, "office_table"));
}

}  // namespace
}  // namespace hrs::geometry
