// SPDX-License-Identifier: GPL-3.0-or-later
// Writing scenes: load -> write -> load gives the same scene and the same
// text, for every shipped scene file and for scenes using every optional field.

#include <gtest/gtest.h>

#include <string>

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
using scene_fixture::set;

void expect_round_trip(const Scene& scene, const std::string& label) {
  const std::string text = write_scene(scene);
  const Scene again = parse_scene(text, label + " (written)");
  EXPECT_EQ(again, scene) << label;
  EXPECT_EQ(write_scene(again), text) << label;
}

TEST(SceneRoundTrip, EverySceneFileLoadsWritesAndLoadsEqual) {
  const auto files = scene_files();
  ASSERT_GE(files.size(), 5u);
  for (const auto& path : files) {
    SCOPED_TRACE(path.string());
    const Scene scene = load_scene(path.string());
    expect_round_trip(scene, path.string());
  }
}

TEST(SceneRoundTrip, LShapedRoomWithNonConvexObjectAndAllOptionalFields) {
  Json j = base();
  set(j, "/room/polygon", Json::parse("[[0,0],[5,0],[5,2],[2,2],[2,4],[0,4]]"));
  set(j, "/door/center", Json::array({3.5, 2.0}));
  set(j, "/door/start", Json::array({3.5, 1.3, -1.5707963267948966}));
  set(j, "/objects", Json::parse(R"([
    {"id": "sofa", "polygon": [[-0.45,-1.2],[1.15,-1.2],[1.15,-0.4],[0.45,-0.4],[0.45,1.2],[-0.45,1.2]],
     "pose": [0.6, 2.0, 0.1], "wall": {"angle": 0.25}, "approach": {"sides": ["front", "left"], "gap": 0}},
    {"id": "tv", "size": [0.4, 1.2], "pose": [4.7, 1.0, 3.0], "fixed": true, "wall": {"distance": 0.05}},
    {"id": "lamp", "size": [0.3, 0.3], "pose": [1.1, 3.6, 0.7853981633974483]}])"));
  set(j, "/relations", Json::parse(R"([{"a": "tv", "b": "sofa", "angle": 3.141592653589793},
    {"a": "lamp", "b": "sofa", "distance": 1.2, "angle": -0.3, "weight": 2}])"));
  set(j, "/activity/transitions", Json::parse(R"({"door": {"sofa": 0.1, "tv": 0.2, "lamp": 0.7},
    "sofa": {"sofa": 0.3333333333333333, "tv": 0.6666666666666667}, "lamp": {"tv": 1}})"));
  const Scene scene = parse(j);
  ASSERT_EQ(scene.objects[0].footprint.size(), 6u);
  EXPECT_GT(convex_partition(scene.objects[0].footprint).size(), 1u);  // really non-convex
  expect_round_trip(scene, "L-shaped");
}

TEST(SceneRoundTrip, RoomSizeShorthandIsKept) {
  Json j = base();
  erase(j, "/room", "polygon");
  set(j, "/room/size", Json::array({5, 4}));
  const Scene scene = parse(j);
  const std::string text = write_scene(scene);
  EXPECT_NE(text.find("\"size\""), std::string::npos);
  EXPECT_EQ(Json::parse(text)["room"].count("polygon"), 0u);
  expect_round_trip(scene, "size room");
}

}  // namespace
}  // namespace hrs::geometry
