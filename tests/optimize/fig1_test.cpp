// SPDX-License-Identifier: GPL-3.0-or-later
// The point of the paper's Fig. 1: a bedroom designed without the wheelchair
// (path weights 0) leaves objects the chair cannot reach; designed with the
// path costs (default weights) it can tour more of the M sequences. Each final
// layout is re-toured here with fresh planners (seeds independent of the
// design run) and the feasible tours are counted and printed.
#include <gtest/gtest.h>

#include <cstdio>

#include "geometry/cspace.h"
#include "optimize/design.h"
#include "planning/tour.h"

namespace hrs::optimize {
namespace {

int feasible_tours(const geometry::Scene& layout, const std::vector<Sequence>& sequences) {
  geometry::CSpace cspace(layout);
  int found = 0;
  for (std::size_t k = 0; k < sequences.size(); ++k) {
    planning::TourPlanner planner(layout, cspace, {}, 9001 + k);
    planning::Tour tour = planner.plan(sequences[k].nodes);
    planning::recheck_tour(cspace, layout.wheelchair.turning_radius, tour);
    found += tour.found ? 1 : 0;
  }
  return found;
}

TEST(Fig1, PathCostsMakeMoreToursFeasibleThanInteriorCostsAlone) {
  const auto bedroom =
      geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/scenes/bedroom.json");
  const int iterations = 700;  // the paper's budget
  int total[2] = {0, 0};
  const int initial = feasible_tours(bedroom, scene_sequences(bedroom));
  std::printf("Fig. 1 (bedroom, %d iterations): initial layout %d/%d feasible tours\n", iterations,
              initial, bedroom.activity.sequences);
  for (std::uint64_t seed : {1u, 2u, 3u, 4u}) {  // four designs, as in the paper's figures
    for (int with_path = 0; with_path < 2; ++with_path) {
      geometry::Scene scene = bedroom;
      if (!with_path) scene.weights.path = {0.0, 0.0, 0.0};
      DesignOptions options;
      options.planner = hrs::optimize::PlannerConfig::from_preset("baseline");
      options.seed = seed;
      options.iterations = iterations;
      const auto r = design(scene, options);
      ASSERT_TRUE(r.valid);
      const int found = feasible_tours(r.layout, r.sequences);
      total[with_path] += found;
      std::printf(
          "  seed %llu, path weights %s: %d/%zu feasible (re-planned), %d/%d in the run; "
          "interior cost %.3f\n",
          static_cast<unsigned long long>(seed), with_path ? "[1,1,1]" : "[0,0,0]", found,
          r.sequences.size(), r.final.tours_found, r.final.tours_total, r.final.interior());
    }
  }
  std::printf("  total feasible: path weights 0: %d, defaults: %d\n", total[0], total[1]);
  RecordProperty("feasible_weights_zero", total[0]);
  RecordProperty("feasible_defaults", total[1]);
  EXPECT_GT(total[1], total[0]);
}

}  // namespace
}  // namespace hrs::optimize
