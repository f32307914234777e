// SPDX-License-Identifier: GPL-3.0-or-later
#include "planning/path_shortening.h"

#include <vector>

#include "planning/path_ops.h"

namespace hrs::planning {

rs::Path shorten_path(const Pose2& start, const rs::Path& path, MotionValidator& validator,
                      double step) {
  // Poses along the path and their arc lengths.
  std::vector<Pose2> pose{start};
  std::vector<double> at{0.0};
  double s = 0.0;
  for_each_piece(start, path, step, path.radius, [&](const PathPiece& q) {
    s += q.part.length;
    pose.push_back(q.end);
    at.push_back(s);
    return true;
  });
  const int n = static_cast<int>(pose.size()) - 1;
  if (n < 2) return path;
  rs::Path out{{}, path.radius};
  int i = 0;
  while (i < n) {
    int next = i + 1;
    rs::Path piece = subpath(path, at[i], at[i + 1]);
    for (int j = n; j > i + 1; j = i + (j - i) / 2) {
      rs::Path direct = rs::shortest_path(pose[i], pose[j], path.radius);
      if (direct.length() < at[j] - at[i] - 1e-3 && validator.path_free(pose[i], direct)) {
        next = j;
        piece = std::move(direct);
        break;
      }
    }
    for (const rs::Segment& seg : piece.segments) append_segment(out.segments, seg);
    i = next;
  }
  return out;
}

}  // namespace hrs::planning
