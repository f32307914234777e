// SPDX-License-Identifier: GPL-3.0-or-later
// RS-decomposition (paper §V-A): kd-tree nearest neighbours against brute
// force, deterministic construction, valid predicted paths, and the measured
// prediction accuracy (printed; the paper's setting is a 3 m radius).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <thread>

#include "rs/decomposition.h"
#include "rs/kd_tree.h"
#include "rs/pose_grid.h"
#include "tests/support/poses.h"

namespace hrs::rs {
namespace {

using test_support::goal_tolerance;
using test_support::pose_error;
using test_support::random_pose;

TEST(RsKdTree, NearestMatchesBruteForceWithHeadingWrapAround) {
  std::mt19937_64 rng(31);
  for (double w : {0.1, 1.0, 5.0}) {
    PoseKdTree tree(w);
    std::vector<Pose2> pts;
    for (int i = 0; i < 3000; ++i) {
      Pose2 p = random_pose(rng, 4.0);
      if (i % 10 == 0) p.theta = std::numbers::pi - 1e-3 * (i % 7);  // crowd the seam
      pts.push_back(p);
      tree.insert(p);
    }
    for (int k = 0; k < 3000; ++k) {
      Pose2 q = random_pose(rng, 5.0);
      if (k % 5 == 0) q.theta = -std::numbers::pi + 1e-4 * (k % 3);
      double best = std::numeric_limits<double>::infinity();
      for (const auto& p : pts) best = std::min(best, tree.distance2(p, q));
      const auto nn = tree.nearest(q);
      ASSERT_GE(nn, 0);
      EXPECT_DOUBLE_EQ(tree.distance2(pts[nn], q), best);
    }
  }
}

// The grid the decomposition searches answers like brute force (lowest index
// among equally near points) and like the kd-tree, while it re-buckets as
// points arrive: queries between insertions, inside and outside the box,
// headings crowded at the ±π seam, and grids flat in one axis.
TEST(RsPoseGrid, NearestMatchesBruteForceAndTheKdTreeWhileGrowing) {
  std::mt19937_64 rng(37);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const auto& [w, half_x, half_y] :
       std::vector<std::array<double, 3>>{{0.7, 6.0, 5.0}, {0.1, 3.0, 3.0}, {5.0, 2.0, 0.05}}) {
    PoseGrid grid(w, -half_x, half_x, -half_y, half_y);
    PoseKdTree tree(w);
    std::vector<Pose2> pts;
    EXPECT_EQ(grid.nearest({0, 0, 0}), -1);
    for (int i = 0; i < 6000; ++i) {
      Pose2 p{half_x * u(rng), half_y * u(rng), std::numbers::pi * u(rng)};
      if (i % 10 == 0) p.theta = std::numbers::pi - 1e-3 * (i % 7);  // crowd the seam
      pts.push_back(p);
      grid.insert(p);
      tree.insert(p);
      if (i % 3 != 0) continue;
      // A query inside the box, or up to half its size outside it.
      Pose2 q{1.5 * half_x * u(rng), 1.5 * half_y * u(rng), std::numbers::pi * u(rng)};
      if (i % 5 == 0) q.theta = -std::numbers::pi + 1e-4 * (i % 3);
      std::int32_t brute = -1;
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < pts.size(); ++k) {
        const double d = grid.distance2(pts[k], q);
        if (d < best) best = d, brute = static_cast<std::int32_t>(k);
      }
      const std::int32_t got = grid.nearest(q);
      ASSERT_EQ(got, brute) << "w " << w << " points " << pts.size();
      EXPECT_EQ(tree.distance2(pts[tree.nearest(q)], q), best);
    }
  }
}

DecompositionOptions small_options() {
  DecompositionOptions o;
  o.radius = 0.7;
  o.room_width = 3.0;
  o.room_depth = 2.5;
  return o;
}

