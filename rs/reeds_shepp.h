#pragma once
// Reeds–Shepp curves (Reeds & Shepp 1990; the paper's steering function,
// §III-B, and the RS-decomposition of §V-A): shortest paths of a car that
// drives forwards and backwards with a minimum turning radius.
//
// API contract used by planning/ (the rs issue may extend, not break it):
//   rs::Segment, rs::Steer, rs::Path, rs::shortest_path, rs::shortest_length,
//   rs::pose_at, rs::sample.

#include <string>
#include <vector>

#include "geometry/pose.h"

namespace hrs::rs {

using geometry::Pose2;

enum class Steer : char { kLeft = 'L', kStraight = 'S', kRight = 'R' };

//! One piece of a path: constant steering and gear, arc length in metres.
struct Segment {
  Steer steer = Steer::kStraight;
  int gear = 1;         //!< +1 forward, -1 reverse
  double length = 0.0;  //!< metres, >= 0
  friend bool operator==(const Segment&, const Segment&) = default;
};

//! A path of RS segments driven from some start pose with a turning radius.
struct Path {
  std::vector<Segment> segments;
  double radius = 1.0;  //!< turning radius of the arcs, metres
  //! Sum of segment lengths, metres.
  double length() const;
  //! Word like "L+S+R-" (steer letter then gear sign per segment).
  std::string word() const;
};

//! Pose reached after driving `segment` from `start` with turning radius r.
Pose2 advance(const Pose2& start, const Segment& segment, double radius);
//! Pose at arc length s (clamped to [0, length]) along `path` from `start`.
Pose2 pose_at(const Pose2& start, const Path& path, double s);
//! Poses from start to end at most `step` metres apart, both ends included.
std::vector<Pose2> sample(const Pose2& start, const Path& path, double step);

//! The exact shortest RS path from `from` to `to` (all 48 words).
Path shortest_path(const Pose2& from, const Pose2& to, double radius);
//! Its length only (no allocation).
double shortest_length(const Pose2& from, const Pose2& to, double radius);

}  // namespace hrs::rs
