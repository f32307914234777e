// SPDX-License-Identifier: GPL-3.0-or-later
// The room zoo (experiments/room_zoo.h): every generated room and witness
// passes the reader, rooms are deterministic in their seed and respect the
// object bounds and shapes, the witness meets every wall and relation
// preference exactly, and (slow) every witness is tourable by the design loop.

#include "experiments/room_zoo.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "geometry/error.h"
#include "geometry/scene.h"
#include "optimize/costs.h"
#include "optimize/sequences.h"

namespace {

using hrs::experiments::zoo::generate_room;
using hrs::experiments::zoo::is_partition;
using hrs::experiments::zoo::Shape;
using hrs::experiments::zoo::ZooOptions;
using hrs::experiments::zoo::ZooRoom;
namespace geometry = hrs::geometry;

ZooOptions geometry_only(std::uint64_t seed, int lo, int hi) {
  ZooOptions o;
  o.seed = seed;
  o.min_objects = lo;
  o.max_objects = hi;
  o.check_tours = false;
  return o;
}

//! The room read back from its own file text (throws when the reader refuses it).
geometry::Scene reread(const geometry::Scene& s, const std::string& label) {
  return geometry::parse_scene(geometry::write_scene(s), label);
}

TEST(RoomZoo, HundredsOfRoomsPassTheReaderAndRespectTheBounds) {
  const std::pair<int, int> ranges[] = {{4, 8}, {9, 16}, {17, 24}, {25, 40}, {4, 40}};
  int rooms = 0;
  std::map<Shape, int> shapes;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    for (const auto& [lo, hi] : ranges) {
      const ZooRoom r = generate_room(geometry_only(seed, lo, hi), static_cast<int>(seed % 7) + 1);
      SCOPED_TRACE(r.name + " objects " + std::to_string(lo) + "-" + std::to_string(hi));
      ASSERT_TRUE(r.feasible);
      ASSERT_FALSE(r.scene.objects.empty());
      EXPECT_NO_THROW(reread(r.scene, r.name + ".json"));
      EXPECT_NO_THROW(reread(r.witness, r.name + ".witness.json"));
      const int n = static_cast<int>(r.scene.objects.size());
      EXPECT_GE(n, lo);
      EXPECT_LE(n, hi);
      EXPECT_GE(r.area, 9.0);
      EXPECT_EQ(r.scene.activity.sequences, 10);
      EXPECT_GE(geometry::longest_walk(r.scene.activity, 3), 3);
      ++shapes[r.shape];
      ++rooms;
    }
  }
  EXPECT_EQ(rooms, 200);
  EXPECT_EQ(shapes.size(), 4u);  // every shape is drawn
}

TEST(RoomZoo, SameSeedSameRoomOtherSeedOtherRoom) {
  const ZooOptions o = geometry_only(11, 4, 40);
  for (int i = 1; i <= 5; ++i) {
    const ZooRoom a = generate_room(o, i), b = generate_room(o, i);
    EXPECT_EQ(geometry::write_scene(a.scene), geometry::write_scene(b.scene));
    EXPECT_EQ(geometry::write_scene(a.witness), geometry::write_scene(b.witness));
    const ZooRoom c = generate_room(geometry_only(12, 4, 40), i);
    EXPECT_NE(geometry::write_scene(a.scene), geometry::write_scene(c.scene));
  }
}

TEST(RoomZoo, CheckedRoomsAreTheSameWhateverTheThreads) {
  ZooOptions o = geometry_only(3, 4, 8);
  o.check_tours = true;
  o.threads = 1;
  const ZooRoom one = generate_room(o, 1);
  o.threads = 2;
  const ZooRoom two = generate_room(o, 1);
  EXPECT_EQ(geometry::write_scene(one.scene), geometry::write_scene(two.scene));
  EXPECT_EQ(geometry::write_scene(one.witness), geometry::write_scene(two.witness));
  EXPECT_EQ(one.plant_attempts, two.plant_attempts);
  EXPECT_EQ(one.witness_cost, two.witness_cost);
}

// A room whose plants all fail is drawn again; a room that passes at its
// first draw does not depend on how many draws are allowed. One plant per
// draw makes failures common (an object that finds no place).
TEST(RoomZoo, ARoomWhosePlantsAllFailIsDrawnAgainAndOthersStayTheSame) {
  int redrawn = 0, rescued = 0, first_draw = 0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    for (int index = 1; index <= 8; ++index) {
      ZooOptions once = geometry_only(seed, 25, 40);
      once.max_plants = 1;
      once.max_draws = 1;
      ZooOptions more = once;
      more.max_draws = 6;
      const ZooRoom a = generate_room(once, index), b = generate_room(more, index);
      SCOPED_TRACE(a.name);
      EXPECT_EQ(a.room_draws, 1);
      if (a.feasible) {
        ++first_draw;
        EXPECT_EQ(b.room_draws, 1);
        EXPECT_EQ(geometry::write_scene(a.scene), geometry::write_scene(b.scene));
        EXPECT_EQ(geometry::write_scene(a.witness), geometry::write_scene(b.witness));
        continue;
      }
      ++redrawn;
      EXPECT_GT(b.room_draws, 1);
      EXPECT_EQ(b.plant_attempts, b.room_draws);  // one plant per draw
      if (!b.feasible) continue;
      ++rescued;
      EXPECT_NE(geometry::write_scene(a.witness), geometry::write_scene(b.witness));
      EXPECT_NO_THROW(reread(b.scene, b.name + ".json"));
      EXPECT_NO_THROW(reread(b.witness, b.name + ".witness.json"));
      const int n = static_cast<int>(b.scene.objects.size());
      EXPECT_GE(n, 25);
      EXPECT_LE(n, 40);
    }
  }
  // Both cases occur, and most failed rooms pass at a later draw.
  std::printf("40 rooms at one plant per draw: %d pass at the first draw, %d redrawn, %d of them pass\n",
              first_draw, redrawn, rescued);
  EXPECT_GT(first_draw, 0);
  EXPECT_GT(redrawn, 0);
  EXPECT_GT(2 * rescued, redrawn);
  const ZooOptions bad = [] {
    ZooOptions o = geometry_only(1, 4, 8);
    o.max_draws = 0;
    return o;
  }();
  EXPECT_THROW(generate_room(bad, 1), hrs::InputError);
}

