// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Reeds–Shepp curves (Reeds & Shepp 1990; the paper's steering function,
// §III-B, and the RS-decomposition of §V-A): shortest paths of a car that
// drives forwards and backwards with a minimum turning radius.
//
// API contract used by planning/ (the rs issue may extend, not break it):
//   rs::Segment, rs::Steer, rs::Path, rs::shortest_path, rs::shortest_length,
//   rs::pose_at, rs::sample.
//
// The shortest path is the minimum over the 48 words of Reeds and Shepp's
// sufficient family (CSC, CCC, CCCC, CCSC, CCSCC with time-flip, reflection
// and backwards symmetries), evaluated in closed form with shared trigonometry
// and lower-bound pruning: a candidate's arcs are first known as directions
// (products of |A|, |B| and algebraic rotations), so a candidate that breaks
// a sign constraint or cannot be shorter costs no atan2; see
// rs/reeds_shepp.cpp for the formulas' sources.

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
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
//! Poses from start to end at most `step` metres apart, both ends included
//! (a zero-length path gives the start pose once). Requires step > 0.
std::vector<Pose2> sample(const Pose2& start, const Path& path, double step);

//! The exact shortest RS path from `from` to `to` (all 48 words).
//! Requires radius > 0. Segments shorter than ~1e-11 radius are dropped, so
//! identical poses give an empty path and collinear ones a single "S".
Path shortest_path(const Pose2& from, const Pose2& to, double radius);
//! Its length only (no allocation).
double shortest_length(const Pose2& from, const Pose2& to, double radius);
//! A lower bound of shortest_length, without solving: the larger of the
//! straight-line distance and radius · |Δθ| (Δθ wrapped to (−π, π]; a path
//! whose curvature is at most 1 / radius turns at most ds / radius along ds).
inline double length_lower_bound(const Pose2& from, const Pose2& to, double radius) {
  const double dx = to.x - from.x, dy = to.y - from.y;
  return std::max(std::sqrt(dx * dx + dy * dy),
                  radius * std::abs(geometry::wrap_angle(to.theta - from.theta)));
}
//! The index in `from` of the pose with the shortest path to `to`, the first
//! of equal lengths (from.size() when there is none of finite length): the
//! answer of computing shortest_length for each in order and keeping a
//! strictly shorter one, with fewer solves (candidates go by increasing
//! length_lower_bound and stop once a bound exceeds the best length).
//! `scratch` is reused between calls.
std::size_t first_shortest(std::span<const Pose2> from, const Pose2& to, double radius,
                           std::vector<std::pair<double, std::size_t>>& scratch);

// ---- Additions beyond the planner's contract ------------------------------

//! Number of words in Reeds and Shepp's sufficient family.
inline constexpr int kWordCount = 48;

//! Name of word `id` in [0, kWordCount), e.g. "L+R-S-L-" (the nominal word:
//! it keeps segments that happen to have zero length in a given query).
std::string_view word_name(int id);
//! Id of a word name such as "L+S+R-"; -1 when it is not one of the 48.
int word_id(std::string_view name);

//! Length (metres) and word id of the shortest path.
struct ShortestWord {
  double length = 0.0;  //!< metres
  int word = 0;         //!< in [0, kWordCount)
};
//! The shortest path's length and word (no allocation); same result as
//! shortest_path().
ShortestWord shortest_word(const Pose2& from, const Pose2& to, double radius);
//! How much of the search the solver skips. Every level finds a shortest
//! path; kNone evaluates all 48 words, kFamilyBounds skips a formula family
//! whose lower bound is not below the best so far, kFull (what every other
//! function here uses) also skips single candidates whose arcs' directions
//! break a sign constraint or bound the length above the best. kFull and
//! kFamilyBounds give the same answer bit for bit; kNone may pick another
//! word among words whose lengths tie to rounding.
enum class Pruning { kNone, kFamilyBounds, kFull };
//! shortest_word() with the given pruning (tests and benchmarks).
ShortestWord shortest_word(const Pose2& from, const Pose2& to, double radius, Pruning pruning);

//! Length of the shortest path of one given word from `from` to `to`, or
//! +infinity when that word cannot connect them (no allocation). Evaluated by
//! a separate, plain implementation of the formulas.
double word_length(int word, const Pose2& from, const Pose2& to, double radius);
//! The path of one given word, or nullopt when that word cannot connect them.
std::optional<Path> word_path(int word, const Pose2& from, const Pose2& to, double radius);

//! Pose at the end of `path` driven from `start`.
Pose2 end_pose(const Pose2& start, const Path& path);
//! The same curve driven from its end back to its start: segments in reverse
//! order with the gear flipped.
Path reversed(const Path& path);
//! `first` followed by `second` (radii must match); equal adjacent segments
//! (same steer and gear) are merged.
Path concatenate(const Path& first, const Path& second);

}  // namespace hrs::rs
