// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Small operations on Reeds–Shepp paths that the planner needs when it grows
// a tree edge by edge (§III-B) and joins legs into tours (§III-C): cutting a
// path at an arc length, concatenating paths, normalising segment lists.

#include <vector>

#include "geometry/pose.h"
#include "rs/reeds_shepp.h"

namespace hrs::planning {

//! Segments shorter than this (metres) are dropped when paths are normalised.
inline constexpr double kMinSegmentLength = 1e-12;

//! Appends `segment` to `out`, merging it into the last segment when steer and
//! gear agree and dropping it when it is shorter than kMinSegmentLength.
void append_segment(std::vector<rs::Segment>& out, const rs::Segment& segment);
//! The part of `path` between arc lengths `s0` and `s1` (clamped, s0 <= s1).
rs::Path subpath(const rs::Path& path, double s0, double s1);
//! A segment cut into `count` equal pieces of at most `max_piece` metres
//! (at least one): the one cut the continuous checks, the re-certification
//! and the path operations share.
struct SegmentPieces {
  int count;
  rs::Segment part;  //!< one piece: the segment's steer and gear, length / count
};
SegmentPieces cut_segment(const rs::Segment& segment, double max_piece);
//! One piece of a path walked by for_each_piece().
struct PathPiece {
  geometry::Pose2 start;
  rs::Segment part;
  geometry::Pose2 end;  //!< rs::advance(start, part, radius)
};
//! Walks `path` driven from `start` in the pieces of cut_segment(segment,
//! max_piece), segment by segment, arcs of turning radius `radius`; calls
//! visit(piece) in order and stops at the first call returning false.
//! True when every piece was visited and accepted.
template <class Visit>
bool for_each_piece(const geometry::Pose2& start, const rs::Path& path, double max_piece,
                    double radius, Visit&& visit) {
  geometry::Pose2 p = start;
  for (const rs::Segment& seg : path.segments) {
    const auto [pieces, part] = cut_segment(seg, max_piece);
    for (int i = 0; i < pieces; ++i) {
      const PathPiece piece{p, part, rs::advance(p, part, radius)};
      if (!visit(piece)) return false;
      p = piece.end;
    }
  }
  return true;
}

}  // namespace hrs::planning
