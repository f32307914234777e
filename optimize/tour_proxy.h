#pragma once
// SPDX-License-Identifier: GPL-3.0-or-later
// A tour-length proxy of a layout, without planning: what the M tours
// would cost if the wheelchair drove the shortest Reeds–Shepp curve
// (Reeds & Shepp 1990) between one stop per allowed side of each object
// (the free goal pose nearest the middle of that side), ignoring obstacles
// between stops. The polish's shorter-tour
// rearrangement (optimize/rearrange.h, RearrangeGoal::kShorterTours)
// searches layouts that lower it; every layout it keeps is planned and
// kept only at a lower total cost, so the proxy steers and never decides.
//
// Per sequence k (door first), a dynamic programme over the stops picks the
// cheapest stop of each visited object: a leg into object o from stop a to
// stop b costs α̂(o) · (w_l · RS(a, b) + w_r · |wrap(θ_b − θ_a)|), the
// legs' terms of C_path (paper §III-D) with the shortest curve for the
// planned path and its net turn for the rotation; the proxy is
// Σ_k L̂(s_k) · DP_k, in the units of the total cost. An object with no
// stop left free (a stop's chair footprint, corners and centre, outside
// the room or inside another footprint) is charged for its legs the length
// and rotation terms of an unfound tour (CostModel::unfound_length(), share
// 1, no clearance term).

#include <string>
#include <vector>

#include "geometry/pose.h"
#include "geometry/scene.h"
#include "optimize/costs.h"
#include "planning/goals.h"

namespace hrs::optimize {

class TourProxy {
 public:
  //! `local[i]`: object i's goal poses in its own frame
  //! (planning::local_goal_poses with the tours' options).
  TourProxy(const geometry::Scene& scene, const CostModel& model,
            const std::vector<std::vector<planning::GoalPose>>& local);

  //! The proxy of the layout `poses` (scene order). Footprints, free stops,
  //! each leg's cost matrix and each sequence's term are cached from the
  //! previous call and recomputed only where something moved (free stops:
  //! of the objects whose stops' reach a moved footprint's box meets), so
  //! a chain that moves one or two objects a step pays for those; one
  //! TourProxy serves one thread.
  double value(const std::vector<geometry::Pose2>& poses) const;


 private:
  const geometry::Scene& scene_;
  const CostModel& model_;
  //! Per object, per allowed side with a goal pose: that side's goal poses
  //! in the object's frame, from the middle slot outwards.
  std::vector<std::vector<std::vector<geometry::Pose2>>> stops_;
  //! One leg's cost matrix between its two ends' free stops, for the stops
  //! it was computed with.
  struct Leg {
    int from = -1, to = -1;  //!< object indices (−1: the door)
    std::vector<geometry::Pose2> from_stops, to_stops;
    std::vector<double> cost;  //!< w_l · RS + w_r · |Δθ|, row-major (from, to)
    bool valid = false;
  };
  std::vector<std::vector<int>> nodes_;  //!< per sequence: object indices (−1: the door)
  std::vector<std::vector<int>> legs_;   //!< per sequence: indices into leg_cache_ by (from node · size + to node)
  std::vector<double> alpha_;            //!< α̂ per object
  geometry::Pose2 door_;
  // The caches (see value()).
  mutable std::vector<Leg> leg_cache_;
  mutable std::vector<geometry::Pose2> at_;  //!< the poses the footprints are for
  mutable std::vector<geometry::Polygon> fp_;
  mutable std::vector<geometry::Box> box_;
  mutable std::vector<geometry::Box> reach_;  //!< round every stop's chair, per object
  mutable std::vector<double> seq_;           //!< each sequence's term
  mutable std::vector<std::vector<geometry::Pose2>> free_;  //!< free stops per object
  mutable bool cached_ = false;
};

}  // namespace hrs::optimize
