// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Simulated annealing over object poses (paper §III-E): Metropolis acceptance
// min(1, exp(−ΔC/t)) under geometric cooling; a move translates one movable
// object (step shrinking geometrically with the temperature) or rotates it
// (a quarter/half turn, or a small turn that also shrinks); while hot, some
// translations jump anywhere in a given box. A move that the
// caller's exact validity test rejects is never evaluated. The best layout
// seen among fully valid layouts is kept.
//
// The annealer knows nothing about wheelchairs: costs, validity and undo are
// callbacks, so it is tested on toy costs (tests/optimize/annealer_test.cpp)
// and driven by optimize/design.h for real layouts. Randomness comes from the
// seeded engine passed in; the order of draws is fixed, so a run is a
// function of (seed, callbacks).

#include <array>
#include <atomic>
#include <functional>
#include <optional>
#include <random>
#include <vector>

#include "geometry/pose.h"

namespace hrs::optimize {

using geometry::Pose2;

struct AnnealOptions {
  int iterations = 700;                   //!< proposals (paper §VI: 700)
  double t_start = 1.0;                   //!< temperature of the first iteration, cost units
  double t_end = 1e-3;                    //!< temperature of the last iteration
  double step_start = 1.0;                //!< largest translation at t_start, metres (per axis)
  double step_end = 0.02;                 //!< largest translation at t_end, metres
  double rotate_probability = 0.3;        //!< share of moves that rotate
  double quarter_turn_probability = 0.5;  //!< share of rotations by ±π/2 or π
  //! Box [xmin, ymin, xmax, ymax] for jump moves; none: translations only step.
  std::optional<std::array<double, 4>> bounds;
  //! Share of translations that jump to a uniform position in `bounds` at
  //! t_start; it shrinks with the step (geometrically to step_end/step_start).
  double jump_probability = 0.2;
  //! A jump also turns the object by a uniform multiple of π/2, and is
  //! redrawn (position and turn) until the exact validity test passes, at
  //! most this many draws in all: a large object in a crowded room is
  //! seldom valid at a uniform position, and a jump that is never valid
  //! cannot carry it out of a place that blocks the room (docs/optimize.md
  //! "Blocked layouts"). 1: a single draw.
  int jump_attempts = 25;
  //! Share of proposals that move one of the callbacks' focus objects
  //! (AnnealCallbacks::focus) when there are any; half of those moves are
  //! jumps (whatever the temperature) with up to focus_jump_attempts draws:
  //! an object that walls the door in is often wedged, so that only a
  //! relocation frees it.
  double focus_probability = 0.5;
  int focus_jump_attempts = 200;
  //! Share of proposals drawn from AnnealCallbacks::preferred when it is set
  //! (a pose that meets one of the object's preferences), redrawn until
  //! valid at most preference_attempts times; when none is valid the
  //! iteration proposes an ordinary move instead.
  double preference_probability = 0.25;
  int preference_attempts = 8;
};

//! One proposed move of one object.
struct Move {
  int object = -1;  //!< index into the poses; -1 for the initial evaluation
  Pose2 from, to;
  bool rotation = false;
  bool jump = false;  //!< a translation to a uniform position in the bounds
  bool preference = false;  //!< drawn from AnnealCallbacks::preferred
};

//! What happened in one iteration (for reports).
struct TraceEntry {
  int iteration = 0;
  double temperature = 0.0;
  int object = -1;
  bool rotation = false;
  bool jump = false;
  bool preference = false;     //!< a preference move (AnnealCallbacks::preferred)
  bool valid = false;          //!< passed the exact validity test
  double proposed_cost = 0.0;  //!< NaN when not valid (never evaluated)
  bool accepted = false;
  double current_cost = 0.0;  //!< after the decision
  double best_cost = 0.0;     //!< best valid cost so far (inf if none yet)
};

struct AnnealResult {
  std::vector<Pose2> best;  //!< best fully valid layout (initial if none)
  double best_cost = 0.0;   //!< its cost (inf if no valid layout was seen)
  bool best_valid = false;  //!< a fully valid layout was seen
  double initial_cost = 0.0;
  std::vector<Pose2> final_poses;  //!< the chain's last state
  double final_cost = 0.0;
  int proposals = 0;        //!< iterations run
  int valid_proposals = 0;  //!< proposals that were evaluated
  int accepted = 0;         //!< accepted proposals
  bool stopped = false;     //!< interrupted through the stop flag
  std::vector<TraceEntry> trace;
};

//! The Metropolis decision a proposal faces, known before it is costed (the
//! uniform is drawn first): lets the cost stop early once a lower bound of
//! the proposal's cost is already rejected (docs/optimize.md "Early
//! rejection").
struct Acceptance {
  bool active = false;  //!< false for the initial evaluation: nothing is decided
  double current = 0.0;
  double temperature = 0.0;
  double u = 0.0;
  //! True when every cost >= `lower_bound` is rejected. Exact: it decides
  //! on lower_bound less a relative 1e-9 (far above the rounding of the
  //! cost's sums), and the acceptance probability falls with the cost, so a
  //! full evaluation would reject too.
  bool rejects(double lower_bound) const;
};

struct AnnealCallbacks {
  //! Exact validity of the layout after moving object `moved` (only that
  //! object's constraints need checking). Required.
  std::function<bool(const std::vector<Pose2>& poses, int moved)> move_valid;
  //! Cost of the layout; `move` is what changed since the last call that was
  //! not reverted (object -1: the initial layout). It may return a lower
  //! bound b of the cost instead when acceptance.rejects(b). Required.
  std::function<double(const std::vector<Pose2>& poses, const Move& move,
                       const Acceptance& acceptance)>
      cost;
  //! A move was evaluated and rejected: the caller restores its own state.
  std::function<void(const Move& move)> rejected;
  //! Whole-layout validity for the best-layout bookkeeping (default: valid).
  std::function<bool(const std::vector<Pose2>& poses)> layout_valid;
  //! The current layout just became the best one (snapshot side data).
  std::function<void()> new_best;
  //! Called after every iteration.
  std::function<void(const TraceEntry& entry)> progress;
  //! Objects the next proposal should rather move (movable indices; empty or
  //! unset: none): with focus_probability the moved object is drawn from
  //! them instead of from all movable objects. Beyond the paper: the design
  //! runner names the objects that wall the door in (docs/optimize.md).
  std::function<std::vector<int>()> focus;
  //! A pose of `object` that meets one of its preferences (interior design
  //! moves: against a wall, in a wall slot, aligned with a relation
  //! partner), drawn with `rng`; nullopt when it has none. Unset: never
  //! asked, and the annealer draws exactly as without it.
  std::function<std::optional<Pose2>(const std::vector<Pose2>& poses, int object,
                                     std::mt19937_64& rng)>
      preferred;
};

//! min(1, exp(−delta/t)); 1 for delta <= 0, 0 for t <= 0 and delta > 0.
double acceptance_probability(double delta, double t);
//! The Metropolis decision for a uniform draw u in [0, 1): u < probability.
bool metropolis_accept(double delta, double t, double u);
//! Temperature of iteration k of n under geometric cooling from t_start to t_end.
double temperature_at(const AnnealOptions& options, int k);

//! Anneals `poses`; objects with movable[i] == false never move. `stop` (may
//! be null) ends the run after the current iteration.
AnnealResult anneal(std::vector<Pose2> poses, const std::vector<bool>& movable,
                    const AnnealOptions& options, const AnnealCallbacks& callbacks,
                    std::mt19937_64& rng, const std::atomic<bool>* stop = nullptr);

}  // namespace hrs::optimize
