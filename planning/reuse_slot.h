// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One key's shared outcome in an iteration of the proposed planner
// (ReusePlanner, planning/reuse.h): what stage A (the database) and stage B
// (repair or a fresh plan) produced, and how, for end_iteration() to count
// and store. Internal to ReusePlanner.

#include <atomic>
#include <limits>
#include <mutex>
#include <optional>
#include <vector>

#include "geometry/pose.h"
#include "planning/leg_provider.h"
#include "planning/reuse_counters.h"
#include "planning/rrt.h"

namespace hrs::planning {

struct ReuseSlot {
  std::mutex mutex;
  geometry::Pose2 from, to;
  //! The lowest index of a tour that asked for this leg (none: only
  //! `speculate` computed it, no trace).
  int first_request = kNoTour;
  //! The same among tours that asked with planning allowed: only then does
  //! stage B's outcome count (else stage B ran for `speculate` alone).
  int first_plan_request = kNoTour;
  static constexpr int kNoTour = std::numeric_limits<int>::max();
  bool speculative = false;  //!< computed by speculate_one()
  //! Its holder is validating or planning (not merely reading a result).
  std::atomic<bool> working{false};
  bool database_done = false;  //!< stage A ran
  bool check_skipped = false;  //!< stage A served the stored path by still_free()
  LegOutcome database;
  bool planned_done = false;  //!< stage B ran
  LegOutcome planned;
  int fresh_iterations = -1;  //!< RRT iterations of the fresh plan (−1: none)
  bool tree_reused = false;
  bool failure_reused = false;
  bool proven = false;  //!< the fresh plan was refused by the gate (a proof)
  std::optional<RrtTree> grown;               //!< the fresh plan's tree (tree reuse)
  std::vector<geometry::Vec2> failed_points;  //!< a failed fresh plan's nodes and goal
};

//! Adds the work of `more` to `into` (tree_nodes: the larger).
void add_stats(LegStats& into, const LegStats& more);

//! Counts the slot's outcome into `c` and returns it: the database's when
//! it served the leg, else stage B's when `planned` (it counts), else null.
const LegOutcome* count_slot(const ReuseSlot& slot, bool planned, ReuseCounters& c);

}  // namespace hrs::planning
