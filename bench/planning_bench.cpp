// SPDX-License-Identifier: GPL-3.0-or-later
// Planning benchmark (issue 4): per-leg time and success of our baseline RRT
// (§III-B) on fixed sets of bedroom legs, in the same run as OMPL's RRT (goal
// bias 0.8, range = our n · step) and RRTConnect on a ReedsSheppStateSpace
// whose validity checker wraps our CSpace::is_free. OMPL checks motions by
// sampling every `kOmplResolution` metres (our planner checks them
// continuously); OMPL planners stop at kOmplTimeLimit seconds per leg, ours at
// its iteration cap. Each benchmark runs the whole set once and reports
// solved legs and mean/median time per leg as counters.
//
// The nearest-node index (planning::PoseNearest) is timed against its
// previous version (bench/nearest_previous.h) on RRT-shaped trees: each step
// draws a uniform target pose in a 4.5 m x 4 m room, asks for the k = 10
// nearest nodes, and grows a chain of 1-5 nodes 0.25 m apart from the
// nearest one, turning towards the target at most 0.25/0.7 rad per step.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>

#include "geometry/cspace.h"
#include "geometry/scene.h"
#include "planning/goals.h"
#include "nearest_previous.h"
#include "planning/nearest.h"
#include "planning/rrt.h"

