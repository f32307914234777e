// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the proposed planner did, counted per design run and per iteration
// (report.json "legs", the harness's measures, Fig. "rrt-it"'s histogram).

#include <cstdint>
#include <map>

namespace hrs::planning {

//! Counts over a design run (or one iteration). Deterministic: legs are
//! counted once per key and iteration, from the pure outcomes.
struct ReuseCounters {
  std::uint64_t legs_database = 0;  //!< served from the database, transformed and validated
  std::uint64_t legs_repaired = 0;  //!< stored path repaired (valid part kept, gap planned)
  std::uint64_t legs_planned = 0;   //!< planned fresh and found
  std::uint64_t legs_failed = 0;    //!< planned fresh, nothing found
  std::uint64_t legs_rejected = 0;  //!< stored paths not valid as they were
  //! Of legs_database: no check run, every object moved since the last
  //! check stood out of reach (ReuseOptions::skip_far_checks).
  std::uint64_t checks_skipped = 0;
  std::uint64_t trees_reused = 0;     //!< fresh plans that grew a kept tree
  std::uint64_t failures_reused = 0;  //!< failed legs known to fail again (in legs_failed)
  std::uint64_t legs_proven = 0;      //!< failed legs proven impossible (in legs_failed)
  std::uint64_t leg_requests = 0;     //!< leg look-ups by tours (shared legs counted per tour)
  //! RRT iterations of the successful fresh plans: iterations → count (Fig. "rrt-it").
  std::map<int, std::uint64_t> rrt_iterations;
  //! Work behind the outcomes (wall time, not reproducible): database
  //! validations, repairs, fresh plans found, fresh plans failed.
  double database_ms = 0.0, repaired_ms = 0.0, planned_ms = 0.0, failed_ms = 0.0;
  ReuseCounters& operator+=(const ReuseCounters& other);
};

}  // namespace hrs::planning
