// SPDX-License-Identifier: GPL-3.0-or-later
// Reeds–Shepp micro-benchmarks (paper §III-B, §V-A): our exact shortest
// length and path against OMPL's ReedsSheppStateSpace::distance on the same
// random pairs, the RS-decomposition look-up, and sampling a path.
//
// Pairs: 4096 random pairs, start and goal uniform in a box of half-size
// 5 m (headings uniform), turning radius 0.7 m, fixed seed. "near" variants
// use a 1 m box (most queries within 2 radii, where the CCC/CCCC families
// compete and pruning helps least). The decomposition is built for a 5 m x
// 5 m room (samples in a 10 m x 10 m box around the start): "far" queries
// partly fall outside it, where the kd-tree prunes poorly.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <ompl/base/spaces/ReedsSheppStateSpace.h>

#include "rs/decomposition.h"
#include "rs/kd_tree.h"
#include "rs/pose_grid.h"
#include "rs/reeds_shepp.h"

namespace {

using hrs::rs::Pose2;
namespace ob = ompl::base;

constexpr double kRadius = 0.7;

struct Pair {
  Pose2 a, b;
};

std::vector<Pair> make_pairs(double half, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> pos(-half, half);
  std::uniform_real_distribution<double> ang(-std::numbers::pi, std::numbers::pi);
  std::vector<Pair> pairs(4096);
  for (auto& p : pairs) {
    p.a = {pos(rng), pos(rng), ang(rng)};
    p.b = {pos(rng), pos(rng), ang(rng)};
  }
  return pairs;
}

const std::vector<Pair>& pairs_for(int which) {
  static const std::vector<Pair> far = make_pairs(5.0, 42);
  static const std::vector<Pair> near = make_pairs(1.0, 43);
  return which == 0 ? far : near;
}

void BM_RsShortestLength(benchmark::State& state) {
  const auto& pairs = pairs_for(static_cast<int>(state.range(0)));
  std::size_t i = 0;
  for (auto _ : state) {
    const Pair& p = pairs[i++ & 4095];
    benchmark::DoNotOptimize(hrs::rs::shortest_length(p.a, p.b, kRadius));
  }
  state.SetLabel(state.range(0) == 0 ? "far" : "near");
}
BENCHMARK(BM_RsShortestLength)->Arg(0)->Arg(1);

//! The same solver at each pruning level (second argument): 0 evaluates all
//! 48 words, 1 skips families by their bounds (the solver before the
//! per-candidate pre-checks), 2 is what shortest_length uses.
void BM_RsShortestPruning(benchmark::State& state) {
  const auto& pairs = pairs_for(static_cast<int>(state.range(0)));
  const auto level = static_cast<hrs::rs::Pruning>(state.range(1));
  std::size_t i = 0;
  for (auto _ : state) {
    const Pair& p = pairs[i++ & 4095];
    benchmark::DoNotOptimize(hrs::rs::shortest_word(p.a, p.b, kRadius, level));
  }
  const char* names[] = {"none", "family bounds", "full"};
  state.SetLabel(std::string(state.range(0) == 0 ? "far, " : "near, ") + names[state.range(1)]);
}
BENCHMARK(BM_RsShortestPruning)->ArgsProduct({{0, 1}, {0, 1, 2}});

void BM_RsShortestPath(benchmark::State& state) {
  const auto& pairs = pairs_for(static_cast<int>(state.range(0)));
  std::size_t i = 0;
  for (auto _ : state) {
    const Pair& p = pairs[i++ & 4095];
    benchmark::DoNotOptimize(hrs::rs::shortest_path(p.a, p.b, kRadius));
  }
  state.SetLabel(state.range(0) == 0 ? "far" : "near");
}
BENCHMARK(BM_RsShortestPath)->Arg(0)->Arg(1);

void BM_OmplDistance(benchmark::State& state) {
  const auto& pairs = pairs_for(static_cast<int>(state.range(0)));
  ob::ReedsSheppStateSpace space(kRadius);
  auto* a = space.allocState()->as<ob::SE2StateSpace::StateType>();
  auto* b = space.allocState()->as<ob::SE2StateSpace::StateType>();
  std::vector<std::pair<ob::State*, ob::State*>> states;
  for (const Pair& p : pairs) {
    auto* sa = space.allocState()->as<ob::SE2StateSpace::StateType>();
    auto* sb = space.allocState()->as<ob::SE2StateSpace::StateType>();
    sa->setXY(p.a.x, p.a.y), sa->setYaw(p.a.theta);
    sb->setXY(p.b.x, p.b.y), sb->setYaw(p.b.theta);
    states.emplace_back(sa, sb);
  }
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& s = states[i++ & 4095];
    benchmark::DoNotOptimize(space.distance(s.first, s.second));
  }
  for (auto& s : states) space.freeState(s.first), space.freeState(s.second);
  space.freeState(a), space.freeState(b);
  state.SetLabel(state.range(0) == 0 ? "far" : "near");
}
BENCHMARK(BM_OmplDistance)->Arg(0)->Arg(1);

