// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The design runner behind `hrspace design` (paper §III, Fig. 2): simulated
// annealing over the furniture poses (§III-E) where every evaluated layout is
// toured by the wheelchair along the M most likely sequences (§III-A) and
// scored by the costs of §III-D.
//
// Per iteration: the annealer proposes a move of one movable object; a move
// that leaves the room, overlaps another object or enters the door's clear
// zone is rejected by exact predicates (geometry/polygon_ops.h) before any
// planning; otherwise the C-space is updated incrementally
// (CSpace::move_object), the M tours are planned in parallel (one
// TourPlanner per sequence, seeded from (seed, iteration, tour index), so the
// result is the same for any number of threads), the cost is computed and the
// Metropolis rule decides; a rejected move is undone in the C-space. Every
// found tour is re-certified (recheck_tour) before it counts.
//
// With the proposed planner (§V) one ReusePlanner serves the legs of all M
// tours: each plan_all() is one of its iterations (begin/end), seeded from
// (seed, iteration), so the outputs stay identical for any number of threads.
//
// The initial temperature is a fraction of the initial cost (cost units are
// metres, radians and m², so a fixed temperature would not fit every scene).

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "geometry/cspace.h"
#include "geometry/scene.h"
#include "optimize/annealer.h"
#include "optimize/arrange.h"
#include "optimize/costs.h"
#include "optimize/planner_config.h"
#include "optimize/polish.h"
#include "optimize/preferences.h"
#include "optimize/sequences.h"
#include "planning/reach_gate.h"
#include "planning/recheck.h"
#include "planning/reuse.h"
#include "planning/tour.h"

