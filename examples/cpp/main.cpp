// SPDX-License-Identifier: GPL-3.0-or-later
// The example of docs/cpp.md: loads a scene, checks two poses, plans one
// wheelchair leg and runs a short design with the default planner.
// Usage: design_example SCENE   (e.g. scenes/bedroom.json)

#include <cstdio>
#include <exception>

#include <hrspace/geometry/cspace.h>
#include <hrspace/geometry/error.h>
#include <hrspace/geometry/scene.h>
#include <hrspace/optimize/design.h>
#include <hrspace/planning/rrt.h>

namespace geometry = hrs::geometry;
namespace planning = hrs::planning;
namespace optimize = hrs::optimize;

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: design_example SCENE\n");
    return 2;
  }
  try {
    const geometry::Scene scene = geometry::load_scene(argv[1]);  // hrs::InputError if invalid
    const geometry::CSpace cspace(scene);                         // exact, conservative C-space
    const geometry::Pose2 start{0.9, 1.2, 0.0}, on_bed{2.6, 3.0, 0.0};  // x, y (m), heading (rad)
    std::printf("free: %d %d\n", cspace.is_free(start), cspace.is_free(on_bed));  // 1 0

    planning::LegPlanner planner(scene, cspace);  // the baseline RRT, Reeds-Shepp steering
    const planning::LegResult leg = planner.plan(start, {4.03, 2.39, -1.79}, /*seed=*/1);
    std::printf("leg: found %d, %.2f m, %s\n", leg.found, leg.path.length(), leg.path.word().c_str());

    optimize::DesignOptions options;  // hrspace design's defaults: seed 1, 700 iterations, all cores
    options.seed = 2;
    options.iterations = 20;  // a quick run
    options.planner = optimize::PlannerConfig::from_preset("default");  // or api::parse_planner("default,-trees")
    const optimize::DesignResult result = optimize::design(scene, options);
    std::printf("tours found %d/%d, preferences met %d/%d\n", result.final.tours_found,
                result.final.tours_total, result.preferences.met, result.preferences.total);
    return leg.found ? 0 : 1;
  } catch (const hrs::InputError& e) {
    std::fprintf(stderr, "design_example: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "design_example: %s\n", e.what());
    return 1;
  }
}