TEST(RsDecomposition, IsDeterministicForASeed) {
  std::mt19937_64 r1(7), r2(7), r3(8);
  const Decomposition a(small_options(), r1), b(small_options(), r2), c(small_options(), r3);
  ASSERT_EQ(a.samples().size(), b.samples().size());
  for (std::size_t i = 0; i < a.samples().size(); ++i) {
    EXPECT_EQ(a.samples()[i].pose, b.samples()[i].pose);
    EXPECT_EQ(a.samples()[i].word, b.samples()[i].word);
  }
  EXPECT_NE(a.samples().front().pose, c.samples().front().pose);
}

TEST(RsDecomposition, SamplesCarryTheirShortestWordAndStayInTheDoubledRoom) {
  std::mt19937_64 rng(9);
  const auto o = small_options();
  const Decomposition d(o, rng);
  EXPECT_GE(d.samples().size(), static_cast<std::size_t>(o.initial_samples));
  EXPECT_GE(d.drawn(), static_cast<std::size_t>(o.stop_after));
  for (const auto& s : d.samples()) {
    EXPECT_LE(std::abs(s.pose.x), o.room_width);
    EXPECT_LE(std::abs(s.pose.y), o.room_depth);
    EXPECT_EQ(s.word, shortest_word({}, s.pose, o.radius).word);
  }
  EXPECT_GE(d.region_count(), 10);
  EXPECT_LE(d.region_count(), kWordCount);
}

TEST(RsDecomposition, PredictedPathIsValidWhenReturnedAndNeverShorterThanExact) {
  std::mt19937_64 rng(10);
  const auto o = small_options();
  const Decomposition d(o, rng);
  int returned = 0;
  for (int i = 0; i < 20000; ++i) {
    // Start and goal anywhere in the room, any headings.
    const Pose2 a = random_pose(rng, 1.5), b = random_pose(rng, 1.5);
    const Path exact = d.exact_path(a, b);
    EXPECT_NEAR(exact.length(), shortest_length(a, b, o.radius), 1e-12);
    const auto p = d.predicted_path(a, b);
    if (!p) {
      EXPECT_TRUE(std::isinf(d.predicted_length(a, b)));
      continue;
    }
    ++returned;
    EXPECT_LE(pose_error(end_pose(a, *p), b), goal_tolerance(a, b));
    EXPECT_GE(p->length(), exact.length() - 1e-9 * (1 + exact.length()));
    EXPECT_NEAR(p->length(), d.predicted_length(a, b), 1e-12 * (1 + p->length()));
  }
  EXPECT_GT(returned, 0);
}

