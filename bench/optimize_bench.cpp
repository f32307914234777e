// SPDX-License-Identifier: GPL-3.0-or-later
// Benchmarks of optimize/: one full bedroom design (paper §VI: 700
// iterations, M = 10; the paper reports 3–5 min per design with planning
// 96 % of it) and the per-iteration pieces that are not planning.
//
//   ./build/bench/optimize_bench --benchmark_filter=BedroomDesign/700
#include <benchmark/benchmark.h>

#include <string>

#include "geometry/scene.h"
#include "optimize/costs.h"
#include "optimize/design.h"
#include "optimize/sequences.h"

namespace {

using namespace hrs;

const geometry::Scene& bedroom() {
  static const geometry::Scene scene =
      geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/scenes/bedroom.json");
  return scene;
}

//! One design; arguments: iterations, threads (0: all cores).
void BM_BedroomDesign(benchmark::State& state) {
  optimize::DesignResult r;
  for (auto _ : state) {
    optimize::DesignOptions options;
    options.planner = hrs::optimize::PlannerConfig::from_preset("baseline");
    options.seed = 1;
    options.iterations = static_cast<int>(state.range(0));
    options.threads = static_cast<int>(state.range(1));
    r = optimize::design(bedroom(), options);
    benchmark::DoNotOptimize(r.final);
  }
  state.counters["wall_s"] = r.time_total_s;
  state.counters["planning_s"] = r.time_planning_s;
  state.counters["planning_share"] = r.time_planning_s / r.time_total_s;
  state.counters["tours_found"] = r.final.tours_found;
  state.counters["cost_initial"] = r.initial.total();
  state.counters["cost_final"] = r.final.total();
  state.counters["acceptance"] = static_cast<double>(r.accepted) / std::max(1, r.proposals);
  state.counters["threads"] = r.threads;
}
BENCHMARK(BM_BedroomDesign)
    ->Args({700, 0})
    ->Args({50, 1})
    ->Args({50, 2})
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

void BM_TopSequences(benchmark::State& state) {
  const optimize::AoGraph graph(bedroom().activity);
  for (auto _ : state) benchmark::DoNotOptimize(optimize::top_sequences(graph, "door", 3, 10));
}
BENCHMARK(BM_TopSequences)->Unit(benchmark::kMicrosecond);

void BM_InteriorCost(benchmark::State& state) {
  const optimize::CostModel model(bedroom(), optimize::scene_sequences(bedroom()));
  std::vector<geometry::Pose2> poses;
  for (const auto& o : bedroom().objects) poses.push_back(o.pose);
  for (auto _ : state) benchmark::DoNotOptimize(model.interior(poses));
}
BENCHMARK(BM_InteriorCost)->Unit(benchmark::kMicrosecond);

//! The exact pre-planning check of one move (room, door zone, other objects).
void BM_MoveValidity(benchmark::State& state) {
  const auto& scene = bedroom();
  for (auto _ : state) benchmark::DoNotOptimize(optimize::object_violation(scene, 0));
}
BENCHMARK(BM_MoveValidity)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
