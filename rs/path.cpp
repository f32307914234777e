// SPDX-License-Identifier: GPL-3.0-or-later
// Operations on Reeds–Shepp paths as segment lists (rs/reeds_shepp.h): length
// and word, driving a path from a pose (exact arcs and lines), sampling,
// reversal and concatenation. The shortest-path formulas are in
// reeds_shepp.cpp.

#include "rs/reeds_shepp.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <string>
#include <vector>

namespace hrs::rs {

double Path::length() const {
  double sum = 0.0;
  for (const auto& s : segments) sum += s.length;
  return sum;
}

std::string Path::word() const {
  std::string w;
  w.reserve(2 * segments.size());
  for (const auto& s : segments) {
    w += static_cast<char>(s.steer);
    w += s.gear < 0 ? '-' : '+';
  }
  return w;
}

Pose2 advance(const Pose2& start, const Segment& segment, double radius) {
  const double d = segment.gear < 0 ? -segment.length : segment.length;
  const double c0 = std::cos(start.theta), s0 = std::sin(start.theta);
  if (segment.steer == Steer::kStraight) return {start.x + d * c0, start.y + d * s0, start.theta};
  // Turning by dth about the centre at radius r to the left (or right):
  // chord = 2 r sin(dth/2) along heading theta + dth/2.
  const double dth = (segment.steer == Steer::kLeft ? d : -d) / radius;
  const double half = 0.5 * dth;
  const double chord = segment.steer == Steer::kLeft ? 2.0 * radius * std::sin(half)
                                                     : -2.0 * radius * std::sin(half);
  const double ch = start.theta + half;
  return {start.x + chord * std::cos(ch), start.y + chord * std::sin(ch),
          geometry::wrap_angle(start.theta + dth)};
}

Pose2 pose_at(const Pose2& start, const Path& path, double s) {
  Pose2 p = start;
  double left = std::max(0.0, s);
  for (const auto& seg : path.segments) {
    if (left <= 0.0) break;
    if (left >= seg.length) {
      p = advance(p, seg, path.radius);
      left -= seg.length;
    } else {
      p = advance(p, {seg.steer, seg.gear, left}, path.radius);
      left = 0.0;
    }
  }
  return p;
}

Pose2 end_pose(const Pose2& start, const Path& path) {
  Pose2 p = start;
  for (const auto& seg : path.segments) p = advance(p, seg, path.radius);
  return p;
}

std::vector<Pose2> sample(const Pose2& start, const Path& path, double step) {
  assert(step > 0.0);
  const double total = path.length();
  std::vector<Pose2> out;
  if (!(step > 0.0) || total <= 0.0) {
    out.push_back(total <= 0.0 ? start : end_pose(start, path));
    if (total > 0.0) out.insert(out.begin(), start);
    return out;
  }
  const auto n = static_cast<std::size_t>(std::ceil(total / step));
  out.reserve(n + 1);
  out.push_back(start);
  // Walk segment by segment so each sample costs one advance().
  Pose2 seg_start = start;
  double seg_begin = 0.0;
  std::size_t k = 1;
  for (const auto& seg : path.segments) {
    const double seg_end = seg_begin + seg.length;
    for (; k < n; ++k) {
      const double s = total * static_cast<double>(k) / static_cast<double>(n);
      if (s > seg_end) break;
      out.push_back(advance(seg_start, {seg.steer, seg.gear, s - seg_begin}, path.radius));
    }
    seg_start = advance(seg_start, seg, path.radius);
    seg_begin = seg_end;
  }
  for (; k < n; ++k) out.push_back(seg_start);  // rounding at the very end
  out.push_back(seg_start);
  return out;
}

Path reversed(const Path& path) {
  Path r;
  r.radius = path.radius;
  r.segments.assign(path.segments.rbegin(), path.segments.rend());
  for (auto& s : r.segments) s.gear = -s.gear;
  return r;
}

Path concatenate(const Path& first, const Path& second) {
  assert(first.radius == second.radius || first.segments.empty() || second.segments.empty());
  Path p;
  p.radius = first.segments.empty() ? second.radius : first.radius;
  p.segments = first.segments;
  for (const auto& s : second.segments) {
    if (!p.segments.empty() && p.segments.back().steer == s.steer &&
        p.segments.back().gear == s.gear)
      p.segments.back().length += s.length;
    else
      p.segments.push_back(s);
  }
  return p;
}

}  // namespace hrs::rs
