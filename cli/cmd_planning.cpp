// `hrspace plan` and `hrspace tour`: the planning layer on the command line
// (one leg of the baseline RRT, §III-B; one tour by branch and bound, §III-C).

#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/args.h"
#include "cli/commands.h"
#include "geometry/cspace.h"
#include "geometry/error.h"
#include "geometry/free_grid.h"
#include "geometry/polygon_ops.h"
#include "geometry/scene.h"
#include "planning/reuse.h"
#include "planning/rrt.h"
#include "planning/tour.h"
#include "planning/tour_json.h"

namespace hrs::cli {

namespace {

geometry::Scene read_scene(const std::string& path) {
  if (path == "-") return geometry::parse_scene(read_input("-"), "stdin");
  return geometry::load_scene(path);
}

//! Throws InputError naming `what` when the chair at `pose` is not usable as
//! a start or goal: outside the room, overlapping an object, or too close to
//! an obstacle for the conservative C-space to certify it free.
void require_free(const geometry::Scene& scene, const geometry::CSpace& cspace,
                  const geometry::Pose2& pose, const std::string& what) {
  if (cspace.is_free(pose)) return;
  const double hl = 0.5 * scene.wheelchair.length, hw = 0.5 * scene.wheelchair.width;
  geometry::Polygon chair;
  for (geometry::Vec2 v : {geometry::Vec2{hl, hw}, {-hl, hw}, {-hl, -hw}, {hl, -hw}}) {
    chair.push_back(geometry::to_world(pose, v));
  }
  std::ostringstream at;
  at << what << " pose " << pose.x << "," << pose.y << "," << pose.theta << ": ";
  if (!geometry::polygon_inside(chair, scene.room.polygon))
    throw InputError(at.str() + "the wheelchair is outside the room");
  for (int i = 0; i < cspace.object_count(); ++i) {
    geometry::Object o = scene.objects[i];
    o.pose = cspace.object_pose(i);
    if (geometry::interiors_overlap(chair, geometry::world_footprint(o)))
      throw InputError(at.str() + "the wheelchair collides with object '" + o.id + "'");
  }
  throw InputError(
      at.str() + "the wheelchair touches or nearly touches a wall or object (not certified free)");
}

geometry::Pose2 pose_option(const Args& args, const std::string& name) {
  const auto v = args.get(name);
  if (!v) throw InputError("missing --" + name + " x,y,theta (see --help)");
  const std::vector<double> n = parse_numbers(*v, 3, "--" + name);
  return {n[0], n[1], n[2]};
}

std::vector<std::string> split_ids(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  std::string id;
  while (std::getline(ss, id, ',')) {
    if (id.empty()) throw InputError("--sequence: empty object id in '" + text + "'");
    out.push_back(id);
  }
  if (out.empty()) throw InputError("--sequence: no object ids");
  return out;
}

}  // namespace

int cmd_plan(const Argv& argv) {
  const Args args(argv, {"from", "to", "seed", "iterations", "step", "planner", "reuse"});
  const std::string usage =
      "hrspace plan SCENE --from x,y,theta --to x,y,theta [--seed N] [--iterations N] [--step M]\n"
      "                   [--planner baseline|proposed] [--reuse samples,steering]";
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
                 "--planner proposed draws the RRT's samples from the RS-decomposition and\n"
                 "steers through its predicted words (paper V-A; --reuse samples or steering\n"
                 "for one of them); the decomposition is built first, from --seed.\n"
                 "Exit 0 whether or not a path is found; 2 for a bad scene, or a start or\n"
                 "goal pose outside the room or in collision.\n";
    return 0;
  }
  args.expect_positional(1, usage);
  const geometry::Scene scene = read_scene(args.positional()[0]);
  const geometry::CSpace cspace(scene);
  const geometry::Pose2 from = pose_option(args, "from");
  const geometry::Pose2 to = pose_option(args, "to");
  require_free(scene, cspace, from, "--from");
  require_free(scene, cspace, to, "--to");
  planning::PlannerOptions options;
  options.max_iterations =
      static_cast<int>(args.integer("iterations", options.max_iterations, 1, 100000000));
  options.step_length = args.number("step", options.step_length);
  if (!(options.step_length > 0.0)) throw InputError("--step: must be > 0");
  const auto seed = static_cast<std::uint64_t>(args.integer("seed", 1, 0, 0x7fffffffffffffffL));
  const auto reuse = planner_option(args, "samples,steering", "samples,steering");
  planning::TourOptions tour;
  tour.planner = options;
  std::unique_ptr<planning::ReusePlanner> proposed;
  if (reuse) proposed = std::make_unique<planning::ReusePlanner>(scene, cspace, tour, *reuse, seed);
  planning::LegPlanner planner(scene, cspace, options,
                               proposed ? proposed->hooks().planner : planning::PlannerHooks{});
  const planning::LegResult result = planner.plan(from, to, seed);
  // Not found: is there any motion at all? (A certificate, or "not proven".)
  bool impossible = false;
  if (!result.found) {
    try {
      const geometry::FreeGrid grid(scene);
      geometry::ReachabilityQuery query;
      impossible = query.query(grid, from, to, grid.cell_count()) ==
                   geometry::ReachabilityQuery::Answer::kDisconnected;
    } catch (const std::invalid_argument&) {
      // The chair is too small for the grid's cells: nothing is proven.
    }
  }
  std::cout << planning::plan_json(from, to, result, scene.wheelchair.turning_radius, impossible)
            << "\n";
  return 0;
}

