// SPDX-License-Identifier: GPL-3.0-or-later
#include "planning/reuse_slot.h"

#include <algorithm>

namespace hrs::planning {

void add_stats(LegStats& into, const LegStats& more) {
  into.iterations += more.iterations;
  into.collision_checks += more.collision_checks;
  into.tree_nodes = std::max(into.tree_nodes, more.tree_nodes);
  into.time_ms += more.time_ms;
}

const LegOutcome* count_slot(const ReuseSlot& slot, bool planned, ReuseCounters& c) {
  if (slot.database.rejected) ++c.legs_rejected;
  const LegOutcome* outcome = nullptr;
  if (slot.database_done && slot.database.found) {
    outcome = &slot.database;
    ++c.legs_database;
    if (slot.check_skipped) ++c.checks_skipped;
    c.database_ms += outcome->stats.time_ms;
  } else if (planned) {
    outcome = &slot.planned;
    if (outcome->found && outcome->source == LegSource::kRepaired) {
      ++c.legs_repaired;
      c.repaired_ms += outcome->stats.time_ms;
    } else if (outcome->found) {
      ++c.legs_planned;
      ++c.rrt_iterations[slot.fresh_iterations];
      c.planned_ms += outcome->stats.time_ms;
    } else {
      ++c.legs_failed;
      c.failed_ms += outcome->stats.time_ms;
    }
  }
  if (planned) {
    if (slot.tree_reused) ++c.trees_reused;
    if (slot.failure_reused) ++c.failures_reused;
    if (slot.proven && !slot.planned.found) ++c.legs_proven;
  }
  return outcome;
}

}  // namespace hrs::planning
