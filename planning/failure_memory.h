// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Memory of failed legs (beyond the paper; the proposed planner's `failures`
// and `backoff` techniques). A failed RRT run is kept with its ends, the
// layout it ran in and every position its collision queries were centred
// near; while the ends are unchanged and every object that moved since
// stayed out of reach of those positions, the same run would make the same
// queries with the same answers, so the failure repeats: a proof, not a
// guess. The memory also counts each key's failures in a row (`backoff`).
//
// Written between iterations only (ReusePlanner::end_iteration), read by the
// tours of an iteration in parallel: no lock is needed.

#include <map>
#include <vector>

#include "geometry/cspace.h"
#include "geometry/pose.h"
#include "geometry/scene.h"
#include "planning/tour.h"

namespace hrs::planning {

class FailureMemory {
 public:
  //! `margin`: how far from a node (or the goal) an object's footprint must
  //! stay for no collision query of the run to change (moved_objects_clear).
  FailureMemory(const geometry::Scene& scene, double margin) : scene_(&scene), margin_(margin) {}

  //! True when the recorded failure of `key` provably repeats in the
  //! current layout of `cspace`.
  bool repeats(const LegKey& key, const geometry::Pose2& from, const geometry::Pose2& to,
               const geometry::CSpace& cspace) const;
  //! Records a failed run of `key` in `layout` (object poses) whose queries
  //! were centred near `points`.
  void record(const LegKey& key, const geometry::Pose2& from, const geometry::Pose2& to,
              std::vector<geometry::Pose2> layout, std::vector<geometry::Vec2> points);
  //! The leg was found: its recorded failure no longer holds.
  void forget(const LegKey& key) { failures_.erase(key); }

  //! `backoff`: fresh plans of `key` that failed in a row since last found.
  int failed_in_a_row(const LegKey& key) const;
  //! Counts a fresh plan's outcome for failed_in_a_row().
  void count_fresh_plan(const LegKey& key, bool found);

 private:
  struct Failure {
    geometry::Pose2 from, to;
    std::vector<geometry::Pose2> layout;
    std::vector<geometry::Vec2> points;
  };
  const geometry::Scene* scene_;
  double margin_;
  std::map<LegKey, Failure> failures_;
  std::map<LegKey, int> in_a_row_;
};

}  // namespace hrs::planning
