// SPDX-License-Identifier: GPL-3.0-or-later
// The room zoo's feasibility by construction (slow: plans tours): for a
// handful of seeds and every size bucket, the plant is accepted, the witness
// is a valid layout (the exact checks: inside the room, no overlap, the
// door's zone clear), and the witness as written to its file and read back
// finds every tour again, on one thread where the generator used two, at the
// same cost. The tours are planned by the same design loop the generator
// uses (check_layout); what this adds is the file round trip and the thread
// count.

#include <gtest/gtest.h>

#include <string>

#include "experiments/room_zoo.h"
#include "geometry/scene.h"
#include "optimize/design.h"

namespace {

using namespace hrs::experiments::zoo;

TEST(RoomZooSlow, EveryWitnessIsTourable) {
  const std::pair<int, int> buckets[] = {{4, 8}, {9, 16}, {17, 24}, {25, 40}};
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    for (const auto& [lo, hi] : buckets) {
      ZooOptions o;
      o.seed = seed;
      o.min_objects = lo;
      o.max_objects = hi;
      o.threads = 2;
      const ZooRoom r = generate_room(o, 1);
      SCOPED_TRACE(r.name + " " + std::to_string(lo) + "-" + std::to_string(hi));
      ASSERT_TRUE(r.feasible) << r.plant_attempts << " plants";
      EXPECT_EQ(r.tours_total, 10);
      const hrs::geometry::Scene w = hrs::geometry::parse_scene(
          hrs::geometry::write_scene(r.witness), r.name + ".witness.json");
      EXPECT_EQ(hrs::optimize::layout_violation(w), "");
      const WitnessCheck c = check_layout(w, 1);
      EXPECT_EQ(c.tours_found, c.tours_total);
      EXPECT_EQ(c.tours_total, 10);
      EXPECT_EQ(c.cost, r.witness_cost);  // the same whatever the threads
    }
  }
}

}  // namespace
