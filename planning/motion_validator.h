// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Continuous collision checking of Reeds–Shepp motions (the paper's planner
// checks every RRT edge against furniture and walls, §III-B). Each segment is
// handed to CSpace::straight_free / arc_free, which certify a whole motion
// without sampling; a path is free when all its segments are. The free prefix
// of a path (where the RRT stops "at the first invalid pose") is found by
// cutting the path into short pieces and checking them in order.
//
// One validator per planner instance: it counts its checks, so it is cheap
// mutable state; the CSpace it reads is shared and never modified here.

#include <cassert>
#include <cstdint>

#include "geometry/cspace.h"
#include "geometry/pose.h"
#include "rs/reeds_shepp.h"

namespace hrs::planning {

using geometry::CSpace;
using geometry::Pose2;

class MotionValidator {
 public:
  //! Checks motions in `cspace` with arcs of turning radius `radius`.
  MotionValidator(const CSpace& cspace, double radius) : cspace_(&cspace), radius_(radius) {
    assert(radius > 0.0 && "MotionValidator: turning radius must be > 0");
  }

  const CSpace& cspace() const { return *cspace_; }
  double radius() const { return radius_; }

  //! True only if the chair at `pose` is certainly free.
  bool pose_free(const Pose2& pose);
  //! Continuous check of one segment driven from `start` (no sampling).
  bool segment_free(const Pose2& start, const rs::Segment& segment);
  //! Continuous check of a whole path driven from `start`.
  bool path_free(const Pose2& start, const rs::Path& path);
  //! Arc length of the longest prefix of `path` made of whole free pieces,
  //! where the path is cut into pieces of at most `piece` metres (and at its
  //! segment borders); the path is free up to there. Equals path.length()
  //! when the whole path is free.
  double free_prefix(const Pose2& start, const rs::Path& path, double piece);
  //! As free_prefix(), but a piece the continuous check cannot certify is
  //! bisected up to `refine_depth` times (5 cm / 2^6 < 1 mm) before it counts
  //! as blocked: the checks are conservative (a cover of the swept chair), so
  //! a free motion cut differently can be certified where one cut was not,
  //! and a blocked motion stays blocked at every cut.
  double certified_prefix(const Pose2& start, const rs::Path& path, double piece,
                          int refine_depth = 6);

  //! Continuous checks performed so far (one per segment or piece).
  std::uint64_t checks() const { return checks_; }
  void reset_checks() { checks_ = 0; }

 private:
  bool certified(const Pose2& start, const rs::Segment& part, int depth);

  const CSpace* cspace_;
  double radius_;
  std::uint64_t checks_ = 0;
};

}  // namespace hrs::planning
