// SPDX-License-Identifier: GPL-3.0-or-later
#include "planning/motion_validator.h"

#include <algorithm>
#include <cmath>

#include "planning/path_ops.h"

namespace hrs::planning {

bool MotionValidator::pose_free(const Pose2& pose) {
  ++checks_;
  return cspace_->is_free(pose);
}

bool MotionValidator::segment_free(const Pose2& start, const rs::Segment& segment) {
  ++checks_;
  switch (segment.steer) {
    case rs::Steer::kStraight:
      return cspace_->straight_free(start, segment.gear * segment.length);
    case rs::Steer::kLeft:
      return cspace_->arc_free(start, radius_, segment.length / radius_, segment.gear);
    case rs::Steer::kRight:
      return cspace_->arc_free(start, radius_, -segment.length / radius_, segment.gear);
  }
  return false;
}

bool MotionValidator::path_free(const Pose2& start, const rs::Path& path) {
  Pose2 p = start;
  for (const rs::Segment& seg : path.segments) {
    if (!segment_free(p, seg)) return false;
    p = rs::advance(p, seg, radius_);
  }
  return true;
}

double MotionValidator::free_prefix(const Pose2& start, const rs::Path& path, double piece) {
  return certified_prefix(start, path, piece, 0);  // no bisection: the plain cut
}

bool MotionValidator::certified(const Pose2& start, const rs::Segment& part, int depth) {
  if (segment_free(start, part)) return true;
  if (depth <= 0) return false;
  const rs::Segment half{part.steer, part.gear, 0.5 * part.length};
  return certified(start, half, depth - 1) &&
         certified(rs::advance(start, half, radius_), half, depth - 1);
}

double MotionValidator::certified_prefix(const Pose2& start, const rs::Path& path, double piece,
                                         int refine_depth) {
  double done = 0.0;
  for_each_piece(start, path, piece, radius_, [&](const PathPiece& q) {
    if (!certified(q.start, q.part, refine_depth)) return false;
    done += q.part.length;
    return true;
  });
  return done;
}

}  // namespace hrs::planning
