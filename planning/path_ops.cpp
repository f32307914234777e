// SPDX-License-Identifier: GPL-3.0-or-later
#include "planning/path_ops.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace hrs::planning {

void append_segment(std::vector<rs::Segment>& out, const rs::Segment& segment) {
  if (!(segment.length >= kMinSegmentLength)) return;
  if (!out.empty() && out.back().steer == segment.steer && out.back().gear == segment.gear) {
    out.back().length += segment.length;
    return;
  }
  out.push_back(segment);
}

SegmentPieces cut_segment(const rs::Segment& segment, double max_piece) {
  assert(max_piece > 0.0 && segment.length >= 0.0);
  const int count = std::max(1, static_cast<int>(std::ceil(segment.length / max_piece - 1e-9)));
  return {count, rs::Segment{segment.steer, segment.gear, segment.length / count}};
}

rs::Path subpath(const rs::Path& path, double s0, double s1) {
  assert(s0 <= s1 && "subpath: s0 <= s1");
  rs::Path out;
  out.radius = path.radius;
  double start = 0.0;
  for (const rs::Segment& seg : path.segments) {
    const double end = start + seg.length;
    const double a = std::max(start, s0);
    const double b = std::min(end, s1);
    if (b > a) append_segment(out.segments, {seg.steer, seg.gear, b - a});
    start = end;
    if (start >= s1) break;
  }
  return out;
}

}  // namespace hrs::planning
