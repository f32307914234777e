// SPDX-License-Identifier: GPL-3.0-or-later
// Geometry micro-benchmarks on the bedroom scene: point query, straight and
// arc checks, and the incremental update after one object translates or
// rotates (docs/design-notes.md "Performance"). Run:
//   build/bench/geometry_bench --benchmark_min_time=0.5

#include <benchmark/benchmark.h>

#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "geometry/cspace.h"
#include "geometry/scene.h"

namespace {

using hrs::geometry::CSpace;
using hrs::geometry::Pose2;
using hrs::geometry::Scene;
constexpr double kPi = std::numbers::pi;

const Scene& bedroom() {
  static const Scene s = hrs::geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/scenes/bedroom.json");
  return s;
}

std::vector<Pose2> random_poses(const Scene& s, int n, std::uint64_t seed) {
  double xmin = 1e9, xmax = -1e9, ymin = 1e9, ymax = -1e9;
  for (const auto& v : s.room.polygon) {
    xmin = std::min(xmin, v.x), xmax = std::max(xmax, v.x);
    ymin = std::min(ymin, v.y), ymax = std::max(ymax, v.y);
  }
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(xmin, xmax), uy(ymin, ymax), ut(-kPi, kPi);
  std::vector<Pose2> out(n);
  for (auto& p : out) p = {ux(rng), uy(rng), ut(rng)};
  return out;
}

//! Random poses in the room; the mix of free and colliding answers is the
//! room's own (about 14 % free in the bedroom).
void BM_PointQuery(benchmark::State& state) {
  const CSpace cs(bedroom(), {static_cast<int>(state.range(0))});
  const auto poses = random_poses(bedroom(), 4096, 1);
  std::size_t i = 0, free = 0;
  for (auto _ : state) {
    free += cs.is_free(poses[i++ & 4095]);
  }
  benchmark::DoNotOptimize(free);
  state.counters["objects"] = static_cast<double>(bedroom().objects.size());
}
BENCHMARK(BM_PointQuery)->Arg(72);

//! The bedroom with three more small objects (8 in all), the target's setting.
const Scene& bedroom8() {
  static const Scene s = [] {
    Scene b = bedroom();
    const double xy[3][2] = {{3.2, 1.4}, {1.6, 2.2}, {0.7, 3.0}};
    for (int i = 0; i < 3; ++i) {
      hrs::geometry::Object o;
      o.id = "extra" + std::to_string(i);
      o.footprint = {{-0.2, -0.2}, {0.2, -0.2}, {0.2, 0.2}, {-0.2, 0.2}};
      o.pose = {xy[i][0], xy[i][1], 0.3 * i};
      b.objects.push_back(o);
    }
    return b;
  }();
  return s;
}

void BM_PointQuery8Objects(benchmark::State& state) {
  const CSpace cs(bedroom8());
  const auto poses = random_poses(bedroom8(), 4096, 1);
  std::size_t i = 0, free = 0;
  for (auto _ : state) free += cs.is_free(poses[i++ & 4095]);
  benchmark::DoNotOptimize(free);
  state.counters["objects"] = static_cast<double>(bedroom8().objects.size());
}
BENCHMARK(BM_PointQuery8Objects);

//! Point queries restricted to free poses (the planner's common case).
void BM_PointQueryFree(benchmark::State& state) {
  const CSpace cs(bedroom());
  std::vector<Pose2> poses;
  for (const Pose2& p : random_poses(bedroom(), 40000, 2))
    if (cs.is_free(p)) poses.push_back(p);
  std::size_t i = 0, free = 0;
  for (auto _ : state) free += cs.is_free(poses[i++ % poses.size()]);
  benchmark::DoNotOptimize(free);
}
BENCHMARK(BM_PointQueryFree);

//! Straight motions of 0.3 m from free poses.
void BM_StraightCheck(benchmark::State& state) {
  const CSpace cs(bedroom());
  std::vector<Pose2> poses;
  for (const Pose2& p : random_poses(bedroom(), 40000, 3))
    if (cs.is_free(p)) poses.push_back(p);
  std::size_t i = 0, free = 0;
  for (auto _ : state) free += cs.straight_free(poses[i++ % poses.size()], 0.3);
  benchmark::DoNotOptimize(free);
}
BENCHMARK(BM_StraightCheck);

//! Arcs of 45° at the scene's turning radius from free poses.
void BM_ArcCheck(benchmark::State& state) {
  const CSpace cs(bedroom());
  std::vector<Pose2> poses;
  for (const Pose2& p : random_poses(bedroom(), 40000, 4))
    if (cs.is_free(p)) poses.push_back(p);
  const double r = bedroom().wheelchair.turning_radius;
  std::size_t i = 0, free = 0;
  for (auto _ : state) free += cs.arc_free(poses[i++ % poses.size()], r, kPi / 4, 1);
  benchmark::DoNotOptimize(free);
}
BENCHMARK(BM_ArcCheck);

void BM_UpdateTranslate(benchmark::State& state) {
  CSpace cs(bedroom(), {static_cast<int>(state.range(0))});
  Pose2 p = cs.object_pose(0);
  double dx = 0.01;
  for (auto _ : state) {
    p.x += dx;
    dx = -dx;
    cs.move_object(0, p);
  }
}
BENCHMARK(BM_UpdateTranslate)->Arg(72)->Unit(benchmark::kMicrosecond);

void BM_UpdateRotate(benchmark::State& state) {
  CSpace cs(bedroom(), {static_cast<int>(state.range(0))});
  Pose2 p = cs.object_pose(0);
  double dt = 0.05;
  for (auto _ : state) {
    p.theta += dt;
    dt = -dt;
    cs.move_object(0, p);
  }
}
BENCHMARK(BM_UpdateRotate)->Arg(72)->Unit(benchmark::kMicrosecond);

void BM_Build(benchmark::State& state) {
  for (auto _ : state) {
    CSpace cs(bedroom());
    benchmark::DoNotOptimize(cs.piece_count());
  }
}
BENCHMARK(BM_Build)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
