// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Paper §V-B: the path database. Paths found in earlier layouts (and by the
// other tours of the same layout) are kept by leg key and served again when
// the leg's ends kept their relative pose; ReusePlanner validates, repairs
// and counts them (planning/reuse.h).

#include <map>
#include <optional>
#include <vector>

#include "geometry/cspace.h"
#include "geometry/pose.h"
#include "geometry/scene.h"
#include "planning/tour.h"
#include "rs/reeds_shepp.h"

namespace hrs::planning {

using geometry::Pose2;

//! §V-B: paths keyed by LegKey. A path is a list of RS segments driven from
//! its start, so it lives in the frame of its from-pose; its to-pose is kept
//! relative to that frame. When the current ends have the same relative pose
//! (both objects moved rigidly together, or neither moved), the stored path
//! driven from the new from-pose ends exactly at the new to-pose.
class PathDatabase {
 public:
  struct Entry {
    rs::Path path;
    Pose2 from, to;  //!< world poses of the ends when stored
    //! Object poses of a layout in which MotionValidator::path_free(from,
    //! path) held; empty when the path was never checked that way (a fresh
    //! or repaired path was checked in pieces, which is not the same query).
    std::vector<Pose2> checked;
    //! With `checked`: the chair's reference positions along the path from
    //! `from`, at most kTraceStep metres apart, both ends included.
    std::vector<geometry::Vec2> trace;
  };
  //! Ends whose relative poses differ by at most this are "the same" (m + rad).
  static constexpr double kRigidTolerance = 1e-9;
  //! Spacing (metres of path) of Entry::trace.
  static constexpr double kTraceStep = 0.1;

  const Entry* find(const LegKey& key) const;
  //! The stored path transformed to the ends `from`, `to` when they are
  //! rigidly the same as the stored ones, else nullopt.
  std::optional<rs::Path> transformed(const LegKey& key, const Pose2& from, const Pose2& to) const;
  //! Stores the path; `checked`: the object poses of a layout in which
  //! path_free(from, path) held (empty: not known), then the trace is kept.
  void put(const LegKey& key, const Pose2& from, const Pose2& to, const rs::Path& path,
           std::vector<Pose2> checked = {});
  void erase(const LegKey& key) { entries_.erase(key); }
  //! True when path_free(e.from, e.path), which held in the layout
  //! e.checked, provably holds in the current layout of `cspace`: every
  //! object that moved since lies (now) farther than `margin` from each point
  //! of e.trace (moved_objects_clear; its old pose blocked nothing then and
  //! is gone, so no query of the check can change to "blocked"). The
  //! margin's terms are in ReusePlanner's constructor.
  static bool still_free(const Entry& e, const geometry::CSpace& cspace,
                         const geometry::Scene& scene, double margin);
  std::size_t size() const { return entries_.size(); }

 private:
  std::map<LegKey, Entry> entries_;
};

}  // namespace hrs::planning
