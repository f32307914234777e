// SPDX-License-Identifier: GPL-3.0-or-later
// Scene format rules of the document, the room, the door and the wheelchair:
// one broken scene per rule of scene-format.md, each of which must name the
// file, the exact JSON pointer and what is wrong.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "geometry/error.h"
#include "geometry/scene.h"
#include "tests/geometry/scene_fixture.h"
#include "tests/support/scratch.h"

namespace hrs::geometry {
namespace {

using scene_fixture::base;
using scene_fixture::erase;
using scene_fixture::expect_broken;
using scene_fixture::expect_rejected;
using scene_fixture::Json;
using scene_fixture::kBase;
using scene_fixture::parse;
using scene_fixture::set;

// ---- document ---------------------------------------------------------------

TEST(SceneRules, InvalidJsonIsRejected) {
  expect_rejected("{\"format\": \"hrspace-scene/1\",", "", "invalid JSON");
}
TEST(SceneRules, NaNLiteralIsInvalidJson) {
  expect_rejected("{\"name\": NaN}", "", "invalid JSON");
}
TEST(SceneRules, OverflowingNumberIsRejected) {
  std::string text = base().dump();
  text.replace(text.find("0.65"), 4, "1e999");
  expect_rejected(text, "", "overflow");
}
TEST(SceneRules, EmptyFileIsRejected) {
  expect_rejected("", "", "empty");
  expect_rejected("  \n ", "", "empty");
}
TEST(SceneRules, MissingFileIsRejected) {
  const std::string path = "/nonexistent/hrspace/none.json";
  try {
    load_scene(path);
    FAIL() << "loaded a missing file";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("cannot open"), std::string::npos) << e.what();
  }
}
TEST(SceneRules, LoadSceneNamesThePathInMessages) {
  const auto path = test_support::scratch_path("scene_test_broken.json");
  {
    Json j = base();
    set(j, "/objects/3/size/0", -1);
    std::ofstream(path) << j.dump(2);
  }
  try {
    load_scene(path.string());
    FAIL() << "accepted a negative size";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path.string() + ": /objects/3/size/0: must be > 0, got -1.0");
  }
  std::filesystem::remove(path);
}
TEST(SceneRules, TopLevelMustBeAnObject) { expect_rejected("[1, 2]", "", "JSON object"); }
TEST(SceneRules, DuplicateKeyIsRejected) {
  std::string text = kBase;
  text.replace(text.find("\"fixed\": true }"), 15, "\"fixed\": true, \"fixed\": false }");
  expect_rejected(text, "/objects/1/fixed", "duplicate");
}
TEST(SceneRules, FormatIsRequired) {
  expect_broken([](Json& j) { erase(j, "", "format"); }, "/format", "missing");
}
TEST(SceneRules, FormatMustBeVersionOne) {
  expect_broken([](Json& j) { set(j, "/format", "hrspace-scene/2"); }, "/format", "unsupported");
}
TEST(SceneRules, NameIsRequired) {
  expect_broken([](Json& j) { erase(j, "", "name"); }, "/name", "missing");
}
TEST(SceneRules, NameMustBeAString) {
  expect_broken([](Json& j) { set(j, "/name", 3); }, "/name", "string");
}
TEST(SceneRules, UnknownTopLevelFieldIsRejected) {
  expect_broken([](Json& j) { set(j, "/objetcs", Json::array()); }, "/objetcs", "unknown field");
}
TEST(SceneRules, UnknownNestedFieldsAreRejected) {
  expect_broken([](Json& j) { set(j, "/room/height", 2.5); }, "/room/height", "unknown field");
  expect_broken([](Json& j) { set(j, "/door/hinge", "left"); }, "/door/hinge", "unknown field");
  expect_broken([](Json& j) { set(j, "/wheelchair/mass", 90); }, "/wheelchair/mass",
                "unknown field");
  expect_broken([](Json& j) { set(j, "/objects/0/colour", "red"); }, "/objects/0/colour",
                "unknown field");
  expect_broken([](Json& j) { set(j, "/objects/0/wall/side", 1); }, "/objects/0/wall/side",
                "unknown field");
  expect_broken([](Json& j) { set(j, "/objects/0/approach/gaps", 1); }, "/objects/0/approach/gaps",
                "unknown field");
  expect_broken([](Json& j) { set(j, "/relations/0/c", "x"); }, "/relations/0/c", "unknown field");
  expect_broken([](Json& j) { set(j, "/activity/steps", 2); }, "/activity/steps", "unknown field");
  expect_broken([](Json& j) { set(j, "/weights/wall", Json::array({1})); }, "/weights/wall",
                "unknown field");
}
TEST(SceneRules, CommentIsAllowedAnywhere) {
  Json j = base();
  for (const char* p : {"/room", "/door", "/wheelchair", "/objects/0", "/objects/0/wall",
                        "/objects/0/approach", "/relations/0", "/activity", "/activity/transitions",
                        "/activity/transitions/door", "/weights"}) {
    set(j, std::string(p) + "/comment", "a note");
  }
  EXPECT_EQ(parse(j), parse(base()));
}