namespace hrs::optimize {

struct DesignOptions {
  std::uint64_t seed = 1;
  int iterations = 700;            //!< annealing iterations (paper: 700)
  int threads = 0;                 //!< tour-planning threads, caller included (0: all cores)
  double t_start_fraction = 0.03;  //!< t_start = this × initial total cost (docs/optimize.md)
  double t_end_ratio = 1e-3;       //!< t_end = this × t_start
  AnnealOptions anneal;            //!< moves; its temperatures and iterations are set from above
  planning::TourOptions tour;      //!< the tour planner (baseline)
  geometry::CSpaceOptions cspace;
  //! Which planner and which of the design loop's additions (refusal gate,
  //! escape, early rejection, goal skipping, preferences, shorter tours,
  //! lattice rescue): optimize/planner_config.h.
  //! `tour.planner.skip_tried_goal_nodes` is taken from it.
  PlannerConfig planner;
  planning::ReachGateOptions gate;  //!< the grid behind refusals and escape
  //! Every object's α̂ set to 1 (CostModel::set_uniform_alpha): the control
  //! of the α experiment; off in every product run.
  bool uniform_alpha = false;
  //! The opening arrangement of the input before the annealing, when
  //! `planner.prefer` is on (docs/optimize.md "Arrangement"); off only to
  //! study the annealing alone.
  bool opening = true;
  //! When set, the object poses of every planned layout are appended here,
  //! in planning order (the input of replay_planning()).
  std::vector<std::vector<Pose2>>* layouts_out = nullptr;
};

//! One iteration of a design run (report.json "trace").
struct DesignStep {
  TraceEntry anneal;
  CostTerms proposed;        //!< terms of the proposed layout (zeros when invalid)
  double planning_ms = 0.0;  //!< wall time of planning the M tours
  bool planned = false;      //!< the M tours were planned for this proposal
  //! Rejected on a lower bound: `proposed` holds the interior terms and the
  //! tours planned before the decision (tours_total of them).
  bool rejected_early = false;
  //! The proposed planner's leg counts of this iteration (its trace "legs").
  std::optional<planning::ReuseCounters> legs;
};

struct DesignResult {
  geometry::Scene layout;             //!< the input scene with the best poses
  std::vector<Sequence> sequences;    //!< the M sequences, most likely first
  std::vector<planning::Tour> tours;  //!< tours of the best layout (tours[k] ↔ sequences[k])
  CostTerms initial;                  //!< of the input layout
  //! The scene's preferences met by the input and by the best layout
  //! (optimize/preferences.h, default tolerances).
  PreferenceReport preferences_initial, preferences;
  CostTerms final;                    //!< of the best layout
  bool valid = false;                 //!< the best layout passed every exact check
  int proposals = 0, valid_proposals = 0, accepted = 0;
  bool stopped = false;  //!< interrupted through the stop flag
  double time_total_s = 0.0;
  double time_planning_s = 0.0;  //!< wall time spent planning tours
  //! Wall time of the run's three phases, which sum to time_total_s up to
  //! the report's bookkeeping: the setup (AO sequences, C-space, planners
  //! and their decomposition), the annealing (the first planning of the
  //! input layout, the separation and unblocking before the annealing, and
  //! the planning in it) and the finish (polish, rescue, final checks).
  //! Planning and grid fills (gate_ms) cut across the phases.
  double time_setup_s = 0.0, time_anneal_s = 0.0, time_finish_s = 0.0;
  double t_start = 0.0, t_end = 0.0;
  //! Found tours that recheck_tour() turned to unfound (over all plannings).
  int tours_invalidated = 0;
  int threads = 1;
  //! False when all path weights are 0: then only the initial and the best
  //! layout are toured (the cost does not depend on the tours).
  bool planned_every_iteration = true;
  std::vector<DesignStep> trace;
  //! Early rejection: proposals rejected on a bound and the tours they left
  //! unplanned (or stopped), with an estimate of the planning time saved
  //! (tours skipped × the run's mean planning time per planned tour).
  struct Early {
    int proposals = 0;
    int tours_skipped = 0;
    long legs_skipped = 0;  //!< legs of the skipped tours' sequences
    double saved_s_estimate = 0.0;
  } early;
  int tours_planned = 0;     //!< tours planned to the end (all rounds)
  //! The unblocking before the annealing (docs/optimize.md "Blocked
  //! layouts"): stops walled off from the door before and after, proposals
  //! made and kept (all 0 when nothing was walled off).
  struct Unblock {
    int walled_before = 0, walled_after = 0, proposals = 0, accepted = 0;
    int separated = 0;  //!< objects moved to make an invalid input layout valid
    int separation_passes = 0;  //!< passes over the objects in violation
    //! Why the layout was still not valid after the separation ("" when
    //! it was valid, or was valid from the start).
    std::string left_invalid;
  } unblock;
  //! Moves refused because they would leave a stop without any free goal
  //! pose (docs/optimize.md "Blocked layouts"), counted at each draw.
  int covering_moves = 0;
  //! The opening arrangement of the input layout before the annealing
  //! (PlannerConfig::prefer; docs/optimize.md "Preferences"): whether it
  //! ran and was kept, the input's and the arranged layout's tours found
  //! and total cost (equal when nothing was arranged), its proposals and
  //! time (the tour round not included).
  struct Opening {
    bool ran = false, kept = false;
    int proposals = 0;
    int tours_found_before = 0, tours_found_after = 0;
    double cost_before = 0.0, cost_after = 0.0;
    double ms = 0.0;
  } opening;
  //! The preference arrangement of the annealer's best layout
  //! (optimize/arrange.h): preferences met and tours found before and after,
  //! and whether it was kept (at least the same tours, a lower total cost).
  ArrangeReport arrange;
  //! The final polish (optimize/polish.h): poses planned and kept.
  struct Polish : PolishResult {
    int tours_found_before = 0, met_before = 0;  //!< of the annealer's best layout
  } polish;
  //! The lattice rescue of the final layout's unfound tours
  //! (PlannerConfig::rescue): whether it ran, the tours it found, its time.
  struct Rescue {
    bool ran = false;
    int tours_unfound = 0;  //!< by the best layout when it was unblocked before the polish, else the final one
    int tours_found = 0;    //!< by the lattice
    int unblocked = 0;      //!< by unblocking the walled-off stops again (before the polish, after it)
    double ms = 0.0;
  } rescue;
  long legs_refused = 0;     //!< legs the free grid proved impossible
  std::uint64_t gate_fills = 0;  //!< reachable sets filled (one per layout that needed one)
  double gate_ms = 0.0;          //!< their total time
  bool proposed = false;             //!< planned by the proposed planner
  std::string planner;               //!< the planner configuration's name (PlannerConfig::name)
  std::string reuse;                 //!< its techniques ("none" … "samples,steering,paths,trees")
  planning::ReuseCounters counters;  //!< its leg counts and RRT-iterations histogram
};

//! Why a layout is not valid, or "" when it is: every object inside the room,
//! no two objects overlapping, the door's clear zone free (exact predicates,
//! contact allowed within geometry::kContactTolerance, as in the reader).
std::string layout_violation(const geometry::Scene& scene);
//! The same for object `index` only, against the room, door zone and others.
std::string object_violation(const geometry::Scene& scene, int index);
//! object_violation(scene, index).empty(), the same verdict, quicker where
//! two convex footprints overlap deeply (no amount to report).
bool object_fits(const geometry::Scene& scene, int index);

//! Runs one design. `stop` (may be null) ends the run after the current
//! iteration; `progress` (may be null) is called after every iteration.
//! Set before the first iteration's tours are planned (while the sequences
//! are enumerated or the goal poses generated, both checked in their inner
//! loops), it makes design() throw hrs::Interrupted: there is no design yet.
DesignResult design(const geometry::Scene& scene, const DesignOptions& options,
                    const std::atomic<bool>* stop = nullptr,
                    const std::function<void(const DesignStep&)>& progress = {});

//! A planner-only run over a fixed sequence of layouts.
struct ReplayResult {
  int layouts = 0;
  double planning_s = 0.0;   //!< wall time of planning the M tours of every layout
  double setup_s = 0.0;      //!< building the C-space and planners (the decomposition)
  long tours_total = 0;      //!< tours asked for: layouts × M
  long tours_found = 0;      //!< found tours, summed over the layouts
  double tour_length = 0.0;  //!< their path lengths summed (metres)
  int tours_invalidated = 0;
  planning::ReuseCounters counters;  //!< the proposed planner's
};

//! Plans the M tours of each layout in `layouts` (object poses, e.g. a
//! design run's `layouts_out`) in order, as design() would, with the planner
//! of `options` (baseline or proposed), without annealing: the same planning
//! problems for every planner, so their times and tours compare directly.
ReplayResult replay_planning(const geometry::Scene& scene,
                             const std::vector<std::vector<Pose2>>& layouts,
                             const DesignOptions& options);

//! Seed of tour k in planning round `iteration` (0: the initial layout; round r is
//! the r-th proposal that passed the exact checks, so rejected-before-planning
//! proposals consume no round).
std::uint64_t tour_seed(std::uint64_t seed, int iteration, int tour);

}  // namespace hrs::optimize
