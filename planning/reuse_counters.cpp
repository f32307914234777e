// SPDX-License-Identifier: GPL-3.0-or-later
#include "planning/reuse_counters.h"

namespace hrs::planning {

ReuseCounters& ReuseCounters::operator+=(const ReuseCounters& o) {
  legs_database += o.legs_database;
  legs_repaired += o.legs_repaired;
  legs_planned += o.legs_planned;
  legs_failed += o.legs_failed;
  legs_rejected += o.legs_rejected;
  checks_skipped += o.checks_skipped;
  trees_reused += o.trees_reused;
  failures_reused += o.failures_reused;
  legs_proven += o.legs_proven;
  leg_requests += o.leg_requests;
  for (const auto& [k, v] : o.rrt_iterations) rrt_iterations[k] += v;
  database_ms += o.database_ms;
  repaired_ms += o.repaired_ms;
  planned_ms += o.planned_ms;
  failed_ms += o.failed_ms;
  return *this;
}

}  // namespace hrs::planning
