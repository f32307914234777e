// SPDX-License-Identifier: GPL-3.0-or-later
// What a scene derives from its data: polygon areas, world footprints, and
// the door helpers (inward normal, clear zone, start pose) against hand values.

#include <gtest/gtest.h>

#include <numbers>

#include "geometry/scene.h"
#include "tests/geometry/scene_fixture.h"

namespace hrs::geometry {
namespace {

using scene_fixture::base;
using scene_fixture::erase;
using scene_fixture::Json;
using scene_fixture::parse;
using scene_fixture::set;

constexpr double kPi = std::numbers::pi;

TEST(SceneGeometry, SignedAreaIsPositiveForCounterClockwise) {
  const Polygon square{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  EXPECT_DOUBLE_EQ(signed_area(square), 4.0);
  EXPECT_DOUBLE_EQ(signed_area(Polygon{{0, 0}, {0, 2}, {2, 2}, {2, 0}}), -4.0);
  EXPECT_DOUBLE_EQ(signed_area(Polygon{{0, 0}, {5, 0}, {5, 2}, {2, 2}, {2, 4}, {0, 4}}), 14.0);
}

TEST(SceneGeometry, FootprintRotatesThenTranslates) {
  Object o;
  o.footprint = {{-1, -0.5}, {1, -0.5}, {1, 0.5}, {-1, 0.5}};
  o.pose = {3.0, 2.0, kPi / 2};
  const Polygon r = rotated_footprint(o);
  const Polygon w = world_footprint(o);
  const Polygon expected{{3.5, 1.0}, {3.5, 3.0}, {2.5, 3.0}, {2.5, 1.0}};
  ASSERT_EQ(w.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(w[i].x, expected[i].x, 1e-12);
    EXPECT_NEAR(w[i].y, expected[i].y, 1e-12);
    EXPECT_EQ(w[i], r[i] + o.pose.position());  // exactly rotated + position
  }
}

TEST(SceneGeometry, DoorHelpersOnTheBottomWall) {
  const Scene s = parse(base());  // door at (1, 0) on the edge (0,0)->(5,0)
  const Vec2 n = door_inward_normal(s);
  EXPECT_NEAR(n.x, 0.0, 1e-15);
  EXPECT_NEAR(n.y, 1.0, 1e-15);
  const Polygon zone = door_clear_zone(s);
  const Polygon expected{{0.55, 0.0}, {1.45, 0.0}, {1.45, 1.2}, {0.55, 1.2}};
  ASSERT_EQ(zone.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(zone[i].x, expected[i].x, 1e-12) << i;
    EXPECT_NEAR(zone[i].y, expected[i].y, 1e-12) << i;
  }
  EXPECT_GT(signed_area(zone), 0.0);
  const Pose2 start = door_start_pose(s);  // 1.1 / 2 + 0.05 inside, facing +y
  EXPECT_NEAR(start.x, 1.0, 1e-12);
  EXPECT_NEAR(start.y, 0.6, 1e-12);
  EXPECT_NEAR(start.theta, kPi / 2, 1e-12);
}

TEST(SceneGeometry, DoorHelpersOnTheLeftWall) {
  Json j = base();
  set(j, "/door/center", Json::array({0.0, 2.0}));  // edge (0,4)->(0,0): inward is +x
  const Scene s = parse(j);
  const Vec2 n = door_inward_normal(s);
  EXPECT_NEAR(n.x, 1.0, 1e-15);
  EXPECT_NEAR(n.y, 0.0, 1e-15);
  const Pose2 start = door_start_pose(s);
  EXPECT_NEAR(start.x, 0.6, 1e-12);
  EXPECT_NEAR(start.y, 2.0, 1e-12);
  EXPECT_NEAR(start.theta, 0.0, 1e-12);
  const Polygon zone = door_clear_zone(s);
  double min_x = 1e9, max_x = -1e9, min_y = 1e9, max_y = -1e9;
  for (Vec2 v : zone) {
    min_x = std::min(min_x, v.x), max_x = std::max(max_x, v.x);
    min_y = std::min(min_y, v.y), max_y = std::max(max_y, v.y);
  }
  EXPECT_NEAR(min_x, 0.0, 1e-12);
  EXPECT_NEAR(max_x, 1.2, 1e-12);
  EXPECT_NEAR(min_y, 1.55, 1e-12);
  EXPECT_NEAR(max_y, 2.45, 1e-12);
}

TEST(SceneGeometry, DoorOnTheInnerEdgeOfAnLShapedRoomFacesDown) {
  Json j = base();
  set(j, "/room/polygon", Json::parse("[[0,0],[5,0],[5,2],[2,2],[2,4],[0,4]]"));
  set(j, "/door/center", Json::array({3.5, 2.0}));  // edge (5,2)->(2,2)
  set(j, "/objects", Json::parse(R"([{"id": "desk", "size": [0.8, 1.6], "pose": [1, 3, 0]}])"));
  set(j, "/activity/transitions", Json::parse(R"({"door": {"desk": 1}})"));
  erase(j, "", "relations");
  Scene s = parse(j);
  const Vec2 n = door_inward_normal(s);
  EXPECT_NEAR(n.x, 0.0, 1e-15);
  EXPECT_NEAR(n.y, -1.0, 1e-15);
  Pose2 start = door_start_pose(s);
  EXPECT_NEAR(start.x, 3.5, 1e-12);
  EXPECT_NEAR(start.y, 1.4, 1e-12);
  EXPECT_NEAR(start.theta, -kPi / 2, 1e-12);
  s.door.start = Pose2{3.0, 1.0, 0.5};  // an explicit start wins
  EXPECT_EQ(door_start_pose(s), (Pose2{3.0, 1.0, 0.5}));
}

}  // namespace
}  // namespace hrs::geometry
