// Scene format `hrspace-scene/1`: one broken scene per rule of scene-format.md
// (each must name the file, the exact JSON pointer and what is wrong), the
// load -> write -> load round trip, and the door helpers against hand values.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "geometry/error.h"
#include "geometry/polygon_ops.h"
#include "geometry/scene.h"

namespace hrs::geometry {
namespace {

using Json = nlohmann::json;
using Ptr = Json::json_pointer;
constexpr double kPi = std::numbers::pi;

//! A valid scene touching every section; each test breaks one rule of it.
const char* const kBase = R"({
  "format": "hrspace-scene/1",
  "name": "base",
  "comment": "test fixture",
  "room": { "polygon": [[0, 0], [5, 0], [5, 4], [0, 4]] },
  "door": { "center": [1.0, 0.0], "width": 0.9, "clear_depth": 1.2 },
  "wheelchair": { "length": 1.1, "width": 0.65, "turning_radius": 0.7 },
  "objects": [
    { "id": "desk", "size": [0.8, 1.6], "pose": [2.5, 3.5, -1.5707963267948966],
      "wall": { "distance": 0.0, "angle": 0.0 },
      "approach": { "sides": ["front"], "gap": 0.1 } },
    { "id": "shelf", "size": [0.4, 1.0], "pose": [4.7, 2.0, 3.141592653589793], "fixed": true },
    { "id": "plant", "polygon": [[0, 0], [0.4, 0], [0.2, 0.3]], "pose": [0.3, 3.5, 0.0],
      "fixed": true },
    { "id": "table", "size": [0.8, 0.8], "pose": [3.0, 1.5, 0.0] }
  ],
  "relations": [ { "a": "table", "b": "desk", "distance": 2.0, "weight": 0.5 } ],
  "activity": {
    "transitions": {
      "door":  { "desk": 0.5, "table": 0.3, "shelf": 0.2 },
      "desk":  { "desk": 0.2, "table": 0.4, "shelf": 0.4 },
      "table": { "desk": 1.0 },
      "shelf": { "desk": 0.7, "plant": 0.3 }
    },
    "sequences": 4,
    "visits": 2
  },
  "weights": { "path": [1, 2, 0.5], "interior": [1, 1] }
})";

const std::string kLabel = "scenes/base.json";

Json base() { return Json::parse(kBase); }

Scene parse(const Json& j) { return parse_scene(j.dump(2), kLabel); }

