// RS-decomposition (paper §V-A): kd-tree nearest neighbours against brute
// force, deterministic construction, valid predicted paths, and the measured
// prediction accuracy (printed; the paper's setting is a 3 m radius).

#include <gtest/gtest.h>

#include <cstdio>
#include <numbers>
#include <random>

#include "rs/decomposition.h"
#include "rs/kd_tree.h"
#include "tests/rs/fixtures.h"

namespace hrs::rs {
namespace {

using test::goal_tolerance;
using test::pose_error;
using test::random_pose;

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
  EXPECT_LE(acc.word_accuracy, 1.0);
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
