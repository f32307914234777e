// SPDX-License-Identifier: GPL-3.0-or-later
// The nearest-node index against a linear scan (insertions, removals,
// heading wrap), the fixed-query order against the index, and the path
// operations the planner builds trees with.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <iterator>
#include <numbers>
#include <random>
#include <vector>

#include "geometry/random.h"
#include "planning/nearest.h"
#include "planning/path_ops.h"
#include "rs/reeds_shepp.h"

namespace hrs::planning {
namespace {

using geometry::Pose2;
using hrs::uniform01;

TEST(PoseNearest, KdTreeMatchesLinearScanIncludingHeadingWrap) {
  std::mt19937_64 rng(7);
  PoseNearest tree(0.7);
  std::vector<Pose2> poses;
  for (int i = 0; i < 4000; ++i) {
    // Half the headings crowd around ±pi, where wrap-around matters.
    const double t = (i % 2)
                         ? std::numbers::pi * (2 * uniform01(rng) - 1)
                         : geometry::wrap_angle(std::numbers::pi + 0.3 * (2 * uniform01(rng) - 1));
    poses.push_back({5 * uniform01(rng), 4 * uniform01(rng), t});
    tree.insert(poses.back(), 1000 + i);
  }
  std::vector<std::int32_t> got;
  for (int q = 0; q < 400; ++q) {
    const Pose2 query{5 * uniform01(rng), 4 * uniform01(rng),
                      (q % 2) ? 3.1 + 0.04 * uniform01(rng) : -3.14 + 6.28 * uniform01(rng)};
    const std::size_t k = 1 + q % 12;
    std::vector<std::pair<double, int>> all;
    for (int i = 0; i < static_cast<int>(poses.size()); ++i)
      all.emplace_back(tree.distance(query, poses[i]), i);
    std::sort(all.begin(), all.end());
    tree.nearest(query, k, got);
    ASSERT_EQ(got.size(), k);
    for (std::size_t j = 0; j < k; ++j) EXPECT_EQ(got[j], 1000 + all[j].second) << q << " " << j;
  }
}
// Removals prune whole subtrees once none of their poses is live: answers
// must still equal a linear scan over the live poses, through thousands of
// interleaved inserts, removals (some repeated, some of unknown ids) and
// queries, down to a tree with no live pose at all.
TEST(PoseNearest, RemovalsMatchLinearScanOverLivePoses) {
  std::mt19937_64 rng(11);
  PoseNearest tree(0.7);
  std::vector<Pose2> poses;
  std::vector<bool> live;
  std::vector<std::int32_t> got;
  int checked = 0;
  for (int step = 0; step < 12000; ++step) {
    const double u = uniform01(rng);
    if (step < 6000 && u < 0.5) {
      poses.push_back(
          {4 * uniform01(rng), 4 * uniform01(rng), std::numbers::pi * (2 * uniform01(rng) - 1)});
      live.push_back(true);
      tree.insert(poses.back(), static_cast<std::int32_t>(poses.size() - 1));
    } else if (u < 0.8 && !poses.empty()) {
      // Remove the live pose nearest a random point (clusters of removals,
      // like the planner's goal attempts), or an id again, or an unknown id.
      const Pose2 at{4 * uniform01(rng), 4 * uniform01(rng), 0.0};
      int pick = -1;
      double best = 1e300;
      for (std::size_t i = 0; i < poses.size(); ++i)
        if (live[i] && tree.distance(at, poses[i]) < best)
          best = tree.distance(at, poses[i]), pick = static_cast<int>(i);
      if (pick >= 0) {
        tree.remove(pick);
        live[pick] = false;
        tree.remove(pick);  // removing twice changes nothing
      }
      tree.remove(static_cast<std::int32_t>(poses.size() + 5));
    } else {
      const Pose2 query{4 * uniform01(rng), 4 * uniform01(rng),
                        std::numbers::pi * (2 * uniform01(rng) - 1)};
      const std::size_t k = 1 + step % 10;
      std::vector<std::pair<double, int>> all;
      for (std::size_t i = 0; i < poses.size(); ++i)
        if (live[i]) all.emplace_back(tree.distance(query, poses[i]), static_cast<int>(i));
      std::sort(all.begin(), all.end());
      tree.nearest(query, k, got);
      ASSERT_EQ(got.size(), std::min(k, all.size())) << step;
      for (std::size_t j = 0; j < got.size(); ++j) ASSERT_EQ(got[j], all[j].second) << step;
      ++checked;
    }
  }
  EXPECT_GT(checked, 2000);
  EXPECT_EQ(std::count(live.begin(), live.end(), true), 0);  // drained to empty
}
// QueryOrder against PoseNearest asked the same fixed query, over 12000
// interleaved inserts (ids increasing, a quarter of them repeating an
// earlier pose so that distances tie) and removals; ids as the RRT uses them.
TEST(QueryOrder, MatchesPoseNearestForItsQueryUnderInsertsAndRemovals) {
  std::mt19937_64 rng(11);
  for (int round = 0; round < 4; ++round) {
    const Pose2 query{4 * uniform01(rng), 4 * uniform01(rng),
                      std::numbers::pi * (2 * uniform01(rng) - 1)};
    PoseNearest tree(0.7);
    QueryOrder order(0.7);
    order.reset(query);
    std::vector<Pose2> poses;
    std::vector<std::int32_t> want, got;
    for (int step = 0; step < 3000; ++step) {
      if (step % 5 < 3 || poses.empty()) {
        const Pose2 p = !poses.empty() && step % 4 == 0
                            ? poses[static_cast<std::size_t>(rng() % poses.size())]
                            : Pose2{4 * uniform01(rng), 4 * uniform01(rng),
                                    std::numbers::pi * (2 * uniform01(rng) - 1)};
        poses.push_back(p);
        const auto id = static_cast<std::int32_t>(poses.size() - 1);
        tree.insert(p, id);
        order.insert(p, id);
      } else if (step % 5 == 3) {
        const auto id = static_cast<std::int32_t>(rng() % (poses.size() + 3));
        tree.remove(id);
        order.remove(id);
      } else {
        const std::size_t k = 1 + step % 10;
        tree.nearest(query, k, want);
        order.nearest(k, got);
        ASSERT_EQ(got, want) << "round " << round << " step " << step;
      }
    }
  }
}

// Leaves split at the median of their widest axis: poses that share
// coordinates (a coarse lattice, so medians often equal a minimum) and a
// pile of identical poses (a leaf that cannot split) must still give the
// linear scan's answer, ties broken by insertion order, under removals.
TEST(PoseNearest, LatticeAndIdenticalPosesMatchLinearScan) {
  std::mt19937_64 rng(23);
  PoseNearest tree(0.7);
  std::vector<Pose2> poses;
  std::vector<bool> live;
  const Pose2 pile{1.5, 2.0, std::numbers::pi};
  for (int i = 0; i < 3000; ++i) {
    const Pose2 p = i % 3 == 0 ? pile
                               : Pose2{0.5 * static_cast<double>(rng() % 9),
                                       0.5 * static_cast<double>(rng() % 7),
                                       std::numbers::pi / 2 * static_cast<double>(rng() % 4) -
                                           std::numbers::pi / 2};
    poses.push_back(p);
    live.push_back(true);
    tree.insert(p, i);
  }
  // The pile's thousand equal poses end in one leaf that no split can cut
  // (no coordinate separates them); the answers must not depend on it.
  std::vector<std::int32_t> got;
  for (int q = 0; q < 3000; ++q) {
    if (q % 3 == 0) {
      const auto id = static_cast<std::int32_t>(rng() % poses.size());
      tree.remove(id);
      live[static_cast<std::size_t>(id)] = false;
    }
    const Pose2 query = q % 4 == 0 ? pile
                                   : Pose2{0.5 * static_cast<double>(rng() % 10) - 0.25,
                                           0.5 * static_cast<double>(rng() % 8),
                                           std::numbers::pi * (2 * uniform01(rng) - 1)};
    const std::size_t k = 1 + q % 40;
    std::vector<std::pair<double, int>> all;
    for (std::size_t i = 0; i < poses.size(); ++i)
      if (live[i]) all.emplace_back(tree.distance(query, poses[i]), static_cast<int>(i));
    std::sort(all.begin(), all.end());
    tree.nearest(query, k, got);
    ASSERT_EQ(got.size(), std::min(k, all.size())) << q;
    for (std::size_t j = 0; j < got.size(); ++j) ASSERT_EQ(got[j], all[j].second) << q << " " << j;
  }
}

// The index ranks by a heading gap computed without wrap_angle (|a − b|, or
// 2pi minus it past pi). For headings already in (−pi, pi] it must be the
// same double as distance()'s |wrap_angle(a − b)|: random headings, and
// headings at and next to ±pi and 0, where the two branches meet.
TEST(PoseNearest, RankingDistanceEqualsDistanceBitForBit) {
  std::mt19937_64 rng(29);
  const double pi = std::numbers::pi;
  const double edges[] = {pi,
                          std::nextafter(pi, 0.0),
                          -std::nextafter(pi, 0.0),
                          0.0,
                          -0.0,
                          std::nextafter(0.0, 1.0),
                          pi / 2,
                          -pi / 2,
                          std::nextafter(pi / 2, 0.0),
                          -std::nextafter(pi / 2, 0.0)};
  PoseNearest n(0.7);
  int compared = 0;
  for (int i = 0; i < 1000000; ++i) {
    const auto heading = [&] {
      return rng() % 4 == 0 ? edges[rng() % std::size(edges)] : pi * (2 * uniform01(rng) - 1);
    };
    const Pose2 a{4 * uniform01(rng), 4 * uniform01(rng), heading()};
    const Pose2 b{4 * uniform01(rng), 4 * uniform01(rng), heading()};
    if (a.theta <= -pi || b.theta <= -pi) continue;  // outside (−pi, pi]
    const double want = n.distance(a, b);
    const double got = n.ranking_distance(a, b);
    ASSERT_EQ(std::memcmp(&want, &got, sizeof want), 0) << i << " " << a.theta << " " << b.theta;
    ++compared;
  }
  EXPECT_GT(compared, 990000);
}

TEST(PoseNearest, DistanceWrapsHeading) {
  PoseNearest n(0.5);
  EXPECT_NEAR(n.distance({0, 0, 3.1}, {0, 0, -3.1}), 0.5 * (2 * std::numbers::pi - 6.2), 1e-12);
  EXPECT_NEAR(n.distance({0, 0, 0}, {3, 4, 0}), 5.0, 1e-12);
}
TEST(PathOps, SubpathPiecesConcatenateToThePath) {
  rs::Path p{
      {{rs::Steer::kLeft, 1, 0.7}, {rs::Steer::kStraight, -1, 1.2}, {rs::Steer::kRight, 1, 0.4}},
      0.7};
  rs::Path joined{{}, 0.7};
  for (double s = 0; s < p.length(); s += 0.33)
    for (const auto& seg : subpath(p, s, std::min(s + 0.33, p.length())).segments)
      append_segment(joined.segments, seg);
  ASSERT_EQ(joined.segments.size(), p.segments.size());
  for (std::size_t i = 0; i < p.segments.size(); ++i) {
    EXPECT_EQ(joined.segments[i].steer, p.segments[i].steer);
    EXPECT_EQ(joined.segments[i].gear, p.segments[i].gear);
    EXPECT_NEAR(joined.segments[i].length, p.segments[i].length, 1e-12);
  }
}

}  // namespace
}  // namespace hrs::planning