//! The RRT's pick among its k = 10 nearest nodes (rs::first_shortest):
//! 512 sets, each the 10 nodes of a 2000-pose cloud (5 m box) nearest to a
//! random target by the planner's weighted distance (heading 0.7 m/rad).
//! Arg 0 is first_shortest, whose later solves are capped just above the
//! best length so far; arg 1 is the previous method on the same sets: the
//! same order by lower bound, each pose solved in full.
struct PickSet {
  std::vector<Pose2> from;
  Pose2 to;
};
const std::vector<PickSet>& pick_sets() {
  static const std::vector<PickSet> sets = [] {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> pos(-5.0, 5.0), ang(-std::numbers::pi, std::numbers::pi);
    std::vector<Pose2> cloud(2000);
    for (auto& p : cloud) p = {pos(rng), pos(rng), ang(rng)};
    std::vector<PickSet> out(512);
    std::vector<std::pair<double, std::size_t>> order;
    for (auto& s : out) {
      s.to = {pos(rng), pos(rng), ang(rng)};
      order.clear();
      for (std::size_t i = 0; i < cloud.size(); ++i) {
        const double dx = cloud[i].x - s.to.x, dy = cloud[i].y - s.to.y;
        const double dt = hrs::geometry::wrap_angle(cloud[i].theta - s.to.theta);
        order.emplace_back(dx * dx + dy * dy + 0.49 * dt * dt, i);
      }
      std::partial_sort(order.begin(), order.begin() + 10, order.end());
      for (int k = 0; k < 10; ++k) s.from.push_back(cloud[order[k].second]);
    }
    return out;
  }();
  return sets;
}
std::size_t pick_uncapped(const PickSet& s, std::vector<std::pair<double, std::size_t>>& scratch) {
  scratch.clear();
  for (std::size_t i = 0; i < s.from.size(); ++i)
    scratch.emplace_back(hrs::rs::length_lower_bound(s.from[i], s.to, kRadius), i);
  std::sort(scratch.begin(), scratch.end());
  std::size_t best = s.from.size();
  double best_length = std::numeric_limits<double>::infinity();
  for (const auto& [bound, i] : scratch) {
    if (bound > best_length + 1e-9 * (1.0 + best_length)) break;
    const double d = hrs::rs::shortest_length(s.from[i], s.to, kRadius);
    if (d < best_length || (best < s.from.size() && d == best_length && i < best))
      best_length = d, best = i;
  }
  return best;
}
void BM_RsFirstShortest(benchmark::State& state) {
  const auto& sets = pick_sets();
  std::vector<std::pair<double, std::size_t>> scratch;
  std::size_t i = 0;
  for (auto _ : state) {
    const PickSet& s = sets[i++ & 511];
    if (state.range(0) == 0)
      benchmark::DoNotOptimize(hrs::rs::first_shortest(s.from, s.to, kRadius, scratch));
    else
      benchmark::DoNotOptimize(pick_uncapped(s, scratch));
  }
  state.SetLabel(state.range(0) == 0 ? "k=10, capped" : "k=10, previous (uncapped)");
}
BENCHMARK(BM_RsFirstShortest)->Arg(0)->Arg(1);