namespace {

using hrs::geometry::Pose2;
namespace ob = ompl::base;
namespace og = ompl::geometric;

constexpr double kOmplResolution = 0.01;  //!< metres between checked poses
constexpr double kOmplTimeLimit = 0.5;    //!< seconds per leg

struct Query {
  Pose2 from, to;
};

struct Fixture {
  hrs::geometry::Scene scene;
  std::unique_ptr<hrs::geometry::CSpace> cspace;
  std::vector<Query> object_legs;  //!< between goal poses of two different objects
  std::vector<Query> random_legs;  //!< between uniformly random free poses
};

double unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

const Fixture& bedroom() {
  static const Fixture f = [] {
    Fixture f;
    f.scene = hrs::geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/scenes/bedroom.json");
    f.cspace = std::make_unique<hrs::geometry::CSpace>(f.scene);
    std::vector<std::vector<hrs::planning::GoalPose>> goals;
    std::vector<int> usable;
    for (std::size_t i = 0; i < f.scene.objects.size(); ++i) {
      goals.push_back(hrs::planning::goal_poses(f.scene, f.scene.objects[i],
                                                f.scene.objects[i].pose, *f.cspace));
      if (!goals.back().empty()) usable.push_back(static_cast<int>(i));
    }
    // The door's start pose counts as an object with one goal pose.
    goals.push_back({{hrs::geometry::door_start_pose(f.scene), hrs::geometry::Side::kFront, 0}});
    usable.push_back(static_cast<int>(goals.size() - 1));
    std::mt19937_64 rng(4);
    while (f.object_legs.size() < 120) {
      const int a = usable[rng() % usable.size()];
      const int b = usable[rng() % usable.size()];
      if (a == b) continue;
      f.object_legs.push_back(
          {goals[a][rng() % goals[a].size()].pose, goals[b][rng() % goals[b].size()].pose});
    }
    auto free_pose = [&] {
      for (;;) {
        const Pose2 p{4.5 * unit(rng), 4.0 * unit(rng), 3.141592653589793 * (2 * unit(rng) - 1)};
        if (f.cspace->is_free(p)) return p;
      }
    };
    while (f.random_legs.size() < 120) f.random_legs.push_back({free_pose(), free_pose()});
    return f;
  }();
  return f;
}

void report(benchmark::State& state, std::vector<double> ms, int solved) {
  std::sort(ms.begin(), ms.end());
  state.counters["legs"] = static_cast<double>(ms.size());
  state.counters["solved"] = solved;
  state.counters["mean_ms"] = std::accumulate(ms.begin(), ms.end(), 0.0) / ms.size();
  state.counters["median_ms"] = ms[ms.size() / 2];
  state.counters["p95_ms"] = ms[ms.size() * 95 / 100];
}

const std::vector<Query>& legs_of(const Fixture& f, int set) {
  return set == 0 ? f.object_legs : f.random_legs;
}

void BM_OurRrt(benchmark::State& state) {
  const Fixture& f = bedroom();
  const auto& legs = legs_of(f, static_cast<int>(state.range(0)));
  hrs::planning::PlannerOptions options;
  options.skip_tried_goal_nodes = state.range(1) != 0;
  hrs::planning::LegPlanner planner(f.scene, *f.cspace, options);
  for (auto _ : state) {
    std::vector<double> ms;
    int solved = 0;
    for (std::size_t i = 0; i < legs.size(); ++i) {
      const auto t0 = std::chrono::steady_clock::now();
      const auto r = planner.plan(legs[i].from, legs[i].to, 1 + i);
      ms.push_back(
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
      solved += r.found;
      benchmark::DoNotOptimize(r);
    }
    report(state, ms, solved);
  }
}

template <class Planner>
void BM_Ompl(benchmark::State& state) {
  ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
  const Fixture& f = bedroom();
  const auto& legs = legs_of(f, static_cast<int>(state.range(0)));
  auto space = std::make_shared<ob::ReedsSheppStateSpace>(f.scene.wheelchair.turning_radius);
  ob::RealVectorBounds bounds(2);
  bounds.setLow(0, 0.0);
  bounds.setHigh(0, 4.5);
  bounds.setLow(1, 0.0);
  bounds.setHigh(1, 4.0);
  space->setBounds(bounds);
  og::SimpleSetup ss(space);
  const hrs::geometry::CSpace& cspace = *f.cspace;
  ss.setStateValidityChecker([&cspace](const ob::State* s) {
    const auto* se2 = s->as<ob::SE2StateSpace::StateType>();
    return cspace.is_free({se2->getX(), se2->getY(), se2->getYaw()});
  });
  ss.getSpaceInformation()->setStateValidityCheckingResolution(kOmplResolution /
                                                               space->getMaximumExtent());
  auto planner = std::make_shared<Planner>(ss.getSpaceInformation());
  const hrs::planning::PlannerOptions ours;
  planner->setRange(ours.max_steps * ours.step_length);
  if constexpr (std::is_same_v<Planner, og::RRT>) planner->setGoalBias(ours.goal_bias);
  ss.setPlanner(planner);
  ss.setup();
  for (auto _ : state) {
    std::vector<double> ms;
    int solved = 0;
    for (std::size_t i = 0; i < legs.size(); ++i) {
      ompl::RNG::setSeed(1 + i);
      ss.clear();
      ob::ScopedState<ob::SE2StateSpace> a(space), b(space);
      a->setXY(legs[i].from.x, legs[i].from.y);
      a->setYaw(legs[i].from.theta);
      b->setXY(legs[i].to.x, legs[i].to.y);
      b->setYaw(legs[i].to.theta);
      ss.setStartAndGoalStates(a, b, 1e-6);
      const auto t0 = std::chrono::steady_clock::now();
      const ob::PlannerStatus status = ss.solve(kOmplTimeLimit);
      ms.push_back(
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
      solved += status == ob::PlannerStatus::EXACT_SOLUTION;
    }
    report(state, ms, solved);
  }
}

// Arguments: {set (0: object-to-object legs, 1: random legs), skip_tried_goal_nodes}.
BENCHMARK(BM_OurRrt)
    ->ArgNames({"set", "skip_tried"})
    ->Args({0, 1})
    ->Args({0, 0})
    ->Args({1, 1})
    ->Args({1, 0})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Ompl, og::RRT)
    ->ArgName("set")
    ->Arg(0)
    ->Arg(1)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Ompl, og::RRTConnect)
    ->ArgName("set")
    ->Arg(0)
    ->Arg(1)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

//! One step of the RRT-shaped workload: the query, then the poses added.
struct GrowthStep {
  Pose2 query;
  std::vector<Pose2> added;
};

//! The workload of a tree grown to `nodes` poses (fixed seed), built with
//! the current index (both versions give the same answers, which the unit
//! tests check against a linear scan).
const std::vector<GrowthStep>& growth(int nodes) {
  static std::vector<std::pair<int, std::vector<GrowthStep>>> made;
  for (const auto& [n, steps] : made)
    if (n == nodes) return steps;
  std::mt19937_64 rng(17);
  hrs::planning::PoseNearest index(0.7);
  std::vector<Pose2> poses{{0.6, 0.6, 0.0}};
  index.insert(poses[0], 0);
  std::vector<GrowthStep> steps;
  std::vector<std::int32_t> knn;
  while (static_cast<int>(poses.size()) < nodes) {
    GrowthStep step;
    step.query = {4.5 * unit(rng), 4.0 * unit(rng), 3.141592653589793 * (2 * unit(rng) - 1)};
    index.nearest(step.query, 10, knn);
    Pose2 p = poses[knn.front()];
    const int count = 1 + static_cast<int>(rng() % 5);
    for (int i = 0; i < count && static_cast<int>(poses.size()) < nodes; ++i) {
      const double want = std::atan2(step.query.y - p.y, step.query.x - p.x);
      const double turn = std::clamp(hrs::geometry::wrap_angle(want - p.theta), -0.357, 0.357);
      p.theta = hrs::geometry::wrap_angle(p.theta + turn);
      p.x = std::clamp(p.x + 0.25 * std::cos(p.theta), 0.0, 4.5);
      p.y = std::clamp(p.y + 0.25 * std::sin(p.theta), 0.0, 4.0);
      step.added.push_back(p);
      index.insert(p, static_cast<std::int32_t>(poses.size()));
      poses.push_back(p);
    }
    steps.push_back(std::move(step));
  }
  made.emplace_back(nodes, std::move(steps));
  return made.back().second;
}

//! Grows the whole tree (one k = 10 query and the chain's inserts per step).
template <class Index>
void BM_NearestGrowth(benchmark::State& state) {
  const auto& steps = growth(static_cast<int>(state.range(0)));
  std::vector<std::int32_t> knn;
  std::size_t queries = 0;
  for (auto _ : state) {
    Index index(0.7);
    index.insert({0.6, 0.6, 0.0}, 0);
    std::int32_t next = 1;
    for (const GrowthStep& step : steps) {
      index.nearest(step.query, 10, knn);
      benchmark::DoNotOptimize(knn.data());
      for (const Pose2& p : step.added) index.insert(p, next++);
    }
    queries += steps.size();
  }
  state.counters["ns_per_query_and_inserts"] = benchmark::Counter(
      static_cast<double>(queries), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

//! k = 10 queries (uniform poses in the room) against the grown tree.
template <class Index>
void BM_NearestQuery(benchmark::State& state) {
  const auto& steps = growth(static_cast<int>(state.range(0)));
  Index index(0.7);
  index.insert({0.6, 0.6, 0.0}, 0);
  std::int32_t next = 1;
  for (const GrowthStep& step : steps)
    for (const Pose2& p : step.added) index.insert(p, next++);
  std::vector<std::int32_t> knn;
  std::size_t i = 0;
  for (auto _ : state) {
    index.nearest(steps[i++ % steps.size()].query, 10, knn);
    benchmark::DoNotOptimize(knn.data());
  }
}

BENCHMARK_TEMPLATE(BM_NearestGrowth, hrs::bench::PreviousPoseNearest)
    ->ArgName("nodes")->Arg(1000)->Arg(5000)->Arg(20000)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_NearestGrowth, hrs::planning::PoseNearest)
    ->ArgName("nodes")->Arg(1000)->Arg(5000)->Arg(20000)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_NearestQuery, hrs::bench::PreviousPoseNearest)
    ->ArgName("nodes")->Arg(1000)->Arg(5000)->Arg(20000);
BENCHMARK_TEMPLATE(BM_NearestQuery, hrs::planning::PoseNearest)
    ->ArgName("nodes")->Arg(1000)->Arg(5000)->Arg(20000);

}  // namespace

BENCHMARK_MAIN();
