// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Measurements of found legs kept across the tours and iterations of a
// design run (part of the proposed planner, §V; technique `metrics` in
// planning/reuse.h). Each tour of each iteration measures every leg it found
// (the clearance metrics of §III-D, one CSpace::clearance per waypoint) and
// the design re-certifies it (MotionValidator::certified_prefix). Legs are
// shared by the tours of an iteration and mostly unchanged from one
// iteration to the next, where one object moved.
//
// Both answers are exact: equal to the last bit to measuring afresh.
// - A certified prefix is reused when the leg (start pose and path) is
//   bit-identical to when it was computed and every object that moved since
//   was, before and after its move, out of reach of every checked piece:
//   its footprint farther from each piece's start than the piece length
//   plus CSpace::swept_reach() plus kOffsetSlack (moved_objects_clear). No
//   collision query of the certification can then change its answer.
// - Clearance at a waypoint is the minimum over walls and objects of
//   per-obstacle distances (CSpace::nearest_obstacles). When the leg is
//   unchanged and some objects moved, a side whose nearest obstacle did not
//   move keeps its value lowered by the moved objects' new distances
//   (CSpace::object_clearance; skipped for an object whose position is
//   farther than both sides' values plus its CSpace::object_reach()); a side
//   whose nearest obstacle moved is measured afresh. The metrics are then
//   summed in measure()'s order.
//
// Thread-safe: tours of one iteration call in parallel. Entries are
// immutable once stored and replaced whole; since every answer equals the
// fresh one, which thread stored an entry first never shows in the output.

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "geometry/cspace.h"
#include "geometry/pose.h"
#include "geometry/scene.h"
#include "planning/metrics.h"
#include "planning/tour.h"
#include "rs/reeds_shepp.h"

namespace hrs::planning {

class LegMeasures {
 public:
  //! Reads `cspace` at each call (its layout may change between calls);
  //! `scene` gives the footprints. Both must outlive this.
  //! `reference_width`: the scene's weights.clearance_width.
  LegMeasures(const geometry::Scene& scene, const geometry::CSpace& cspace, double radius,
              double reference_width);

  //! Fills leg.waypoints (every `step` metres) and leg.metrics, equal to
  //! waypoints_of() and measure() in the current layout.
  void measure(Leg& leg, double step);
  //! Equal to MotionValidator(cspace, radius).certified_prefix(leg.from,
  //! leg.path, piece) in the current layout.
  double certified_prefix(const Leg& leg, double piece);

  //! How the answers were obtained (depends on thread timing: not for reports).
  struct Counters {
    std::uint64_t metrics_same = 0;     //!< nothing moved: stored metrics
    std::uint64_t metrics_updated = 0;  //!< objects moved: stored clearances updated
    std::uint64_t metrics_fresh = 0;    //!< no usable entry: measured afresh
    std::uint64_t certified_same = 0;   //!< nothing moved: stored prefix
    std::uint64_t certified_kept = 0;   //!< objects moved, all out of reach: stored prefix
    std::uint64_t certified_fresh = 0;  //!< certified afresh
  };
  Counters counters() const;

 private:
  struct MetricsEntry {
    double step = 0.0;
    Pose2 from;
    rs::Path path;
    std::vector<Pose2> layout;  //!< object poses when measured
    std::vector<Pose2> waypoints;
    std::vector<geometry::CSpace::NearestObstacles> nearest;  //!< per waypoint
    PathMetrics metrics;
  };
  struct CertifiedEntry {
    Pose2 from;
    rs::Path path;
    double piece = 0.0;
    std::vector<Pose2> layout;
    double prefix = 0.0;
    std::vector<geometry::Vec2> starts;  //!< start position of every piece checked
  };
  //! Brings the stored nearest obstacles of `entry` (measured in another
  //! layout, same leg) to `now`, where the objects `moved` moved.
  void update_nearest(MetricsEntry& entry, const std::vector<int>& moved,
                      const std::vector<Pose2>& now) const;
  //! True when no object that moved between `then` and `now` came within
  //! reach of a piece of `e` (in either pose).
  bool moves_out_of_reach(const CertifiedEntry& e, const std::vector<Pose2>& now) const;

  const geometry::Scene* scene_;
  const geometry::CSpace* cspace_;
  double radius_;
  double reference_width_;
  double swept_reach_;                //!< CSpace::swept_reach()
  std::vector<double> object_reach_;  //!< CSpace::object_reach() per object
  mutable std::mutex mutex_;          //!< guards the maps and counters_
  std::map<LegKey, std::shared_ptr<const MetricsEntry>> metrics_;
  std::map<LegKey, std::shared_ptr<const CertifiedEntry>> certified_;
  Counters counters_;
};

}  // namespace hrs::planning
