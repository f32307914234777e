// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Plain 2-D value types shared by every module: points, poses, angle
// wrapping, pose algebra (frames, gaps) and bounding boxes.
// Angles are radians, counter-clockwise from world +x (docs/scene-format.md).

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace hrs::geometry {

//! A point or vector in the plane, metres.
struct Vec2 {
  double x = 0.0;  //!< metres
  double y = 0.0;  //!< metres
  friend Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
  friend Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
  friend Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
  friend bool operator==(const Vec2&, const Vec2&) = default;
};

inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
inline double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
inline double norm(Vec2 a) { return std::hypot(a.x, a.y); }

//! Wraps an angle to (-pi, pi].
inline double wrap_angle(double a) {
  constexpr double kPi = std::numbers::pi;
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  if (a > -kPi && a <= kPi) return a;
  a = std::fmod(a, kTwoPi);
  if (a <= -kPi) a += kTwoPi;
  if (a > kPi) a -= kTwoPi;
  return a;
}

//! Distance from p to the segment [a, b] (doubles: for costs and filters).
inline double point_segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = dot(ab, ab);
  double t = len2 > 0.0 ? dot(p - a, ab) / len2 : 0.0;
  t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
  return norm(p - (a + t * ab));
}

//! True if segments [a, b] and [c, d] cross at a point interior to both
//! (doubles; touching or collinear segments do not cross).
inline bool segments_cross(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 &&
         d4 != 0;
}

//! A rigid pose: position and heading (the direction the front faces).
struct Pose2 {
  double x = 0.0;      //!< metres
  double y = 0.0;      //!< metres
  double theta = 0.0;  //!< radians
  Vec2 position() const { return {x, y}; }
  friend bool operator==(const Pose2&, const Pose2&) = default;
};

//! Rotates v by angle a (counter-clockwise).
inline Vec2 rotate(Vec2 v, double a) {
  const double c = std::cos(a), s = std::sin(a);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

//! Maps a point from the frame of `p` to the world.
inline Vec2 to_world(const Pose2& p, Vec2 local) { return p.position() + rotate(local, p.theta); }

//! Axis-aligned bounding box.
struct Box {
  double xmin, ymin, xmax, ymax;
};

//! Bounding box of points (inverted, +inf/−inf, when there are none).
inline Box bounding_box(const std::vector<Vec2>& points) {
  Box b{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
        -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (const Vec2& v : points) {
    b.xmin = std::min(b.xmin, v.x);
    b.ymin = std::min(b.ymin, v.y);
    b.xmax = std::max(b.xmax, v.x);
    b.ymax = std::max(b.ymax, v.y);
  }
  return b;
}

//! `b` in the frame of `a` (a's position at the origin, heading +x).
inline Pose2 relative_pose(const Pose2& a, const Pose2& b) {
  const double c = std::cos(a.theta), s = std::sin(a.theta);
  const double dx = b.x - a.x, dy = b.y - a.y;
  return {c * dx + s * dy, -s * dx + c * dy, wrap_angle(b.theta - a.theta)};
}

//! Distance (metres) plus absolute heading difference (radians): the one
//! pose gap of tolerances and matches.
inline double pose_gap(const Pose2& a, const Pose2& b) {
  return std::hypot(a.x - b.x, a.y - b.y) + std::abs(wrap_angle(a.theta - b.theta));
}

}  // namespace hrs::geometry