//! Expects `text` to be rejected with one line naming the file, the pointer and `word`.
void expect_rejected(const std::string& text, const std::string& pointer, const std::string& word) {
  try {
    parse_scene(text, kLabel);
    FAIL() << "accepted a broken scene; expected an error at " << pointer;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    const std::string head = pointer.empty() ? kLabel + ": " : kLabel + ": " + pointer + ": ";
    EXPECT_EQ(msg.rfind(head, 0), 0u) << msg;
    EXPECT_NE(msg.find(word), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  }
}

//! Mutates the base scene and expects the error at `pointer` mentioning `word`.
void expect_broken(const std::function<void(Json&)>& mutate, const std::string& pointer,
                   const std::string& word) {
  Json j = base();
  mutate(j);
  expect_rejected(j.dump(2), pointer, word);
}

void set(Json& j, const std::string& pointer, Json value) { j[Ptr(pointer)] = std::move(value); }
void erase(Json& j, const std::string& parent, const std::string& key) {
  j[Ptr(parent)].erase(key);
}

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
  const auto path = std::filesystem::temp_directory_path() / "hrspace_scene_test_broken.json";
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

// ---- objects ----------------------------------------------------------------

TEST(SceneRules, ObjectsAreRequired) {
  expect_broken([](Json& j) { erase(j, "", "objects"); }, "/objects", "missing");
  expect_broken([](Json& j) { set(j, "/objects", Json::object()); }, "/objects", "array");
}
TEST(SceneRules, ObjectIdIsRequired) {
  expect_broken([](Json& j) { erase(j, "/objects/2", "id"); }, "/objects/2/id", "missing");
}
TEST(SceneRules, ObjectIdsMustBeUnique) {
  expect_broken([](Json& j) { set(j, "/objects/3/id", "desk"); }, "/objects/3/id", "duplicate");
}
TEST(SceneRules, ObjectIdDoorIsReserved) {
  expect_broken([](Json& j) { set(j, "/objects/3/id", "door"); }, "/objects/3/id", "reserved");
}
TEST(SceneRules, ObjectIdMustNotBeEmpty) {
  expect_broken([](Json& j) { set(j, "/objects/3/id", ""); }, "/objects/3/id", "empty");
}
TEST(SceneRules, ObjectNeedsSizeOrPolygon) {
  expect_broken([](Json& j) { erase(j, "/objects/3", "size"); }, "/objects/3/size", "missing");
}
TEST(SceneRules, ObjectCannotHaveBothSizeAndPolygon) {
  expect_broken(
      [](Json& j) {
        set(j, "/objects/2/size", Json::array({1, 1}));
      },
      "/objects/2/polygon", "not both");
}
TEST(SceneRules, ObjectSizeMustBePositive) {
  expect_broken([](Json& j) { set(j, "/objects/3/size/0", -1); }, "/objects/3/size/0",
                "must be > 0, got -1");
}
TEST(SceneRules, ObjectSizeMustHaveTwoNumbers) {
  expect_broken(
      [](Json& j) {
        set(j, "/objects/3/size", Json::array({1, 1, 1}));
      },
      "/objects/3/size", "[depth, width]");
  expect_broken([](Json& j) { set(j, "/objects/3/size/1", "0.8"); }, "/objects/3/size/1", "number");
}
TEST(SceneRules, ObjectPolygonNeedsThreeVertices) {
  expect_broken([](Json& j) { set(j, "/objects/2/polygon", Json::parse("[[0,0],[0.4,0]]")); },
                "/objects/2/polygon", "at least 3");
}
TEST(SceneRules, ObjectPolygonMustBeSimple) {
  expect_broken(
      [](Json& j) {
        set(j, "/objects/2/polygon", Json::parse("[[0,0],[0.4,0],[0,0.3],[0.4,0.3]]"));
      },
      "/objects/2/polygon", "simple");
}
TEST(SceneRules, ObjectPolygonMustBeCounterClockwise) {
  expect_broken(
      [](Json& j) { set(j, "/objects/2/polygon", Json::parse("[[0,0],[0.2,0.3],[0.4,0]]")); },
      "/objects/2/polygon", "clockwise");
}
TEST(SceneRules, ObjectPoseIsRequired) {
  expect_broken([](Json& j) { erase(j, "/objects/1", "pose"); }, "/objects/1/pose", "missing");
}
TEST(SceneRules, ObjectPoseMustHaveThreeNumbers) {
  expect_broken(
      [](Json& j) {
        set(j, "/objects/1/pose", Json::array({4.7, 2.0}));
      },
      "/objects/1/pose", "pose");
  expect_broken([](Json& j) { set(j, "/objects/1/pose/2", nullptr); }, "/objects/1/pose/2",
                "number");
}
TEST(SceneRules, ObjectMustBeInsideTheRoom) {
  // The table pokes 0.1 m through the right wall.
  expect_broken([](Json& j) { set(j, "/objects/3/pose/0", 4.7); }, "/objects/3/pose", "inside");
  // Rotating the desk by 90 degrees puts its 1.6 m width across the top wall.
  expect_broken([](Json& j) { set(j, "/objects/0/pose/2", 0.0); }, "/objects/0/pose", "inside");
}
TEST(SceneRules, ObjectInsideLShapedRoomMustAvoidTheNotch) {
  Json j = base();
  set(j, "/room/polygon", Json::parse("[[0,0],[5,0],[5,2],[2,2],[2,4],[0,4]]"));
  set(j, "/objects", Json::parse(R"([{"id": "desk", "size": [0.8, 1.6], "pose": [3.5, 1.0, 0]}])"));
  set(j, "/activity/transitions", Json::parse(R"({"door": {"desk": 1}})"));
  erase(j, "", "relations");
  EXPECT_NO_THROW(parse(j));
  set(j, "/objects/0/pose", Json::array({3.0, 2.5, 0}));  // in the bounding box, not the room
  expect_rejected(j.dump(), "/objects/0/pose", "inside");
}
TEST(SceneRules, FixedObjectsMustNotOverlap) {
  // The shelf moves onto the plant (both fixed).
  expect_broken(
      [](Json& j) {
        set(j, "/objects/2/pose", Json::array({4.5, 1.8, 0.0}));
      },
      "/objects/2/pose", "overlaps");
}
TEST(SceneRules, MovableObjectsMayOverlap) {
  Json j = base();
  set(j, "/objects/3/pose", Json::array({2.5, 3.2, 0.0}));  // table onto the desk
  EXPECT_NO_THROW(parse(j));
  set(j, "/objects/3/pose", Json::array({4.5, 2.0, 0.0}));  // movable table onto fixed shelf
  EXPECT_NO_THROW(parse(j));
}
TEST(SceneRules, FixedMustBeABoolean) {
  expect_broken([](Json& j) { set(j, "/objects/1/fixed", 1); }, "/objects/1/fixed",
                "true or false");
}
TEST(SceneRules, WallDistanceMustBeNonNegative) {
  expect_broken([](Json& j) { set(j, "/objects/0/wall/distance", -0.1); },
                "/objects/0/wall/distance", ">= 0");
}
TEST(SceneRules, WallAngleMustBeANumber) {
  expect_broken([](Json& j) { set(j, "/objects/0/wall/angle", "back"); }, "/objects/0/wall/angle",
                "number");
}
TEST(SceneRules, ApproachSidesMustBeKnown) {
  expect_broken(
      [](Json& j) {
        set(j, "/objects/0/approach/sides", Json::array({"front", "top"}));
      },
      "/objects/0/approach/sides/1", "unknown side");
}
TEST(SceneRules, ApproachSidesMustNotRepeat) {
  expect_broken(
      [](Json& j) {
        set(j, "/objects/0/approach/sides", Json::array({"left", "front", "left"}));
      },
      "/objects/0/approach/sides/2", "duplicate");
}
TEST(SceneRules, ApproachSidesMustNotBeEmpty) {
  expect_broken([](Json& j) { set(j, "/objects/0/approach/sides", Json::array()); },
                "/objects/0/approach/sides", "at least one");
}
TEST(SceneRules, ApproachGapMustBeNonNegative) {
  expect_broken([](Json& j) { set(j, "/objects/0/approach/gap", -0.05); },
                "/objects/0/approach/gap", ">= 0");
}
TEST(SceneRules, ApproachSidesAreParsed) {
  Json j = base();
  set(j, "/objects/0/approach/sides", Json::array({"right", "back"}));
  erase(j, "/objects/0/approach", "gap");
  const Approach a = *parse(j).objects[0].approach;
  EXPECT_EQ(a.sides, (std::array<bool, 4>{false, true, false, true}));
  EXPECT_EQ(a.gap, 0.1);
}

// ---- relations --------------------------------------------------------------

TEST(SceneRules, RelationIdsMustBeKnown) {
  expect_broken([](Json& j) { set(j, "/relations/0/b", "sofa"); }, "/relations/0/b", "unknown");
}
TEST(SceneRules, RelationNeedsTwoDifferentObjects) {
  expect_broken([](Json& j) { set(j, "/relations/0/b", "table"); }, "/relations/0/b", "different");
}
TEST(SceneRules, RelationNeedsDistanceOrAngle) {
  expect_broken([](Json& j) { erase(j, "/relations/0", "distance"); }, "/relations/0/distance",
                "distance and/or angle");
}
TEST(SceneRules, RelationWeightMustBeNonNegative) {
  expect_broken([](Json& j) { set(j, "/relations/0/weight", -1); }, "/relations/0/weight", ">= 0");
}
TEST(SceneRules, RelationDistanceMustBeNonNegative) {
  expect_broken([](Json& j) { set(j, "/relations/0/distance", -2); }, "/relations/0/distance",
                ">= 0");
}

// ---- activity and weights ---------------------------------------------------

TEST(SceneRules, ActivityIsRequired) {
  expect_broken([](Json& j) { erase(j, "", "activity"); }, "/activity", "missing");
  expect_broken([](Json& j) { erase(j, "/activity", "transitions"); }, "/activity/transitions",
                "missing");
}
TEST(SceneRules, TransitionFromMustBeKnown) {
  expect_broken(
      [](Json& j) {
        set(j, "/activity/transitions/sofa", Json{{"desk", 1.0}});
      },
      "/activity/transitions/sofa", "unknown object id");
}
TEST(SceneRules, TransitionToMustBeKnown) {
  expect_broken(
      [](Json& j) {
        erase(j, "/activity/transitions/table", "desk");
        set(j, "/activity/transitions/table/sofa", 1.0);
      },
      "/activity/transitions/table/sofa", "unknown object id");
}
TEST(SceneRules, DoorIsOnlyAStartNode) {
  expect_broken(
      [](Json& j) {
        set(j, "/activity/transitions/table", Json{{"desk", 0.5}, {"door", 0.5}});
      },
      "/activity/transitions/table/door", "start node");
}
TEST(SceneRules, DoorRowIsRequired) {
  expect_broken([](Json& j) { erase(j, "/activity/transitions", "door"); },
                "/activity/transitions/door", "missing");
}
TEST(SceneRules, ProbabilitiesMustBeInUnitInterval) {
  expect_broken(
      [](Json& j) {
        set(j, "/activity/transitions/desk", Json{{"desk", 1.5}, {"table", -0.5}});
      },
      "/activity/transitions/desk/desk", "[0, 1]");
  expect_broken(
      [](Json& j) {
        set(j, "/activity/transitions/desk", Json{{"desk", -0.5}, {"table", 1.5}});
      },
      "/activity/transitions/desk/desk", "[0, 1]");
}
TEST(SceneRules, ProbabilityMustBeANumber) {
  expect_broken([](Json& j) { set(j, "/activity/transitions/table/desk", "1"); },
                "/activity/transitions/table/desk", "number");
}
TEST(SceneRules, RowsMustSumToOne) {
  expect_broken([](Json& j) { set(j, "/activity/transitions/door/shelf", 0.1); },
                "/activity/transitions/door", "sum to 1");
  expect_broken([](Json& j) { set(j, "/activity/transitions/table", Json::object()); },
                "/activity/transitions/table", "sum to 1");
}
TEST(SceneRules, RowSumToleranceIsOneMillionth) {
  Json j = base();
  set(j, "/activity/transitions/shelf/plant", 0.3 + 5e-7);
  EXPECT_NO_THROW(parse(j));
  set(j, "/activity/transitions/shelf/plant", 0.3 + 2e-6);
  expect_rejected(j.dump(), "/activity/transitions/shelf", "sum to 1");
}
TEST(SceneRules, PointerEscapesSlashAndTilde) {
  expect_broken(
      [](Json& j) {
        set(j, "/activity/transitions/a~1b~0c", Json{{"desk", 1.0}});
      },
      "/activity/transitions/a~1b~0c", "unknown object id");
}
TEST(SceneRules, SequencesMustBeAPositiveInteger) {
  expect_broken([](Json& j) { set(j, "/activity/sequences", 0); }, "/activity/sequences", ">= 1");
  expect_broken([](Json& j) { set(j, "/activity/sequences", 2.5); }, "/activity/sequences",
                "integer");
}
TEST(SceneRules, VisitsMustBeAPositiveInteger) {
  expect_broken([](Json& j) { set(j, "/activity/visits", -3); }, "/activity/visits", ">= 1");
  expect_broken([](Json& j) { set(j, "/activity/visits", "3"); }, "/activity/visits", "integer");
}
TEST(SceneRules, WeightsMustHaveTheRightLength) {
  expect_broken(
      [](Json& j) {
        set(j, "/weights/path", Json::array({1, 1}));
      },
      "/weights/path", "3 numbers");
  expect_broken(
      [](Json& j) {
        set(j, "/weights/interior", Json::array({1, 1, 1}));
      },
      "/weights/interior", "2 numbers");
}
TEST(SceneRules, WeightsMustBeNonNegativeNumbers) {
  expect_broken([](Json& j) { set(j, "/weights/path/2", -0.5); }, "/weights/path/2", ">= 0");
  expect_broken([](Json& j) { set(j, "/weights/interior/0", true); }, "/weights/interior/0",
                "number");
}

// ---- round trip -------------------------------------------------------------

void expect_round_trip(const Scene& scene, const std::string& label) {
  const std::string text = write_scene(scene);
  const Scene again = parse_scene(text, label + " (written)");
  EXPECT_EQ(again, scene) << label;
  EXPECT_EQ(write_scene(again), text) << label;
}

std::vector<std::filesystem::path> scene_files() {
  std::vector<std::filesystem::path> out;
  for (const auto& e : std::filesystem::directory_iterator(HRSPACE_SOURCE_DIR "/scenes")) {
    if (e.path().extension() == ".json") out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
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

// ---- geometry helpers -------------------------------------------------------

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