const hrs::rs::Decomposition& decomposition() {
  static const hrs::rs::Decomposition d = [] {
    hrs::rs::DecompositionOptions o;
    o.radius = kRadius;
    o.room_width = 5.0;
    o.room_depth = 5.0;
    std::mt19937_64 rng(1);
    return hrs::rs::Decomposition(o, rng);
  }();
  return d;
}

//! Paper mode: nearest sample's word (kd-tree), then that word alone.
void BM_RsDecompositionPredictedLength(benchmark::State& state) {
  const auto& pairs = pairs_for(static_cast<int>(state.range(0)));
  const auto& d = decomposition();
  std::size_t i = 0;
  for (auto _ : state) {
    const Pair& p = pairs[i++ & 4095];
    benchmark::DoNotOptimize(d.predicted_length(p.a, p.b));
  }
  state.SetLabel(std::to_string(d.samples().size()) + " samples, " +
                 (state.range(0) == 0 ? "far" : "near"));
}
BENCHMARK(BM_RsDecompositionPredictedLength)->Arg(0)->Arg(1);

//! The kd-tree look-up alone.
void BM_RsDecompositionPredictWord(benchmark::State& state) {
  const auto& pairs = pairs_for(static_cast<int>(state.range(0)));
  const auto& d = decomposition();
  std::size_t i = 0;
  for (auto _ : state) {
    const Pair& p = pairs[i++ & 4095];
    benchmark::DoNotOptimize(d.predict_word(p.a, p.b));
  }
  state.SetLabel(state.range(0) == 0 ? "far" : "near");
}
BENCHMARK(BM_RsDecompositionPredictWord)->Arg(0)->Arg(1);

void BM_RsSample(benchmark::State& state) {
  const auto& pairs = pairs_for(0);
  std::vector<hrs::rs::Path> paths;
  for (int k = 0; k < 256; ++k)
    paths.push_back(hrs::rs::shortest_path(pairs[k].a, pairs[k].b, kRadius));
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ & 255;
    benchmark::DoNotOptimize(hrs::rs::sample(pairs[k].a, paths[k], 0.05));
  }
  state.SetLabel("step 0.05 m, paths ~7 m");
}
BENCHMARK(BM_RsSample);

//! The decomposition build's nearest-sample search: the bucket grid against
//! the kd-tree on the same 45 000 samples and queries, uniform in a living
//! room's doubled box (±6 m × ±5 m × ±π, heading weight 0.7 m/rad).
template <class Index>
void nearest_in_box(benchmark::State& state, Index& index) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> x(-6.0, 6.0), y(-5.0, 5.0),
      t(-std::numbers::pi, std::numbers::pi);
  for (int k = 0; k < 45'000; ++k) index.insert({x(rng), y(rng), t(rng)});
  std::vector<Pose2> queries(4096);
  for (auto& q : queries) q = {x(rng), y(rng), t(rng)};
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(index.nearest(queries[i++ & 4095]));
  state.SetLabel("45000 samples");
}
void BM_PoseGridNearest(benchmark::State& state) {
  hrs::rs::PoseGrid grid(kRadius, -6.0, 6.0, -5.0, 5.0);
  nearest_in_box(state, grid);
}
BENCHMARK(BM_PoseGridNearest);
void BM_PoseKdTreeNearest(benchmark::State& state) {
  hrs::rs::PoseKdTree tree(kRadius);
  nearest_in_box(state, tree);
}
BENCHMARK(BM_PoseKdTreeNearest);

//! A whole decomposition build for the living room (6 m × 5 m, r = 0.7 m).
void BM_RsDecompositionBuild(benchmark::State& state) {
  hrs::rs::DecompositionOptions o;
  o.radius = kRadius;
  o.room_width = 6.0;
  o.room_depth = 5.0;
  std::size_t samples = 0;
  for (auto _ : state) {
    std::mt19937_64 rng(1);
    hrs::rs::Decomposition d(o, rng);
    samples = d.samples().size();
    benchmark::DoNotOptimize(samples);
  }
  state.SetLabel(std::to_string(samples) + " samples");
}
BENCHMARK(BM_RsDecompositionBuild)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
