// SPDX-License-Identifier: GPL-3.0-or-later
// Plans one wheelchair leg with an installed hrspace: reads a scene, builds
// its C-space and runs the baseline RRT between two poses.
// Usage: plan_one_leg SCENE x0 y0 t0 x1 y1 t1; exit 0 when a path is found.

#include <cstdio>
#include <cstdlib>
#include <exception>

#include "geometry/cspace.h"
#include "geometry/error.h"
#include "geometry/scene.h"
#include "planning/rrt.h"

int main(int argc, char** argv) {
  if (argc != 8) {
    std::fprintf(stderr, "usage: plan_one_leg SCENE x0 y0 t0 x1 y1 t1\n");
    return 2;
  }
  try {
    const hrs::geometry::Scene scene = hrs::geometry::load_scene(argv[1]);
    const hrs::geometry::CSpace cspace(scene);
    const hrs::geometry::Pose2 from{std::atof(argv[2]), std::atof(argv[3]), std::atof(argv[4])};
    const hrs::geometry::Pose2 to{std::atof(argv[5]), std::atof(argv[6]), std::atof(argv[7])};
    hrs::planning::LegPlanner planner(scene, cspace);
    const hrs::planning::LegResult leg = planner.plan(from, to, 1);
    std::printf("found %d, length %.3f m, word %s, %d RRT iterations\n", leg.found ? 1 : 0,
                leg.path.length(), leg.path.word().c_str(), leg.stats.iterations);
    return leg.found ? 0 : 1;
  } catch (const hrs::InputError& e) {
    std::fprintf(stderr, "plan_one_leg: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "plan_one_leg: %s\n", e.what());
    return 1;
  }
}
