// SPDX-License-Identifier: GPL-3.0-or-later
// `hrspace plan` and `hrspace tour`: the planning layer on the command line
// (one leg of the baseline RRT, §III-B; one tour by branch and bound, §III-C).
// The work itself is in api/operations.h, shared with the Python module.

#include <cstdint>
#include <iostream>
#include <string>
#include <vector>

#include "api/operations.h"
#include "cli/args.h"
#include "cli/commands.h"
#include "geometry/error.h"
#include "geometry/scene.h"

namespace hrs::cli {

namespace {

geometry::Scene read_scene(const std::string& path) {
  if (path == "-") return geometry::parse_scene(read_input("-"), "stdin");
  return geometry::load_scene(path);
}

geometry::Pose2 pose_option(const Args& args, const std::string& name) {
  const auto v = args.get(name);
  if (!v) throw InputError("missing --" + name + " x,y,theta (see --help)");
  const std::vector<double> n = parse_numbers(*v, 3, "--" + name);
  return {n[0], n[1], n[2]};
}

}  // namespace

int cmd_plan(const Argv& argv) {
  const Args args(argv, {"from", "to", "seed", "iterations", "step", "planner", "reuse"});
  const std::string usage =
      "hrspace plan SCENE --from x,y,theta --to x,y,theta [--seed N] [--iterations N] [--step M]\n"
      "                   [--planner baseline|default] [--reuse samples,steering]";
  if (args.help()) {
    std::cout << "usage: " << usage
              << "\n\nPlans one leg of the wheelchair in the scene's initial layout with the\n"
                 "baseline RRT with Reeds-Shepp steering (paper III-B: goal bias 0.8, k = 10,\n"
                 "n = 5 steps) and prints one JSON object: found, from, to, radius, length,\n"
                 "segments, waypoints (every 5 cm), iterations, tree_nodes, collision_checks,\n"
                 "time_ms, impossible (true: no collision-free motion joins the poses at all,\n"
                 "certified by a grid over the free poses; false: found, or not proven).\n"
                 "--seed (default 1) makes the run reproducible; --iterations caps\n"
                 "the RRT (default 3000); --step is the tree's step length (default 0.25 m).\n"
                 "--planner default (or proposed) draws the RRT's samples from the RS-decomposition and\n"
                 "steers through its predicted words (paper V-A; --reuse samples or steering\n"
                 "for one of them); the decomposition is built first, from --seed.\n"
                 "Exit 0 whether or not a path is found; 2 for a bad scene, or a start or\n"
                 "goal pose outside the room or in collision.\n";
    return 0;
  }
  args.expect_positional(1, usage);
  const geometry::Scene scene = read_scene(args.positional()[0]);
  const geometry::Pose2 from = pose_option(args, "from");
  const geometry::Pose2 to = pose_option(args, "to");
  api::LegSettings settings;
  settings.iterations =
      static_cast<int>(args.integer("iterations", settings.iterations, 1, 100000000));
  settings.step = args.number("step", settings.step);
  settings.seed = static_cast<std::uint64_t>(args.integer("seed", 1, 0, 0x7fffffffffffffffL));
  settings.reuse = planner_option(args, api::kPlanReuse.allowed, api::kPlanReuse.fallback);
  std::cout << api::plan_leg_json(scene, from, to, settings) << "\n";
  return 0;
}

int cmd_tour(const Argv& argv) {
  const Args args(argv, {"sequence", "seed", "planner", "reuse"});
  const std::string usage =
      "hrspace tour SCENE --sequence door,ID,ID,... [--seed N] [--planner baseline|default]\n"
      "                   [--reuse LIST]";
  if (args.help()) {
    std::cout << "usage: " << usage
              << "\n\nPlans one tour in the scene's initial layout (paper III-C): from the door's\n"
                 "start pose to a goal pose around each object in order (poses face the\n"
                 "object's centre, on its allowed approach sides), legs by the RRT (default\n"
                 "--planner baseline),\n"
                 "branch and bound over the goal poses. Prints one entry of tours.json:\n"
                 "sequence, found, legs (from, to, segments, waypoints every 5 cm), metrics\n"
                 "(length, rotation, clearance), stats. --planner default (or proposed) serves the legs\n"
                 "through the proposed planner (paper V: decomposition samples and steering,\n"
                 "legs shared within the tour; --reuse to choose among samples, steering,\n"
                 "paths, shortcuts and budget).\n"
                 "Exit 0 whether or not a tour is found; 2 for a bad scene or an unknown\n"
                 "object id.\n";
    return 0;
  }
  args.expect_positional(1, usage);
  const geometry::Scene scene = read_scene(args.positional()[0]);
  const auto text = args.get("sequence");
  if (!text) throw InputError("missing --sequence door,ID,... (see --help)");
  const std::vector<std::string> sequence = api::split_sequence(*text);
  api::check_sequence(scene, sequence);
  const auto seed = static_cast<std::uint64_t>(args.integer("seed", 1, 0, 0x7fffffffffffffffL));
  const auto reuse = planner_option(args, api::kTourReuse.allowed, api::kTourReuse.fallback);
  std::cout << api::plan_tour_json(scene, sequence, seed, reuse) << "\n";
  return 0;
}

}  // namespace hrs::cli
