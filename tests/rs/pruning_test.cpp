// SPDX-License-Identifier: GPL-3.0-or-later
// The pruned Reeds–Shepp solver (rs/reeds_shepp.cpp) at its three levels
// (paper §III-B): the per-candidate pre-checks on the arcs' directions skip
// only candidates that would not be taken, so kFull equals kFamilyBounds bit
// for bit (same length, same word); both equal the solver that evaluates all
// 48 words up to ties between words of equal length. Checked on a million random pairs and on pairs
// built at the places where the pre-checks are closest to wrong: headings
// near 0 and ±π, collinear and coincident poses, and the boundaries of the
// families (|A| = 4, |B| = 2, |B|² = 20, |A|² = 8, |B| = 0).

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <string>

#include "rs/reeds_shepp.h"
#include "tests/support/poses.h"

namespace hrs::rs {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr std::array<double, 4> kRadii{0.3, 0.7, 1.0, 3.0};

struct Tally {
  long checked = 0;
  long mismatched = 0;
  long ties = 0;  //!< pairs where kNone picked another word of equal length
};

//! Compares the levels of pruning on one pair: kFull equals kFamilyBounds
//! bit for bit, and kNone up to ties (the length within 1e-10 radius; the
//! word may differ where two words' lengths tie, often through a zero-length
//! arc).
void compare(const Pose2& a, const Pose2& b, double r, Tally& tally) {
  const ShortestWord full = shortest_word(a, b, r, Pruning::kFull);
  const ShortestWord bounds = shortest_word(a, b, r, Pruning::kFamilyBounds);
  const ShortestWord none = shortest_word(a, b, r, Pruning::kNone);
  ++tally.checked;
  // Arcs under 1e-11 radius are snapped to zero after the candidates are
  // ranked, so words that tie can end up to a few 1e-11 radius apart.
  const double tol = 1e-10 * r + 1e-12 * none.length;
  const bool same = full.length == bounds.length && full.word == bounds.word &&
                    std::abs(full.length - none.length) <= tol;
  if (same && full.word != none.word) ++tally.ties;
  if (same) return;
  if (++tally.mismatched <= 5)
    ADD_FAILURE() << "from (" << a.x << ", " << a.y << ", " << a.theta << ") to (" << b.x << ", "
                  << b.y << ", " << b.theta << ") r = " << r << ": full " << full.length << " "
                  << word_name(full.word) << ", family bounds " << bounds.length << " "
                  << word_name(bounds.word) << ", none " << none.length << " "
                  << word_name(none.word);
}

//! A goal in the start's unit-radius frame given the heading change φ and
//! the point A = (X - sin φ, Y - 1 + cos φ) or B = (X + sin φ, Y - 1 - cos φ)
//! that the families read.
Pose2 goal_from_a(double ax, double ay, double phi) {
  return {ax + std::sin(phi), ay + 1.0 - std::cos(phi), phi};
}
Pose2 goal_from_b(double bx, double by, double phi) {
  return {bx - std::sin(phi), by + 1.0 + std::cos(phi), phi};
}

//! Moves a unit-radius goal seen from the origin into the frame of `start`
//! with radius r.
Pose2 place(const Pose2& start, const Pose2& local, double r) {
  const double c = std::cos(start.theta), s = std::sin(start.theta);
  return {start.x + r * (c * local.x - s * local.y), start.y + r * (s * local.x + c * local.y),
          geometry::wrap_angle(start.theta + local.theta)};
}

TEST(RsPruning, EqualsTheUnprunedSolverOnAMillionRandomPairs) {
  std::mt19937_64 rng(2026);
  Tally tally;
  const std::array<double, 4> spreads{0.5, 2.0, 6.0, 30.0};
  for (int i = 0; i < 1'000'000; ++i) {
    const double r = kRadii[i % 4], k = spreads[(i / 4) % 4];
    compare(test_support::random_pose(rng, k * r), test_support::random_pose(rng, k * r), r,
            tally);
  }
  EXPECT_EQ(tally.checked, 1'000'000);
  EXPECT_EQ(tally.mismatched, 0);
  RecordProperty("ties", std::to_string(tally.ties));
}

TEST(RsPruning, EqualsTheUnprunedSolverOnNearDegeneratePairs) {
  std::mt19937_64 rng(2027);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> exponent(4, 16);
  auto tiny = [&] { return (unit(rng) < 0.5 ? -1.0 : 1.0) * std::pow(10.0, -exponent(rng)); };
  auto angle = [&] { return (2.0 * unit(rng) - 1.0) * kPi; };
  // A heading change that is near 0 or ±π, exactly one of them, or any.
  auto heading = [&]() -> double {
    switch (static_cast<int>(unit(rng) * 6)) {
      case 0: return tiny();
      case 1: return kPi - std::abs(tiny());
      case 2: return -kPi + std::abs(tiny());
      case 3: return unit(rng) < 0.5 ? 0.0 : kPi;
      default: return angle();
    }
  };
  // A distance near one of the families' thresholds (or 0).
  const std::array<double, 6> norms{0.0, 2.0, 4.0, std::sqrt(8.0), std::sqrt(20.0), 1.0};
  Tally tally;
  for (int i = 0; i < 400'000; ++i) {
    const double r = kRadii[i % 4];
    const Pose2 start = test_support::random_pose(rng, 5.0);
    Pose2 local;
    switch (i % 4) {
      case 0: {  // collinear: along the start's heading, ahead or behind
        const double d = (unit(rng) < 0.5 ? -1.0 : 1.0) * 10.0 * unit(rng);
        const double phi = unit(rng) < 0.5 ? tiny() : (unit(rng) < 0.5 ? 0.0 : kPi - std::abs(tiny()));
        local = {d, unit(rng) < 0.5 ? 0.0 : tiny(), phi};
        break;
      }
      case 1:  // coincident up to a tiny offset
        local = {tiny(), tiny(), heading()};
        break;
      case 2: {  // A on a family boundary
        const double n = norms[i / 4 % norms.size()] + (unit(rng) < 0.5 ? 0.0 : tiny());
        const double a = angle();
        local = goal_from_a(n * std::cos(a), n * std::sin(a), heading());
        break;
      }
      default: {  // B on a family boundary
        const double n = norms[i / 4 % norms.size()] + (unit(rng) < 0.5 ? 0.0 : tiny());
        const double a = angle();
        local = goal_from_b(n * std::cos(a), n * std::sin(a), heading());
        break;
      }
    }
    compare(start, place(start, local, r), r, tally);
    // The same goal with the start at the origin (no rotation rounding).
    compare({}, {r * local.x, r * local.y, local.theta}, r, tally);
  }
  EXPECT_EQ(tally.checked, 800'000);
  EXPECT_EQ(tally.mismatched, 0);
}

TEST(RsPruning, EqualsTheUnprunedSolverOnLatticePairs) {
  // Exact coordinates (multiples of 1/4 radius, headings multiples of π/8):
  // exact ties between words are common here.
  Tally tally;
  for (int ix = -16; ix <= 16; ++ix)
    for (int iy = -16; iy <= 16; ++iy)
      for (int it = -8; it <= 8; ++it) compare({}, {0.25 * ix, 0.25 * iy, it * kPi / 8}, 1.0, tally);
  EXPECT_EQ(tally.checked, 33L * 33 * 17);
  EXPECT_EQ(tally.mismatched, 0);
}

}  // namespace
}  // namespace hrs::rs
