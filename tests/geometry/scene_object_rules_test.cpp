// SPDX-License-Identifier: GPL-3.0-or-later
// Scene format rules of the objects, the relations, the AO graph (activity)
// and the weights: one broken scene per rule of scene-format.md, each of which
// must name the file, the exact JSON pointer and what is wrong.

#include <gtest/gtest.h>

#include <string>

#include "geometry/scene.h"
#include "tests/geometry/scene_fixture.h"

namespace hrs::geometry {
namespace {

using scene_fixture::base;
using scene_fixture::erase;
using scene_fixture::expect_broken;
using scene_fixture::expect_rejected;
using scene_fixture::Json;
using scene_fixture::parse;
using scene_fixture::set;

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
  expect_broken([](Json& j) { set(j, "/objects/3/pose/0", 4.7); }, "/objects/3/pose",
                "the footprint of \"table\" sticks out 0.1 m past the wall from (5,0) to (5,4)");
  // Rotating the desk by 90 degrees puts its 1.6 m width across the top wall.
  expect_broken([](Json& j) { set(j, "/objects/0/pose/2", 0.0); }, "/objects/0/pose",
                "sticks out 0.3 m past the wall from (5,4) to (0,4)");
}
TEST(SceneRules, ObjectInsideLShapedRoomMustAvoidTheNotch) {
  Json j = base();
  set(j, "/room/polygon", Json::parse("[[0,0],[5,0],[5,2],[2,2],[2,4],[0,4]]"));
  set(j, "/objects", Json::parse(R"([{"id": "desk", "size": [0.8, 1.6], "pose": [3.5, 1.0, 0]}])"));
  set(j, "/activity/transitions", Json::parse(R"({"door": {"desk": 1}})"));
  erase(j, "", "relations");
  EXPECT_NO_THROW(parse(j));
  set(j, "/objects/0/pose", Json::array({3.0, 2.5, 0}));  // in the bounding box, not the room
  // Farthest out: the corner (3.4, 3.3), 1.3 m above the notch's wall y = 2.
  expect_rejected(j.dump(), "/objects/0/pose", "sticks out 1.3 m past the wall from (5,2) to (2,2)");
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
                "distance, angle and/or faces");
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
TEST(SceneRules, RowSumToleranceIsTheSameAboveAndBelowOne) {
  // |sum - 1| <= 1e-6 both ways: a row one millionth over 1 passes like one
  // a millionth under it (the over side was refused by rounding).
  for (const double plant : {0.300001, 0.299999, 0.3 + 1e-6, 0.3 - 1e-6}) {
    Json j = base();
    set(j, "/activity/transitions/shelf/plant", plant);
    EXPECT_NO_THROW(parse(j)) << "plant " << plant;
  }
  for (const char* row :
       {R"({"desk": 0.500001, "plant": 0.5})", R"({"desk": 0.499999, "plant": 0.5})"}) {
    Json j = base();
    set(j, "/activity/transitions/shelf", Json::parse(row));
    EXPECT_NO_THROW(parse(j)) << row;
  }
  for (const double plant : {0.3000012, 0.2999988}) {
    Json j = base();
    set(j, "/activity/transitions/shelf/plant", plant);
    expect_rejected(j.dump(), "/activity/transitions/shelf", "sum to 1");
  }
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

TEST(SceneRules, RelationFacesMustBeABoolean) {
  expect_broken([](Json& j) { set(j, "/relations/0/faces", 1); }, "/relations/0/faces",
                "true or false");
}

}  // namespace
}  // namespace hrs::geometry