int cmd_tour(const Argv& argv) {
  const Args args(argv, {"sequence", "seed", "planner", "reuse"});
  const std::string usage =
      "hrspace tour SCENE --sequence door,ID,ID,... [--seed N] [--planner baseline|proposed]\n"
      "                   [--reuse LIST]";
  if (args.help()) {
    std::cout << "usage: " << usage
              << "\n\nPlans one tour in the scene's initial layout (paper III-C): from the door's\n"
                 "start pose to a goal pose around each object in order (poses face the\n"
                 "object's centre, on its allowed approach sides), legs by the baseline RRT,\n"
                 "branch and bound over the goal poses. Prints one entry of tours.json:\n"
                 "sequence, found, legs (from, to, segments, waypoints every 5 cm), metrics\n"
                 "(length, rotation, clearance), stats. --planner proposed serves the legs\n"
                 "through the proposed planner (paper V: decomposition samples and steering,\n"
                 "legs shared within the tour; --reuse to choose among samples, steering,\n"
                 "paths, shortcuts, budget and proofs).\n"
                 "Exit 0 whether or not a tour is found; 2 for a bad scene or an unknown\n"
                 "object id.\n";
    return 0;
  }
  args.expect_positional(1, usage);
  const geometry::Scene scene = read_scene(args.positional()[0]);
  const auto text = args.get("sequence");
  if (!text) throw InputError("missing --sequence door,ID,... (see --help)");
  const std::vector<std::string> sequence = split_ids(*text);
  for (const std::string& id : sequence) {
    if (id != planning::kDoorId && scene.find_object(id) < 0)
      throw InputError("--sequence: unknown object id '" + id + "'");
  }
  const geometry::CSpace cspace(scene);
  const auto seed = static_cast<std::uint64_t>(args.integer("seed", 1, 0, 0x7fffffffffffffffL));
  const auto reuse = planner_option(args, "samples,steering,paths,shortcuts,budget,proofs",
                                    "samples,steering,paths");
  std::unique_ptr<planning::ReusePlanner> proposed;
  if (reuse) {
    proposed = std::make_unique<planning::ReusePlanner>(scene, cspace, planning::TourOptions{},
                                                        *reuse, seed);
    proposed->begin_iteration(seed);
  }
  planning::TourPlanner planner(scene, cspace, {}, seed,
                                proposed ? proposed->hooks() : planning::TourHooks{});
  const planning::Tour tour = planner.plan(sequence);
  if (proposed) proposed->end_iteration();
  std::cout << planning::tour_json(tour) << "\n";
  return 0;
}

}  // namespace hrs::cli