// The look-up grid answers the shortest word at the centre of the query's
// cell; with the grid off, the word of the sample nearest the query. Both
// checked against the kd-tree (itself checked against brute force above) on
// queries from many start poses, including relative poses outside the
// sampled box (answered exactly there) and from several threads at once
// (cells filled concurrently must hold the same words).
TEST(RsDecomposition, GridAnswersTheShortestWordAtItsCellCentre) {
  DecompositionOptions o = small_options();
  std::mt19937_64 r1(5), r2(5);
  const Decomposition grid(o, r1);
  o.grid_cell = 0.0;
  const Decomposition plain(o, r2);
  ASSERT_EQ(grid.samples().size(), plain.samples().size());
  std::mt19937_64 rng(17);
  std::vector<std::pair<Pose2, Pose2>> queries;
  for (int i = 0; i < 20000; ++i) {
    const Pose2 a = random_pose(rng, 3.0);
    queries.push_back({a, random_pose(rng, i % 4 == 0 ? 8.0 : 2.5)});
  }
  std::vector<int> words(queries.size());
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for (std::size_t i = t; i < queries.size(); i += 4)
        words[i] = grid.predict_word(queries[i].first, queries[i].second);
    });
  for (auto& th : threads) th.join();
  const double cell = grid.options().grid_cell, pi = std::numbers::pi;
  int inside = 0, outside = 0, agree_with_query = 0;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const auto& [a, b] = queries[i];
    EXPECT_EQ(plain.predict_word(a, b), plain.nearest_word(a, b));
    EXPECT_EQ(grid.predict_word(a, b), words[i]);  // same answer once filled
    // The relative pose and its cell centre.
    const double c = std::cos(a.theta), s = std::sin(a.theta);
    const Pose2 q{c * (b.x - a.x) + s * (b.y - a.y), -s * (b.x - a.x) + c * (b.y - a.y),
                  geometry::wrap_angle(b.theta - a.theta)};
    const int nx = static_cast<int>(std::ceil(2 * o.room_width / cell));
    const int ny = static_cast<int>(std::ceil(2 * o.room_depth / cell));
    const int nt = static_cast<int>(std::ceil(2 * pi / grid.options().grid_angle));
    const double cx = 2 * o.room_width / nx, cy = 2 * o.room_depth / ny, ct = 2 * pi / nt;
    const double fx = (q.x + o.room_width) / cx, fy = (q.y + o.room_depth) / cy;
    if (!(fx >= 0 && fx < nx && fy >= 0 && fy < ny)) {
      // Outside the box: the exact answer, not a sample's.
      ++outside;
      EXPECT_EQ(words[i], shortest_word({}, q, o.radius).word) << i;
      EXPECT_EQ(grid.predicted_length(a, b), shortest_length(a, b, o.radius)) << i;
      const auto p = grid.predicted_path(a, b);
      ASSERT_TRUE(p.has_value());
      EXPECT_EQ(p->segments, shortest_path(a, b, o.radius).segments) << i;
      continue;
    }
    ++inside;
    const int it = std::clamp(static_cast<int>((q.theta + pi) / ct), 0, nt - 1);
    const Pose2 centre{-o.room_width + (static_cast<int>(fx) + 0.5) * cx,
                       -o.room_depth + (static_cast<int>(fy) + 0.5) * cy, -pi + (it + 0.5) * ct};
    EXPECT_EQ(words[i], shortest_word({}, centre, o.radius).word) << i;
    if (words[i] == shortest_word(a, b, o.radius).word) ++agree_with_query;
  }
  EXPECT_GT(inside, 8000);
  EXPECT_GT(outside, 1000);
  // A cell is 5 cm × 5°: its centre's word is mostly the query's own.
  EXPECT_GT(agree_with_query, 0.8 * inside);
  std::printf("grid: %d of %d in-box queries answer the query's own shortest word (%.1f%%)\n",
              agree_with_query, inside, 100.0 * agree_with_query / inside);
}

void report(const char* name, const DecompositionOptions& o, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const Decomposition d(o, rng);
  const auto acc = d.evaluate(100000, rng);
  std::printf(
      "%s: r=%.2f m, room %.1f x %.1f m: %zu samples (%zu drawn while refining), "
      "%d regions; predicted word shortest in %.2f%% of %d queries, infeasible "
      "%.2f%%, mean excess %.4f m (%.2f%%) over %d feasible mispredictions\n",
      name, o.radius, o.room_width, o.room_depth, d.samples().size(), d.drawn(), d.region_count(),
      100.0 * acc.word_accuracy, acc.queries, 100.0 * acc.infeasible_fraction, acc.mean_excess,
      100.0 * acc.mean_relative_excess, acc.mispredicted_feasible);
  EXPECT_GT(acc.word_accuracy, 0.5);
  EXPECT_GE(acc.mean_excess, 0.0);
}

TEST(RsDecomposition, ReportsAccuracyForTheWheelchair) { report("wheelchair", small_options(), 1); }

TEST(RsDecomposition, ReportsAccuracyInThePapersSetting) {
  DecompositionOptions o;
  o.radius = 3.0;  // §V-A: "rotational radius ... three meters"
  o.room_width = 4.0;
  o.room_depth = 4.0;
  report("paper", o, 1);
}

}  // namespace
}  // namespace hrs::rs
