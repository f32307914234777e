// SPDX-License-Identifier: GPL-3.0-or-later
// The annealer on toy costs: finds a known optimum, the Metropolis rule is
// exact, fixed objects never move, invalid moves are never evaluated; early
// rejection (Acceptance::rejects) rejects a bound only when every cost above
// it is rejected, so costs that stop at a rejected bound decide the same.
#include "optimize/annealer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <string>

#include "geometry/random.h"

namespace hrs::optimize {
namespace {

TEST(Annealer, AcceptanceProbabilityIsMetropolis) {
  EXPECT_EQ(acceptance_probability(-1.0, 0.5), 1.0);
  EXPECT_EQ(acceptance_probability(0.0, 0.5), 1.0);
  EXPECT_DOUBLE_EQ(acceptance_probability(1.0, 0.5), std::exp(-2.0));
  EXPECT_DOUBLE_EQ(acceptance_probability(0.3, 2.0), std::exp(-0.15));
  EXPECT_EQ(acceptance_probability(1.0, 0.0), 0.0);
  EXPECT_TRUE(metropolis_accept(0.1, 1.0, std::exp(-0.1) - 1e-12));
  EXPECT_FALSE(metropolis_accept(0.1, 1.0, std::exp(-0.1)));
  EXPECT_TRUE(metropolis_accept(-5.0, 1e-9, 0.999999));
}

TEST(Annealer, CoolingIsGeometricFromStartToEnd) {
  AnnealOptions o;
  o.iterations = 11;
  o.t_start = 2.0;
  o.t_end = 2e-3;
  EXPECT_DOUBLE_EQ(temperature_at(o, 0), 2.0);
  EXPECT_NEAR(temperature_at(o, 10), 2e-3, 1e-15);
  for (int k = 1; k < 10; ++k)
    EXPECT_NEAR(temperature_at(o, k + 1) / temperature_at(o, k), std::pow(1e-3, 0.1), 1e-12);
}

// Every valid proposal raises the cost by exactly delta at a constant
// temperature: the acceptance rate must be exp(−delta/t).
TEST(Annealer, EmpiricalAcceptanceRateMatchesExpMinusDeltaOverT) {
  for (double ratio : {0.1, 0.5, 1.0, 2.0}) {
    AnnealOptions o;
    o.iterations = 20000;
    o.t_start = o.t_end = 0.7;
    const double delta = ratio * 0.7;
    double current = 0.0;
    AnnealCallbacks cb;
    cb.move_valid = [](const std::vector<Pose2>&, int) { return true; };
    cb.cost = [&](const std::vector<Pose2>&, const Move& m, const Acceptance&) {
      return m.object < 0 ? 0.0 : current + delta;
    };
    cb.progress = [&](const TraceEntry& e) { current = e.current_cost; };
    std::mt19937_64 rng(7);
    const auto r = anneal({Pose2{}}, {true}, o, cb, rng);
    const double p = std::exp(-ratio);
    const double rate = static_cast<double>(r.accepted) / r.valid_proposals;
    const double sigma = std::sqrt(p * (1 - p) / r.valid_proposals);
    EXPECT_NEAR(rate, p, 4.5 * sigma) << "delta/t = " << ratio;
    EXPECT_EQ(r.valid_proposals, o.iterations);
  }
}

TEST(Annealer, FindsTheKnownOptimumOfAToyCostAndNeverMovesFixedObjects) {
  // Two movable objects in the box [0, 4]², at least 0.5 apart, pulled to
  // targets; a third object is fixed. Optimum: the targets, cost 0.
  const Pose2 fixed{3.5, 3.5, 0.25};
  const Pose2 target0{1.0, 2.5, 1.2}, target1{3.0, 0.7, -2.9};
  auto sq = [](double v) { return v * v; };
  AnnealCallbacks cb;
  cb.move_valid = [&](const std::vector<Pose2>& p, int moved) {
    EXPECT_NE(moved, 2);
    const Pose2& q = p[moved];
    if (q.x < 0 || q.x > 4 || q.y < 0 || q.y > 4) return false;
    return std::hypot(p[0].x - p[1].x, p[0].y - p[1].y) >= 0.5;
  };
  cb.cost = [&](const std::vector<Pose2>& p, const Move&, const Acceptance&) {
    EXPECT_EQ(p[2], fixed);
    double c = 0.0;
    for (int i = 0; i < 2; ++i) {
      const Pose2& t = i == 0 ? target0 : target1;
      c += sq(p[i].x - t.x) + sq(p[i].y - t.y) + sq(geometry::wrap_angle(p[i].theta - t.theta));
    }
    return c;
  };
  AnnealOptions o;
  o.iterations = 4000;
  o.t_start = 2.0;
  o.t_end = 1e-5;
  o.step_end = 0.005;
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    std::mt19937_64 rng(seed);
    const auto r =
        anneal({{0.5, 0.5, 0.0}, {0.6, 0.6, 3.0}, fixed}, {true, true, false}, o, cb, rng);
    ASSERT_TRUE(r.best_valid);
    EXPECT_LT(r.best_cost, 1e-3) << "seed " << seed;
    EXPECT_NEAR(r.best[0].x, target0.x, 0.03);
    EXPECT_NEAR(r.best[0].y, target0.y, 0.03);
    EXPECT_NEAR(r.best[1].theta, target1.theta, 0.03);
    EXPECT_EQ(r.best[2], fixed);
    EXPECT_LT(r.best_cost, r.initial_cost);
  }
}

TEST(Annealer, InvalidMovesAreNeverEvaluated) {
  int evaluations = 0;
  AnnealCallbacks cb;
  cb.move_valid = [](const std::vector<Pose2>&, int) { return false; };
  cb.cost = [&](const std::vector<Pose2>&, const Move&, const Acceptance&) { return ++evaluations, 1.0; };
  AnnealOptions o;
  o.iterations = 100;
  std::mt19937_64 rng(3);
  const auto r = anneal({{1, 1, 0}, {2, 2, 0}}, {true, true}, o, cb, rng);
  EXPECT_EQ(evaluations, 1);  // the initial layout only
  EXPECT_EQ(r.valid_proposals, 0);
  EXPECT_EQ(r.accepted, 0);
  EXPECT_EQ(r.final_poses, (std::vector<Pose2>{{1, 1, 0}, {2, 2, 0}}));
  for (const auto& e : r.trace) EXPECT_TRUE(std::isnan(e.proposed_cost));
}

TEST(Annealer, RejectedMovesAreUndoneAndReported) {
  int rejected = 0;
  AnnealCallbacks cb;
  cb.move_valid = [](const std::vector<Pose2>&, int) { return true; };
  cb.cost = [](const std::vector<Pose2>&, const Move& m, const Acceptance&) { return m.object < 0 ? 0.0 : 1e9; };
  cb.rejected = [&](const Move& m) {
    ++rejected;
    EXPECT_NE(m.from, m.to);
  };
  AnnealOptions o;
  o.iterations = 200;
  std::mt19937_64 rng(4);
  const auto r = anneal({{1, 1, 0}}, {true}, o, cb, rng);
  EXPECT_EQ(rejected, 200);
  EXPECT_EQ(r.accepted, 0);
  EXPECT_EQ(r.final_poses[0], (Pose2{1, 1, 0}));
  EXPECT_EQ(r.best_cost, 0.0);
}

TEST(Annealer, BestIsTheMinimumOverValidAcceptedLayoutsAndRunsAreSeeded) {
  AnnealCallbacks cb;
  cb.move_valid = [](const std::vector<Pose2>& p, int) { return std::abs(p[0].x) < 3; };
  cb.cost = [](const std::vector<Pose2>& p, const Move&, const Acceptance&) {
    return std::sin(3 * p[0].x) + 0.1 * p[0].y * p[0].y;
  };
  // Layouts with y < 0 count as not fully valid: never the best.
  cb.layout_valid = [](const std::vector<Pose2>& p) { return p[0].y >= 0; };
  AnnealOptions o;
  o.iterations = 500;
  std::mt19937_64 a(11), b(11);
  const auto r1 = anneal({{0, 1, 0}}, {true}, o, cb, a);
  const auto r2 = anneal({{0, 1, 0}}, {true}, o, cb, b);
  ASSERT_EQ(r1.trace.size(), r2.trace.size());
  for (std::size_t i = 0; i < r1.trace.size(); ++i)
    EXPECT_EQ(r1.trace[i].current_cost, r2.trace[i].current_cost);
  EXPECT_EQ(r1.best, r2.best);
  EXPECT_GE(r1.best[0].y, 0.0);
  double min_valid = r1.initial_cost;
  double previous = r1.initial_cost;
  for (const auto& e : r1.trace) {
    EXPECT_LE(e.best_cost, previous);  // never forgets a better layout
    previous = e.best_cost;
    min_valid = std::min(min_valid, e.best_cost);
  }
  EXPECT_EQ(r1.best_cost, min_valid);
  EXPECT_NEAR(r1.best_cost, std::sin(3 * r1.best[0].x) + 0.1 * r1.best[0].y * r1.best[0].y, 1e-12);
}

TEST(Annealer, JumpsLandInTheBoundsAndOnlyWhileHot) {
  AnnealOptions o;
  o.iterations = 4000;
  o.bounds = std::array<double, 4>{-1.0, 2.0, 3.0, 5.0};
  int early = 0, late = 0, without = 0;
  AnnealCallbacks cb;
  cb.move_valid = [](const std::vector<Pose2>&, int) { return true; };
  cb.cost = [](const std::vector<Pose2>&, const Move&, const Acceptance&) { return 0.0; };
  int k = 0;
  cb.rejected = [](const Move&) {};
  cb.progress = [&](const TraceEntry&) { ++k; };
  auto watch = cb;
  watch.cost = [&](const std::vector<Pose2>& p, const Move& m, const Acceptance&) {
    if (m.jump) {
      EXPECT_FALSE(m.rotation);
      EXPECT_GE(p[0].x, -1.0);
      EXPECT_LE(p[0].x, 3.0);
      EXPECT_GE(p[0].y, 2.0);
      EXPECT_LE(p[0].y, 5.0);
      (k < 1000 ? early : late) += 1;
    }
    return 0.0;
  };
  std::mt19937_64 rng(5);
  anneal({{10, 10, 0}}, {true}, o, watch, rng);
  EXPECT_GT(early, 50);
  EXPECT_LT(late, early);
  o.bounds.reset();
  watch.cost = [&](const std::vector<Pose2>&, const Move& m, const Acceptance&) { return without += m.jump, 0.0; };
  std::mt19937_64 rng2(5);
  anneal({{10, 10, 0}}, {true}, o, watch, rng2);
  EXPECT_EQ(without, 0);
}

//! A random double in [a, b).
double uniform(std::mt19937_64& rng, double a, double b) { return a + (b - a) * uniform01(rng); }

TEST(Annealer, AcceptanceRejectsABoundOnlyWhenEveryCostAboveItIsRejected) {
  // rejects(lb) ⇒ !metropolis_accept(c − current, t, u) for every c >= lb:
  // the cost may stop at a lower bound and the decision is the same. Bounds
  // are drawn around the decision's threshold current − t·ln(u) (to within
  // a few ulps up to a few temperatures), at scales 1e-3 … 1e4, with t = 0
  // and u = 0 among them. An inactive Acceptance never rejects.
  std::mt19937_64 rng(20261123);
  int rejected = 0, kept = 0, near_threshold = 0;
  for (int i = 0; i < 400'000; ++i) {
    const double scale = std::pow(10.0, uniform(rng, -3.0, 4.0));
    const double current = (rng() % 8 == 0 ? -1.0 : 1.0) * scale * uniform(rng, 0.0, 10.0);
    const double t = rng() % 16 == 0 ? 0.0 : scale * std::pow(10.0, uniform(rng, -6.0, 0.5));
    const double u = rng() % 64 == 0 ? 0.0 : uniform01(rng);
    const double threshold = u > 0.0 && t > 0.0 ? current - t * std::log(u) : current;
    double lb;
    switch (rng() % 4) {
      case 0:  // ulps from the threshold
        lb = threshold;
        for (int s = static_cast<int>(rng() % 41) - 20; s != 0; s += s > 0 ? -1 : 1)
          lb = std::nextafter(lb, s > 0 ? INFINITY : -INFINITY);
        break;
      case 1:  // relative 1e-12 … 1e-6 from the threshold, either side
        lb = threshold *
             (1.0 + (rng() % 2 ? 1 : -1) * std::pow(10.0, uniform(rng, -12.0, -6.0)));
        break;
      case 2:  // a few temperatures (or scales) around it
        lb = threshold + uniform(rng, -3.0, 3.0) * (t > 0.0 ? t : scale);
        break;
      default:  // anywhere at the scale
        lb = uniform(rng, -2.0, 12.0) * scale;
        break;
    }
    near_threshold += std::abs(lb - threshold) <= 1e-8 * std::max(1.0, std::abs(threshold));
    const Acceptance inactive{false, current, t, u};
    ASSERT_FALSE(inactive.rejects(lb));
    const Acceptance a{true, current, t, u};
    const std::string what = "current " + std::to_string(current) + " t " + std::to_string(t) +
                             " u " + std::to_string(u) + " lb " + std::to_string(lb);
    // Not vacuous: a cost 2e-9 (relative) below the bound that the rule
    // rejects makes the bound rejected (the documented margin is 1e-9).
    const double below = lb - 2e-9 * std::max(1.0, std::abs(lb));
    if (!metropolis_accept(below - current, t, u)) {
      ASSERT_TRUE(a.rejects(lb)) << what;
    }
    if (!a.rejects(lb)) {
      ++kept;
      continue;
    }
    ++rejected;
    const double costs[] = {lb,
                            lb + std::abs(lb) * 1e-15,
                            std::nextafter(lb, INFINITY),
                            lb * (1 + 1e-15),
                            lb + std::abs(lb) * uniform(rng, 0.0, 1e-6),
                            lb + uniform(rng, 0.0, 10.0) * (t > 0.0 ? t : scale),
                            lb + scale * uniform(rng, 0.0, 1e3),
                            INFINITY};
    for (const double c : costs) {
      if (!(c >= lb)) continue;  // lb·(1 + 1e-15) is below a negative lb
      ASSERT_FALSE(metropolis_accept(c - current, t, u)) << what << " c " << c;
    }
  }
  std::printf("rejected %d, not rejected %d, bounds within 1e-8 of the threshold %d\n", rejected,
              kept, near_threshold);
  EXPECT_GT(rejected, 50'000);
  EXPECT_GT(kept, 50'000);
  EXPECT_GT(near_threshold, 100'000);
}

TEST(Annealer, CostsThatStopAtARejectedBoundMakeTheSameDecisions) {
  // A toy cost of two parts (a cheap one known first, then the rest): a
  // run whose cost returns the first part alone whenever acceptance rejects
  // it makes the same decisions, the same chain and the same best layout as
  // the run that always returns the whole cost.
  auto part1 = [](const Pose2& p) {
    return p.x * p.x + (p.y - 1) * (p.y - 1) + 0.3 * std::abs(p.theta) + std::sin(4 * p.x);
  };
  auto part2 = [](const Pose2& p) { return 0.02 * (1.5 + std::sin(5 * p.x + p.y)); };
  for (std::uint64_t seed : {1u, 2u, 3u, 4u}) {
    AnnealResult r[2];
    int stopped_early = 0;
    for (int early = 0; early < 2; ++early) {
      AnnealCallbacks cb;
      cb.move_valid = [](const std::vector<Pose2>& p, int) { return std::abs(p[0].x) < 4; };
      cb.cost = [&, early](const std::vector<Pose2>& p, const Move&, const Acceptance& a) {
        double c = part1(p[0]) + part1(p[1]);
        if (early && a.rejects(c)) return ++stopped_early, c;
        return c + part2(p[0]) + part2(p[1]);
      };
      AnnealOptions o;
      o.iterations = 3000;
      o.t_start = 1.0;
      o.t_end = 1e-3;
      std::mt19937_64 rng(seed);
      r[early] = anneal({{2, 1, 0.5}, {-1, 2, 3}}, {true, true}, o, cb, rng);
    }
    ASSERT_EQ(r[0].trace.size(), r[1].trace.size());
    for (std::size_t i = 0; i < r[0].trace.size(); ++i) {
      ASSERT_EQ(r[0].trace[i].accepted, r[1].trace[i].accepted) << "seed " << seed << " step " << i;
      ASSERT_EQ(r[0].trace[i].valid, r[1].trace[i].valid) << "seed " << seed << " step " << i;
      ASSERT_EQ(r[0].trace[i].current_cost, r[1].trace[i].current_cost) << "seed " << seed;
    }
    EXPECT_EQ(r[0].best, r[1].best);
    EXPECT_EQ(r[0].best_cost, r[1].best_cost);
    EXPECT_EQ(r[0].final_poses, r[1].final_poses);
    EXPECT_EQ(r[0].accepted, r[1].accepted);
    std::printf("seed %d: %d of %d valid proposals stopped at the bound\n", static_cast<int>(seed),
                stopped_early, r[1].valid_proposals);
    EXPECT_GT(stopped_early, 300) << "seed " << seed;
  }
}

}  // namespace
}  // namespace hrs::optimize