TEST(RoomZoo, ShapesAreWhatWasAskedFor) {
  const std::map<Shape, std::size_t> vertices = {
      {Shape::kRect, 4}, {Shape::kL, 6}, {Shape::kU, 8}, {Shape::kFlat, 4}};
  for (const auto& [shape, count] : vertices) {
    for (int i = 1; i <= 10; ++i) {
      ZooOptions o = geometry_only(5, 4, 30);
      o.shape = shape;
      const ZooRoom r = generate_room(o, i);
      SCOPED_TRACE(r.name);
      EXPECT_EQ(r.shape, shape);
      EXPECT_EQ(r.scene.room.polygon.size(), count);
      int partitions = 0;
      for (const auto& ob : r.scene.objects) partitions += is_partition(ob);
      EXPECT_EQ(partitions > 0, shape == Shape::kFlat);
    }
  }
}

TEST(RoomZoo, FlatsAreJoinedByOpeningsOfAtLeast1p1m) {
  for (int i = 1; i <= 30; ++i) {
    ZooOptions o = geometry_only(9, 4, 40);
    o.shape = Shape::kFlat;
    const ZooRoom r = generate_room(o, i);
    SCOPED_TRACE(r.name);
    const double depth = geometry::bounding_box(r.scene.room.polygon).ymax;
    // Partition pieces grouped by their x: the free span of y must hold an
    // opening of at least 1.1 m.
    std::map<double, std::vector<std::pair<double, double>>> walls;
    for (const auto& ob : r.scene.objects) {
      if (!is_partition(ob)) continue;
      EXPECT_TRUE(ob.fixed);
      const auto b = geometry::bounding_box(geometry::world_footprint(ob));
      EXPECT_NEAR(b.xmax - b.xmin, 0.1, 1e-9);
      walls[b.xmin].push_back({b.ymin, b.ymax});
    }
    ASSERT_GE(walls.size(), 1u);
    ASSERT_LE(walls.size(), 2u);
    for (auto& [x, pieces] : walls) {
      std::sort(pieces.begin(), pieces.end());
      double largest = pieces.front().first, at = pieces.front().second;
      for (std::size_t k = 1; k < pieces.size(); ++k) {
        largest = std::max(largest, pieces[k].first - at);
        at = pieces[k].second;
      }
      largest = std::max(largest, depth - at);
      EXPECT_GE(largest, 1.1) << "partition at x = " << x;
    }
  }
}

TEST(RoomZoo, WitnessMeetsEveryPreferenceAndInputIsScrambled) {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const ZooRoom r = generate_room(geometry_only(seed, 4, 40), 1);
    SCOPED_TRACE(r.name);
    const geometry::Scene w = reread(r.witness, "witness");
    const hrs::optimize::CostModel model(w, hrs::optimize::scene_sequences(w));
    int walls = 0, moved = 0;
    std::vector<geometry::Pose2> poses;
    for (std::size_t i = 0; i < w.objects.size(); ++i) {
      const auto& o = w.objects[i];
      poses.push_back(o.pose);
      const auto& in = r.scene.objects[i];
      EXPECT_EQ(in.id, o.id);
      if (o.fixed) {
        EXPECT_EQ(in.pose, o.pose);
      }
      moved += !(in.pose == o.pose);
      if (!o.wall) continue;
      ++walls;
      ASSERT_TRUE(o.wall->distance && o.wall->angle);
      EXPECT_EQ(*o.wall->distance, 0.0);
      EXPECT_EQ(*o.wall->angle, 0.0);
      const int edge = model.nearest_wall(static_cast<int>(i), o.pose);
      EXPECT_LE(model.wall_distance(geometry::world_footprint(o), edge), 1e-9) << o.id;
      EXPECT_LE(std::abs(geometry::wrap_angle(o.pose.theta - model.wall_normal_angle(edge))), 1e-9)
          << o.id;
    }
    for (const auto& rel : w.relations) {
      const auto& a = w.objects[w.find_object(rel.a)].pose;
      const auto& b = w.objects[w.find_object(rel.b)].pose;
      ASSERT_TRUE(rel.distance && rel.angle);
      EXPECT_NEAR(std::hypot(a.x - b.x, a.y - b.y), *rel.distance, 1e-9);
      EXPECT_NEAR(geometry::wrap_angle(a.theta - b.theta - *rel.angle), 0.0, 1e-9);
    }
    EXPECT_GT(walls, 0);
    EXPECT_GT(moved, 0);
    const auto interior = model.interior(poses);
    EXPECT_LE(interior.distance, 1e-12);
    EXPECT_LE(interior.rotation, 1e-12);
  }
}

TEST(RoomZoo, BadObjectBoundsAreInputErrors) {
  EXPECT_THROW(generate_room(geometry_only(1, 3, 8), 1), hrs::InputError);
  EXPECT_THROW(generate_room(geometry_only(1, 9, 8), 1), hrs::InputError);
  EXPECT_THROW(generate_room(geometry_only(1, 4, 101), 1), hrs::InputError);
}

}  // namespace