// ---- room -------------------------------------------------------------------

TEST(SceneRules, RoomIsRequired) {
  expect_broken([](Json& j) { erase(j, "", "room"); }, "/room", "missing");
}
TEST(SceneRules, RoomNeedsPolygonOrSize) {
  expect_broken([](Json& j) { erase(j, "/room", "polygon"); }, "/room/polygon", "missing");
}
TEST(SceneRules, RoomCannotHaveBothPolygonAndSize) {
  expect_broken(
      [](Json& j) {
        set(j, "/room/size", Json::array({5, 4}));
      },
      "/room/size", "not both");
}
TEST(SceneRules, RoomSizeMustBePositive) {
  expect_broken(
      [](Json& j) {
        erase(j, "/room", "polygon");
        set(j, "/room/size", Json::array({5, 0}));
      },
      "/room/size/1", "> 0");
}
TEST(SceneRules, RoomSizeBecomesRectangle) {
  Json j = base();
  erase(j, "/room", "polygon");
  set(j, "/room/size", Json::array({5, 4}));
  const Scene s = parse(j);
  EXPECT_EQ(s.room.polygon, (Polygon{{0, 0}, {5, 0}, {5, 4}, {0, 4}}));
  ASSERT_TRUE(s.room.size.has_value());
  EXPECT_EQ(*s.room.size, (std::array<double, 2>{5, 4}));
}
TEST(SceneRules, RoomNeedsThreeVertices) {
  expect_broken([](Json& j) { set(j, "/room/polygon", Json::parse("[[0,0],[5,0]]")); },
                "/room/polygon", "at least 3");
}
TEST(SceneRules, RoomVertexMustBeAPoint) {
  expect_broken(
      [](Json& j) {
        set(j, "/room/polygon/2", Json::array({5, 4, 0}));
      },
      "/room/polygon/2", "point");
}
TEST(SceneRules, RoomMustBeSimple) {
  expect_broken([](Json& j) { set(j, "/room/polygon", Json::parse("[[0,0],[5,0],[0,4],[5,4]]")); },
                "/room/polygon", "simple");
}
TEST(SceneRules, RoomMustBeCounterClockwise) {
  expect_broken([](Json& j) { set(j, "/room/polygon", Json::parse("[[0,0],[0,4],[5,4],[5,0]]")); },
                "/room/polygon", "clockwise");
}

// ---- door and wheelchair ----------------------------------------------------

TEST(SceneRules, DoorIsRequired) {
  expect_broken([](Json& j) { erase(j, "", "door"); }, "/door", "missing");
}
TEST(SceneRules, DoorCenterIsRequired) {
  expect_broken([](Json& j) { erase(j, "/door", "center"); }, "/door/center", "missing");
}
TEST(SceneRules, DoorCenterMustBeOnTheBoundary) {
  expect_broken(
      [](Json& j) {
        set(j, "/door/center", Json::array({1.0, 0.01}));
      },
      "/door/center", "boundary");
  expect_broken(
      [](Json& j) {
        set(j, "/door/center", Json::array({1.0, -0.5}));
      },
      "/door/center", "boundary");
}
TEST(SceneRules, DoorCenterWithinToleranceIsAccepted) {
  Json j = base();
  set(j, "/door/center", Json::array({1.0, 5e-7}));
  EXPECT_NO_THROW(parse(j));
}
TEST(SceneRules, DoorWidthMustFitOnItsWall) {
  expect_broken([](Json& j) { set(j, "/door/width", 2.2); }, "/door/width", "does not fit");
}
TEST(SceneRules, DoorWidthMustBePositive) {
  expect_broken([](Json& j) { set(j, "/door/width", 0); }, "/door/width", "> 0");
}
TEST(SceneRules, DoorClearDepthMustBePositive) {
  expect_broken([](Json& j) { set(j, "/door/clear_depth", -1.2); }, "/door/clear_depth", "> 0");
}
TEST(SceneRules, DoorStartMustBeAPose) {
  expect_broken([](Json& j) { set(j, "/door/start", Json::array({1, 1})); }, "/door/start", "pose");
  expect_broken(
      [](Json& j) {
        set(j, "/door/start", Json::array({1, 1, "up"}));
      },
      "/door/start/2", "number");
}
TEST(SceneRules, WheelchairDimensionsMustBePositive) {
  expect_broken([](Json& j) { set(j, "/wheelchair/length", 0); }, "/wheelchair/length", "> 0");
  expect_broken([](Json& j) { set(j, "/wheelchair/width", -0.65); }, "/wheelchair/width", "> 0");
  expect_broken([](Json& j) { set(j, "/wheelchair/turning_radius", 0.0); },
                "/wheelchair/turning_radius", "> 0");
}
TEST(SceneRules, WheelchairFieldsAreRequired) {
  expect_broken([](Json& j) { erase(j, "/wheelchair", "turning_radius"); },
                "/wheelchair/turning_radius", "missing");
  expect_broken([](Json& j) { erase(j, "", "wheelchair"); }, "/wheelchair", "missing");
}

}  // namespace
}  // namespace hrs::geometry
