// SPDX-License-Identifier: GPL-3.0-or-later
// Reeds–Shepp properties independent of OMPL (paper §III-B): the shortest
// path reaches the goal, equals the minimum over the 48 words evaluated one
// by one, and the distance is symmetric, at least Euclidean, invariant under
// rigid motions and scales with the radius. Degenerate queries, each by name.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "rs/reeds_shepp.h"
#include "tests/support/poses.h"

namespace hrs::rs {
namespace {

using test_support::goal_tolerance;
using test_support::pose_error;
using test_support::random_pose;
constexpr double kPi = std::numbers::pi;

//! Random queries over several radii and spreads; fixed seed per call site.
template <class F>
void for_random_pairs(std::uint64_t seed, int count, F&& f) {
  std::mt19937_64 rng(seed);
  const double radii[] = {0.3, 0.7, 1.0, 3.0};
  const double spreads[] = {0.5, 2.0, 6.0, 30.0};
  for (int i = 0; i < count; ++i) {
    const double r = radii[i % 4], k = spreads[(i / 4) % 4];
    const Pose2 a = random_pose(rng, k * r), b = random_pose(rng, k * r);
    f(a, b, r);
    if (::testing::Test::HasFailure()) return;
  }
}

double tol(double len) { return 1e-9 * (1.0 + len); }

void expect_reaches(const Pose2& a, const Pose2& b, const Path& p) {
  const Pose2 e = end_pose(a, p);
  EXPECT_TRUE(std::isfinite(e.x) && std::isfinite(e.y) && std::isfinite(e.theta));
  EXPECT_LE(pose_error(e, b), goal_tolerance(a, b))
      << "word " << p.word() << " from (" << a.x << "," << a.y << "," << a.theta << ") to (" << b.x
      << "," << b.y << "," << b.theta << ") r=" << p.radius;
}

TEST(RsWords, TableHas48DistinctWordsThatRoundTrip) {
  std::set<std::string> names;
  for (int w = 0; w < kWordCount; ++w) {
    const std::string n(word_name(w));
    EXPECT_GE(n.size(), 6u);
    EXPECT_LE(n.size(), 10u);
    EXPECT_EQ(word_id(n), w);
    names.insert(n);
  }
  EXPECT_EQ(names.size(), 48u);
  EXPECT_EQ(word_id("L+S+L+"), 0);
  EXPECT_GE(word_id("L+R-S-L-R+"), 0);
  EXPECT_GE(word_id("L+R+L-R-"), 0);
  EXPECT_EQ(word_id("L+L+"), -1);
}

TEST(RsShortest, ClosedFormIntegrationReachesGoal) {
  for_random_pairs(11, 200000, [](const Pose2& a, const Pose2& b, double r) {
    expect_reaches(a, b, shortest_path(a, b, r));
  });
}

TEST(RsShortest, LengthEqualsSumOfSegments) {
  for_random_pairs(12, 100000, [](const Pose2& a, const Pose2& b, double r) {
    const Path p = shortest_path(a, b, r);
    double sum = 0.0;
    for (const auto& s : p.segments) {
      EXPECT_GT(s.length, 0.0);
      EXPECT_TRUE(s.gear == 1 || s.gear == -1);
      sum += s.length;
    }
    EXPECT_DOUBLE_EQ(p.length(), sum);
    EXPECT_NEAR(shortest_length(a, b, r), sum, 1e-12 * (1.0 + sum));
    EXPECT_EQ(p.radius, r);
  });
}

TEST(RsShortest, ShortestWordAgreesWithShortestPath) {
  for_random_pairs(13, 50000, [](const Pose2& a, const Pose2& b, double r) {
    const Path p = shortest_path(a, b, r);
    const ShortestWord w = shortest_word(a, b, r);
    EXPECT_NEAR(w.length, p.length(), 1e-12 * (1.0 + w.length));
    // The path's word is the nominal word minus zero-length segments.
    const std::string nominal(word_name(w.word)), actual = p.word();
    std::size_t j = 0;
    for (std::size_t i = 0; i + 1 < nominal.size() && j < actual.size(); i += 2)
      if (nominal.compare(i, 2, actual, j, 2) == 0) j += 2;
    EXPECT_EQ(j, actual.size()) << nominal << " vs " << actual;
    // The word evaluated alone gives the same length.
    EXPECT_NEAR(word_length(w.word, a, b, r), w.length, tol(w.length));
  });
}

TEST(RsShortest, ShortestIsNeverLongerThanAnyWord) {
  for_random_pairs(14, 20000, [](const Pose2& a, const Pose2& b, double r) {
    const double best = shortest_length(a, b, r);
    double min_word = std::numeric_limits<double>::infinity();
    for (int w = 0; w < kWordCount; ++w) {
      const double l = word_length(w, a, b, r);
      EXPECT_GE(l, best - tol(best)) << word_name(w);
      min_word = std::min(min_word, l);
    }
    // And the fast solver finds that minimum (it prunes, the words do not).
    EXPECT_NEAR(best, min_word, tol(best));
  });
}

TEST(RsShortest, EveryFeasibleWordPathReachesGoal) {
  for_random_pairs(15, 4000, [](const Pose2& a, const Pose2& b, double r) {
    for (int w = 0; w < kWordCount; ++w) {
      const auto p = word_path(w, a, b, r);
      if (!p) {
        EXPECT_TRUE(std::isinf(word_length(w, a, b, r)));
        continue;
      }
      expect_reaches(a, b, *p);
      EXPECT_NEAR(p->length(), word_length(w, a, b, r), 1e-12 * (1.0 + p->length()));
    }
  });
}

TEST(RsShortest, DistanceIsSymmetric) {
  for_random_pairs(16, 100000, [](const Pose2& a, const Pose2& b, double r) {
    const double ab = shortest_length(a, b, r), ba = shortest_length(b, a, r);
    EXPECT_NEAR(ab, ba, tol(ab));
  });
}

TEST(RsShortest, DistanceIsAtLeastEuclidean) {
  for_random_pairs(17, 100000, [](const Pose2& a, const Pose2& b, double r) {
    const double d = std::hypot(b.x - a.x, b.y - a.y);
    EXPECT_GE(shortest_length(a, b, r), d - 1e-12 * (1.0 + d));
  });
}

TEST(RsShortest, LowerBoundNeverExceedsTheLength) {
  int heading_bound_wins = 0;
  for_random_pairs(41, 20000, [&](const Pose2& a, const Pose2& b, double r) {
    const double lb = length_lower_bound(a, b, r), d = shortest_length(a, b, r);
    EXPECT_LE(lb, d + tol(d));
    if (lb > std::hypot(b.x - a.x, b.y - a.y) + 1e-12) ++heading_bound_wins;
  });
  EXPECT_GT(heading_bound_wins, 100);  // the heading term is exercised
}

// first_shortest against the plain loop (shortest_length in order, a
// strictly shorter one kept): sets of 1..12 poses around a target, with
// repeated poses so that ties occur; 4000 sets.
TEST(RsShortest, FirstShortestIsTheFirstOfTheShortestLengths) {
  std::mt19937_64 rng(43);
  std::vector<std::pair<double, std::size_t>> scratch;
  int ties = 0;
  for (int c = 0; c < 4000; ++c) {
    const double r = 0.3 + (c % 4) * 0.4;
    const Pose2 to = random_pose(rng, 2.0);
    std::vector<Pose2> from;
    const int n = 1 + c % 12;
    for (int i = 0; i < n; ++i)
      from.push_back(i > 0 && rng() % 4 == 0 ? from[rng() % i] : random_pose(rng, 3.0));
    std::size_t expected = from.size();
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < from.size(); ++i) {
      const double d = shortest_length(from[i], to, r);
      if (d == best) ++ties;
      if (d < best) {
        best = d;
        expected = i;
      }
    }
    ASSERT_EQ(first_shortest(from, to, r, scratch), expected) << "set " << c;
  }
  EXPECT_GT(ties, 50);
  EXPECT_EQ(first_shortest({}, Pose2{0, 0, 0}, 1.0, scratch), 0u);
}

// The cap first_shortest gives its later solves: sets whose poses are copies
// of one pose moved by 1e-15..1e-8 m or rad, so that lengths tie or differ by
// less than the cap's margin; 20000 sets, against the plain loop.
TEST(RsShortest, FirstShortestAgreesOnNearTies) {
  std::mt19937_64 rng(44);
  std::uniform_int_distribution<int> exponent(-15, -8);
  std::vector<std::pair<double, std::size_t>> scratch;
  int close = 0;
  for (int c = 0; c < 20000; ++c) {
    const double r = 0.3 + (c % 5) * 0.3;
    const Pose2 to = random_pose(rng, 2.0);
    const Pose2 base = random_pose(rng, 3.0);
    std::vector<Pose2> from;
    const int n = 2 + c % 10;
    for (int i = 0; i < n; ++i) {
      Pose2 p = base;
      const double e = std::pow(10.0, exponent(rng));
      switch (rng() % 4) {
        case 0: break;
        case 1: p.x += e; break;
        case 2: p.y -= e; break;
        default: p.theta = geometry::wrap_angle(p.theta + e); break;
      }
      from.push_back(i % 3 == 2 ? random_pose(rng, 3.0) : p);
    }
    std::size_t expected = from.size();
    double best = std::numeric_limits<double>::infinity();
    std::vector<double> d(from.size());
    for (std::size_t i = 0; i < from.size(); ++i) {
      d[i] = shortest_length(from[i], to, r);
      if (d[i] < best) best = d[i], expected = i;
    }
    for (std::size_t i = 0; i < from.size(); ++i)
      if (i != expected && d[i] > best && d[i] <= best * (1.0 + 1e-9)) ++close;
    ASSERT_EQ(first_shortest(from, to, r, scratch), expected) << "set " << c;
  }
  EXPECT_GT(close, 1000);  // lengths within the cap's margin of the best occur
}

TEST(RsShortest, InvariantUnderRigidMotions) {
  std::mt19937_64 rng(18);
  std::uniform_real_distribution<double> ang(-kPi, kPi), off(-50.0, 50.0);
  for_random_pairs(19, 100000, [&](const Pose2& a, const Pose2& b, double r) {
    const double rot = ang(rng), tx = off(rng), ty = off(rng);
    auto move = [&](const Pose2& p) {
      const auto v = geometry::rotate({p.x, p.y}, rot);
      return Pose2{v.x + tx, v.y + ty, geometry::wrap_angle(p.theta + rot)};
    };
    const double d = shortest_length(a, b, r);
    EXPECT_NEAR(shortest_length(move(a), move(b), r), d, 1e-9 * (1.0 + d + 50.0));
  });
}

TEST(RsShortest, ScalesWithRadius) {
  for_random_pairs(20, 100000, [](const Pose2& a, const Pose2& b, double r) {
    const Pose2 a1{a.x / r, a.y / r, a.theta}, b1{b.x / r, b.y / r, b.theta};
    const double d = shortest_length(a, b, r);
    EXPECT_NEAR(d, r * shortest_length(a1, b1, 1.0), tol(d));
  });
}

// ---- Degenerate queries -----------------------------------------------------

void expect_sane(const Pose2& a, const Pose2& b, double r) {
  const Path p = shortest_path(a, b, r);
  const double l = shortest_length(a, b, r);
  EXPECT_TRUE(std::isfinite(l));
  EXPECT_NEAR(p.length(), l, 1e-12 * (1.0 + l));
  expect_reaches(a, b, p);
  EXPECT_NEAR(shortest_length(b, a, r), l, tol(l));
}

TEST(RsDegenerate, IdenticalPosesGiveEmptyPath) {
  for (double r : {0.1, 1.0, 3.0})
    for (const Pose2 a : {Pose2{0, 0, 0}, Pose2{1.5, -2.0, 2.0}, Pose2{-3, 4, kPi}}) {
      const Path p = shortest_path(a, a, r);
      EXPECT_TRUE(p.segments.empty()) << p.word();
      EXPECT_EQ(shortest_length(a, a, r), 0.0);
      EXPECT_EQ(p.word(), "");
    }
}

TEST(RsDegenerate, PosesOneEMinus12Apart) {
  for (double r : {0.5, 1.0, 3.0}) {
    const Pose2 a{2.0, 1.0, 0.3};
    for (const Pose2 b : {Pose2{2.0 + 1e-12, 1.0, 0.3}, Pose2{2.0, 1.0 + 1e-12, 0.3},
                          Pose2{2.0 - 1e-12, 1.0 + 1e-12, 0.3}, Pose2{2.0, 1.0, 0.3 + 1e-12},
                          Pose2{2.0 + 1e-12, 1.0 - 1e-12, 0.3 - 1e-12}}) {
      expect_sane(a, b, r);
      // Lateral offsets cost O(sqrt) of the offset, never more than a parking
      // manoeuvre of ~1e-5 here.
      EXPECT_LE(shortest_length(a, b, r), 1e-4);
    }
  }
}

TEST(RsDegenerate, PureHeadingChangeAtOnePosition) {
  for (double r : {0.5, 1.0, 3.0})
    for (double dth : {1e-9, 0.1, kPi / 2, 2.0, kPi - 1e-12, kPi, -kPi / 2, -3.0}) {
      const Pose2 a{1.0, -1.0, 0.4}, b{1.0, -1.0, 0.4 + dth};
      expect_sane(a, b, r);
      EXPECT_GT(shortest_length(a, b, r), 0.0);
      // Turning in place costs at least the heading change times r.
      EXPECT_GE(shortest_length(a, b, r), r * std::abs(geometry::wrap_angle(dth)) - 1e-9);
    }
}

TEST(RsDegenerate, CollinearGoalAheadIsOneStraightSegment) {
  for (double r : {0.5, 1.0, 3.0})
    for (double d : {1e-6, 0.3, 1.0, 10.0}) {
      const Pose2 a{1.0, 2.0, 0.7};
      const Pose2 b{1.0 + d * std::cos(0.7), 2.0 + d * std::sin(0.7), 0.7};
      expect_sane(a, b, r);
      // Rounding in b leaves a lateral offset of ~1e-16 m: arcs of ~1e-10 rad
      // may remain around the straight segment.
      EXPECT_NEAR(shortest_length(a, b, r), d, 1e-9 * (1.0 + d));
      // Exactly collinear (heading 0): one forward straight segment.
      const Path p = shortest_path({1.0, 2.0, 0.0}, {1.0 + d, 2.0, 0.0}, r);
      EXPECT_EQ(p.word(), "S+");
      EXPECT_NEAR(p.length(), d, 1e-12 * (1.0 + d));
    }
}

TEST(RsDegenerate, CollinearGoalBehindIsOneReverseSegment) {
  for (double r : {0.5, 1.0, 3.0})
    for (double d : {1e-6, 0.3, 1.0, 10.0}) {
      const Pose2 a{1.0, 2.0, -2.5};
      const Pose2 b{1.0 - d * std::cos(-2.5), 2.0 - d * std::sin(-2.5), -2.5};
      expect_sane(a, b, r);
      EXPECT_NEAR(shortest_length(a, b, r), d, 1e-9 * (1.0 + d));
      // Exactly collinear (heading π): one reverse straight segment.
      const Path p = shortest_path({1.0, 2.0, kPi}, {1.0 + d, 2.0, kPi}, r);
      EXPECT_EQ(p.word(), "S-");
      EXPECT_NEAR(p.length(), d, 1e-12 * (1.0 + d));
    }
}

TEST(RsDegenerate, HeadingsAtPlusMinusPi) {
  const double pis[] = {kPi, -kPi, std::nextafter(kPi, 0.0), std::nextafter(-kPi, 0.0)};
  for (double r : {0.5, 1.0, 3.0})
    for (double ta : pis)
      for (double tb : pis)
        for (const auto& [x, y] : {std::pair{0.0, 0.0}, {-2.0, 0.0}, {2.0, 0.0}, {1.0, 1.0}}) {
          const Pose2 a{0.0, 0.0, ta}, b{x, y, tb};
          expect_sane(a, b, r);
          // π and -π are the same heading: same answer either way.
          const Pose2 a2{0.0, 0.0, -ta}, b2{x, y, -tb};
          EXPECT_NEAR(shortest_length(a, b, r), shortest_length(a2, b2, r), 1e-9);
        }
}

// ---- Path utilities ---------------------------------------------------------

TEST(RsPath, PoseAtClampsAndEndsAtGoal) {
  for_random_pairs(21, 2000, [](const Pose2& a, const Pose2& b, double r) {
    const Path p = shortest_path(a, b, r);
    EXPECT_EQ(pose_at(a, p, -1.0), a);
    EXPECT_LE(pose_error(pose_at(a, p, p.length() + 1.0), b), goal_tolerance(a, b));
    EXPECT_LE(pose_error(pose_at(a, p, p.length()), end_pose(a, p)), 1e-12 * (1 + p.length()));
  });
}

TEST(RsPath, SamplesAreAtMostStepApartAndIncludeBothEnds) {
  for_random_pairs(22, 2000, [](const Pose2& a, const Pose2& b, double r) {
    const Path p = shortest_path(a, b, r);
    const double step = 0.05 * r;
    const auto poses = sample(a, p, step);
    ASSERT_FALSE(poses.empty());
    EXPECT_EQ(poses.front(), a);
    EXPECT_LE(pose_error(poses.back(), b), goal_tolerance(a, b));
    const auto n = static_cast<std::size_t>(std::ceil(p.length() / step));
    EXPECT_EQ(poses.size(), p.length() > 0 ? n + 1 : 1u);
    for (std::size_t i = 1; i < poses.size(); ++i) {
      EXPECT_LE(std::hypot(poses[i].x - poses[i - 1].x, poses[i].y - poses[i - 1].y), step + 1e-12);
      // Each sample is the pose at its arc length.
      const double s = p.length() * static_cast<double>(i) / static_cast<double>(n);
      EXPECT_LE(pose_error(poses[i], pose_at(a, p, s)), 1e-9);
    }
  });
}

TEST(RsPath, ReversedPathDrivesFromGoalBackToStart) {
  for_random_pairs(23, 5000, [](const Pose2& a, const Pose2& b, double r) {
    const Path p = shortest_path(a, b, r);
    const Path q = reversed(p);
    EXPECT_DOUBLE_EQ(q.length(), p.length());
    const Pose2 e = end_pose(a, p);
    EXPECT_LE(pose_error(end_pose(e, q), a), goal_tolerance(a, b));
    // Same curve: the pose at s on the reversal is the pose at L - s.
    const double s = 0.3 * p.length();
    EXPECT_LE(pose_error(pose_at(e, q, s), pose_at(a, p, p.length() - s)), 1e-9 * (1 + r));
  });
}

TEST(RsPath, ConcatenationDrivesThroughBothAndMergesEqualSegments) {
  std::mt19937_64 rng(24);
  for (int i = 0; i < 5000; ++i) {
    const double r = 0.7;
    const Pose2 a = random_pose(rng, 3), b = random_pose(rng, 3), c = random_pose(rng, 3);
    const Path ab = shortest_path(a, b, r), bc = shortest_path(b, c, r);
    const Path ac = concatenate(ab, bc);
    EXPECT_NEAR(ac.length(), ab.length() + bc.length(), 1e-12 * (1 + ac.length()));
    EXPECT_LE(pose_error(end_pose(a, ac), c), 1e-8);
    for (std::size_t k = 1; k < ac.segments.size(); ++k)
      EXPECT_FALSE(ac.segments[k].steer == ac.segments[k - 1].steer &&
                   ac.segments[k].gear == ac.segments[k - 1].gear);
  }
  const Path s1{{{Steer::kStraight, 1, 1.0}}, 1.0}, s2{{{Steer::kStraight, 1, 2.0}}, 1.0};
  const Path s = concatenate(s1, s2);
  ASSERT_EQ(s.segments.size(), 1u);
  EXPECT_DOUBLE_EQ(s.segments[0].length, 3.0);
}

TEST(RsPath, AdvanceMatchesArcGeometry) {
  const Pose2 o{0, 0, 0};
  const Pose2 l = advance(o, {Steer::kLeft, 1, kPi / 2}, 1.0);
  EXPECT_NEAR(l.x, 1.0, 1e-15);
  EXPECT_NEAR(l.y, 1.0, 1e-15);
  EXPECT_NEAR(l.theta, kPi / 2, 1e-15);
  const Pose2 rr = advance(o, {Steer::kRight, -1, kPi / 2 * 2.0}, 2.0);  // back, right
  EXPECT_NEAR(rr.x, -2.0, 1e-15);
  EXPECT_NEAR(rr.y, -2.0, 1e-15);
  EXPECT_NEAR(rr.theta, kPi / 2, 1e-15);
  const Pose2 s = advance({1, 1, kPi}, {Steer::kStraight, -1, 2.0}, 1.0);
  EXPECT_NEAR(s.x, 3.0, 1e-15);
  EXPECT_NEAR(s.y, 1.0, 1e-15);
}

}  // namespace
}  // namespace hrs::rs
