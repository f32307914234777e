// SPDX-License-Identifier: GPL-3.0-or-later
// The C++ side of the Python module's benchmark (docs/BENCHMARKS.md,
// "Python bindings"): is_free over 10^6 poses in one loop, as
// hrspace.CSpace.is_free runs it for an (N, 3) array (bench/python_is_free.py
// times the Python call). Poses: uniform over the bedroom's bounding box,
// heading uniform in [-pi, pi), read from a contiguous x, y, theta array into
// a byte per answer, as the module does. Run:
//   build/bench/batch_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>

#include <cstdint>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "geometry/cspace.h"
#include "geometry/scene.h"

namespace {

using hrs::geometry::CSpace;
using hrs::geometry::Scene;

constexpr std::size_t kPoses = 1'000'000;

const Scene& bedroom() {
  static const Scene s =
      hrs::geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/scenes/bedroom.json");
  return s;
}

//! x, y, theta per pose, contiguous (the layout of a C-ordered (N, 3) array).
std::vector<double> random_poses(const Scene& s, std::size_t n, std::uint64_t seed) {
  const hrs::geometry::Box b = hrs::geometry::bounding_box(s.room.polygon);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(b.xmin, b.xmax), uy(b.ymin, b.ymax),
      ut(-std::numbers::pi, std::numbers::pi);
  std::vector<double> out(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    out[3 * i] = ux(rng);
    out[3 * i + 1] = uy(rng);
    out[3 * i + 2] = ut(rng);
  }
  return out;
}

void BM_IsFreeMillion(benchmark::State& state) {
  const CSpace cs(bedroom());
  const std::vector<double> poses = random_poses(bedroom(), kPoses, 1);
  std::vector<std::uint8_t> free(kPoses);
  for (auto _ : state) {
    const double* d = poses.data();
    for (std::size_t i = 0; i < kPoses; ++i)
      free[i] = cs.is_free({d[3 * i], d[3 * i + 1], d[3 * i + 2]});
    benchmark::DoNotOptimize(free.data());
    benchmark::ClobberMemory();
  }
  std::size_t n = 0;
  for (auto f : free) n += f;
  state.counters["free_fraction"] = static_cast<double>(n) / kPoses;
  state.counters["ns_per_pose"] =
      benchmark::Counter(static_cast<double>(kPoses), benchmark::Counter::kIsIterationInvariantRate |
                                                          benchmark::Counter::kInvert);
}
BENCHMARK(BM_IsFreeMillion)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
