// SPDX-License-Identifier: GPL-3.0-or-later
// Reeds–Shepp shortest paths against OMPL's ReedsSheppStateSpace (paper
// §III-B): over 1e6 random pairs our length never exceeds OMPL's by more than
// 1e-9 (1 + length); where ours is shorter, our path must reach the goal, and
// OMPL's path is integrated to say why it missed.

#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <vector>

#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>

#include "rs/reeds_shepp.h"
#include "tests/support/poses.h"

namespace hrs::rs {
namespace {

namespace ob = ompl::base;
using test_support::goal_tolerance;
using test_support::pose_error;
using test_support::random_pose;

class Ompl {
 public:
  explicit Ompl(double radius) : space_(radius), radius_(radius) {
    a_ = space_.allocState()->as<ob::SE2StateSpace::StateType>();
    b_ = space_.allocState()->as<ob::SE2StateSpace::StateType>();
  }
  ~Ompl() {
    space_.freeState(a_);
    space_.freeState(b_);
  }
  Ompl(const Ompl&) = delete;
  Ompl& operator=(const Ompl&) = delete;

  double distance(const Pose2& a, const Pose2& b) {
    set(a, b);
    return space_.distance(a_, b_);
  }
  //! OMPL's path as our Path (gear from the sign of each OMPL length).
  Path path(const Pose2& a, const Pose2& b) {
    set(a, b);
    const auto p = space_.reedsShepp(a_, b_);
    Path out;
    out.radius = radius_;
    for (int i = 0; i < 5; ++i) {
      const auto type = p.type_[i];
      if (type == ob::ReedsSheppStateSpace::RS_NOP || p.length_[i] == 0.0) continue;
      const Steer s = type == ob::ReedsSheppStateSpace::RS_LEFT    ? Steer::kLeft
                      : type == ob::ReedsSheppStateSpace::RS_RIGHT ? Steer::kRight
                                                                   : Steer::kStraight;
      out.segments.push_back({s, p.length_[i] < 0 ? -1 : 1, std::abs(p.length_[i]) * radius_});
    }
    return out;
  }

 private:
  void set(const Pose2& a, const Pose2& b) {
    a_->setXY(a.x, a.y);
    a_->setYaw(a.theta);
    b_->setXY(b.x, b.y);
    b_->setYaw(b.theta);
  }
  ob::ReedsSheppStateSpace space_;
  double radius_;
  ob::SE2StateSpace::StateType* a_;
  ob::SE2StateSpace::StateType* b_;
};

struct Tally {
  long pairs = 0, shorter = 0, longer = 0, ompl_invalid = 0;
  double worst_gain = 0.0;
};

//! Compares one pair; returns false (and reports) on a failure of ours.
void compare(Ompl& ompl, const Pose2& a, const Pose2& b, double radius, Tally& tally) {
  ++tally.pairs;
  const Path ours = shortest_path(a, b, radius);
  const double lo = ours.length();
  const double lr = ompl.distance(a, b);
  const double tol = 1e-9 * (1.0 + lr);
  const double err = pose_error(end_pose(a, ours), b);
  ASSERT_LE(err, goal_tolerance(a, b)) << "our path misses the goal: r=" << radius;
  if (lo > lr + tol) {
    // Only acceptable if OMPL's own path does not reach the goal.
    const Path op = ompl.path(a, b);
    const double oerr = pose_error(end_pose(a, op), b);
    ++tally.longer;
    ADD_FAILURE() << std::setprecision(17) << "ours longer than OMPL: " << lo << " vs " << lr
                  << " (OMPL goal error " << oerr << ") a=" << a.x << "," << a.y << "," << a.theta
                  << " b=" << b.x << "," << b.y << "," << b.theta << " r=" << radius;
  } else if (lo < lr - tol) {
    ++tally.shorter;
    tally.worst_gain = std::max(tally.worst_gain, lr - lo);
    const Path op = ompl.path(a, b);
    if (pose_error(end_pose(a, op), b) > 1e-6) ++tally.ompl_invalid;
    if (tally.shorter <= 10)
      std::printf(
          "shorter than OMPL: r=%.17g a=(%.17g,%.17g,%.17g) b=(%.17g,%.17g,%.17g) "
          "ours=%.17g %s ompl=%.17g %s\n",
          radius, a.x, a.y, a.theta, b.x, b.y, b.theta, lo, ours.word().c_str(), lr,
          op.word().c_str());
  }
}

void report(const char* what, const Tally& t) {
  std::printf(
      "%s: %ld pairs, ours shorter %ld (max gain %.3g m, OMPL path invalid in %ld), "
      "ours longer %ld\n",
      what, t.pairs, t.shorter, t.worst_gain, t.ompl_invalid, t.longer);
}

// 16 (radius, spread) settings x 62 500 pairs = 1e6 random pairs.
TEST(RsVsOmpl, NeverLongerThanOmplOnAMillionRandomPairs) {
  const double radii[] = {0.3, 0.7, 1.0, 3.0};
  const double spreads[] = {0.5, 2.0, 5.0, 25.0};  // box half-size in radii
  Tally total;
  std::uint64_t seed = 1;
  for (double r : radii) {
    Ompl ompl(r);
    for (double k : spreads) {
      std::mt19937_64 rng(seed++);
      for (int i = 0; i < 62500; ++i) {
        const Pose2 a = random_pose(rng, k * r), b = random_pose(rng, k * r);
        compare(ompl, a, b, r, total);
        if (HasFatalFailure()) return;
      }
    }
  }
  report("random", total);
  EXPECT_EQ(total.longer, 0);
}

// Queries on the families' boundaries, where rounding decides: headings on a
// grid of multiples of π/4 (including ±π) and goals on a grid of
// half-radius steps, so many queries are collinear or pure turns.
TEST(RsVsOmpl, NeverLongerThanOmplOnGridQueries) {
  Tally total;
  for (double r : {0.5, 1.0, 3.0}) {
    Ompl ompl(r);
    for (int ta = -4; ta <= 4; ++ta)
      for (int tb = -4; tb <= 4; ++tb)
        for (int ix = -8; ix <= 8; ++ix)
          for (int iy = -8; iy <= 8; ++iy) {
            const Pose2 a{0.0, 0.0, ta * std::numbers::pi / 4};
            const Pose2 b{0.5 * r * ix, 0.5 * r * iy, tb * std::numbers::pi / 4};
            compare(ompl, a, b, r, total);
            if (HasFatalFailure()) return;
          }
  }
  report("grid", total);
  EXPECT_EQ(total.longer, 0);
}

}  // namespace
}  // namespace hrs::rs
