// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The proposed planner's switches (paper §V and our additions): which reuse
// techniques are on and their parameters, and their names (names(), which
// reports print; the --reuse text is parsed in api/reuse_list.h). All
// techniques off is the baseline planner exactly.

#include <array>
#include <string>
#include <string_view>


namespace hrs::planning {

//! Which §V techniques are on, and their parameters.
struct ReuseOptions {
  bool samples = true;   //!< §V-A: RRT samples from the RS-decomposition
  bool steering = true;  //!< §V-A: RS look-ups through the decomposition (exact fallback)
  bool paths = true;     //!< §V-B: path database, shared within and across iterations
  bool trees = true;     //!< §V-C: RRT trees reused while their root barely moves
  //! Beyond the paper: a leg whose RRT failed fails again, without planning,
  //! while its ends are unchanged and every object moved since stayed out of
  //! reach of every pose that RRT examined (then the same run would make the
  //! same collision queries with the same answers: a proof, not a guess).
  bool failures = true;
  //! Beyond the paper: every path the planner stores (fresh or repaired) is
  //! shortened first (shorten_path), so that reused paths are not the
  //! RRT's detours: without it, reuse trades tour length for time.
  bool shortcuts = true;
  //! Beyond the paper (its Fig. "rrt-it": a path that is found at all is
  //! nearly always found in few RRT iterations): a fresh plan stops after
  //! `budget_iterations` RRT iterations instead of the planner's own cap
  //! (3000). A leg that would have needed more fails and the tour tries its
  //! next pose pair: this trades a few hard legs for the time every failing
  //! leg used to cost, which the final costs must absorb (measured in
  //! docs/BENCHMARKS.md). Repairs keep their own, smaller budget.
  //! Opt-in, not in "all": it cost tours found in hard rooms (a design
  //! must not be worse with the proposed planner; docs/planner.md).
  bool budget = false;
  //! Beyond the paper: the clearance metrics and the re-certification of a
  //! found leg are kept (planning/leg_measures.h) and brought up to date
  //! instead of recomputed, by the tours that share the leg and in later
  //! layouts. Exact: the results are the fresh ones to the last bit.
  bool metrics = true;
  //! Beyond the paper: a leg (by key) whose fresh plans failed k times in a
  //! row gets the fresh-plan budget halved k times, down to
  //! `backoff_floor` RRT iterations, and the whole budget again once found.
  //! The failures of a design run repeat by key (goal poses in tight spots
  //! fail layout after layout), and a leg that is found at all is nearly
  //! always found in few iterations (Fig. "rrt-it"). A heuristic: a leg that
  //! needs more than its reduced budget fails (measured in docs/BENCHMARKS.md).
  //! Opt-in, not in "all", for the same reason as `budget`.
  bool backoff = false;
  //! Beyond the paper; changes the work, never an outcome: a tour that asks
  //! for a leg another tour is planning at that moment (tours of an
  //! iteration share legs, computed once) plans, instead of waiting, the
  //! first leg of its own remaining candidates that nobody has started.
  //! A leg that keeps a tour waiting is usually failing (a found leg stops
  //! early), so that tour's next candidate is usually needed next. Legs
  //! computed this way and never asked for leave no trace: counters and
  //! stores take only the legs the tours asked for. One thread: no effect.
  bool speculate = true;
  int backoff_floor = 120;      //!< RRT iterations a backed-off fresh plan keeps at least
  int budget_iterations = 300;  //!< RRT iterations of a fresh plan with `budget` on
  //! §V-B: a stored path whose ends moved apart is repaired (valid part kept,
  //! gap re-planned) before a fresh plan is tried.
  bool repair = true;
  int repair_iterations = 30;  //!< RRT iterations allowed to close a repair's gap
  //! §V-B, exact (part of `paths`, no name of its own; off only in tests): a
  //! stored path that path_free() found free in an earlier layout, driven
  //! from the same start, is served without checking it again when every
  //! object that moved since stays clear of it by a proven margin
  //! (ReusePlanner::still_free): the check would pass.
  bool skip_far_checks = true;
  //! §V-C: a tree is kept while its root moved at most this much (metres +
  //! radians); the tree moves rigidly with its root and is then pruned.
  double tree_root_tolerance = 0.1;
  int tree_max_nodes = 30;           //!< §V-C: a tree past this many nodes is rebuilt (paper: 30)
  int decomposition_initial = 1000;  //!< K of the decomposition (paper: 1000)
  int decomposition_stop = 100;      //!< consecutive agreeing samples ending it (paper: 100)

  //! A technique's --reuse name and its switch.
  struct Technique {
    const char* name;
    bool ReuseOptions::*on;
    const char* what;  //!< one line for --help and the docs
  };
  //! Every technique, in the order names() lists them: the one list that
  //! api::parse_reuse(), names(), any() and none() go through.
  static const std::array<Technique, 10>& techniques();
  //! A technique's numeric parameter, set by NAME=N (budget=500, backoff=10).
  struct Parameter {
    const char* technique;
    bool ReuseOptions::*on;  //!< the technique NAME=N turns on
    int ReuseOptions::*value;
    const char* unit;
  };
  static const std::array<Parameter, 2>& parameters();

  //! True when at least one technique is on; all off is the baseline exactly.
  bool any() const;
  //! Every technique off.
  static ReuseOptions none();
  //! The comma list of the techniques on ("none" when none), with NAME=N
  //! where a parameter differs from its default (the --reuse syntax).
  std::string names() const;
};

}  // namespace hrs::planning
