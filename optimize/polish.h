#pragma once
// SPDX-License-Identifier: GPL-3.0-or-later
// The final polish of a design (docs/optimize.md "Preferences"): after the
// annealing, each movable object with an unmet preference is tried at the
// poses that would meet it (optimize/preferences.h, preferred_poses; a
// wall object also turned in place to the heading its nearest wall asks
// for; a pose that does not fit nudged up to 30 cm), one at a time, alone
// or with one relation partner; when none is kept, at up
// to three places along the walls (wall_slides) that score higher, those
// clear of the kept tours' corridor first; when none of those is kept,
// exchanged with another movable object (preferences.h, swaps), up to two
// exchanges that score higher planned (kept only at no higher total
// cost, unless it mends an angle more than 20° off). When the object's
// heading is still more than 20° off, the places that would mend it
// (its preferred poses and wall places, and for an object without a wall
// distance its places round each relation partner, relation_slides; alone
// or with one relation partner at one of its preferred poses) are
// freed: one or two movable objects holding such a place move to their own
// wall places or preferred poses, or to the place the object leaves (an
// eviction; the best four planned, kept at any cost when they score no
// lower; when none keeps the tours, four more not yet planned, among
// equal scores those that come near the fewest of the tours' chair
// footprints first, TourCorridor::blocked, with an allowance of their own).
// A move is kept when the layout
// is valid, every tour found before is still found (the tours are planned
// again) and the preference score rises (an eviction's: does not fall,
// and fewer angles are more than 20° off): preferences met, less one for
// each angle preference more than 20° off.
// Then each group of objects linked by relation angles (heading_groups) with
// an unmet relation angle, or a member with an unmet wall angle, is tried
// turned as one body (group_turns; a wall
// object whose spot is taken slides along the walls that give it the same
// heading, and is also tried at its next places there; a turned member that
// no longer fits is nudged up to 30 cm), the best two placements planned, on
// the same conditions.
// When an angle is still more than 20° off, a rearrangement
// (optimize/rearrange.h): chains of a
// search over the preferences alone (no planning; Metropolis steps that
// take an object with an unmet preference to one of its preferred poses or
// wall places, moving the one or two movable objects that hold the place
// to places of their own) look for a valid layout with fewer such misses
// and a score no lower, near the kept one and clear of its tours'
// corridor; each chain's best is planned (an allowance of its own, one
// planning per chain, not counted against `max_tries`) and the first that
// keeps every tour is kept at any cost. Then, when a preference is still
// unmet, chains with other seeds look for a layout with a higher score and
// no more gross misses (RearrangeGoal::kHigherScore: a sofa whose place by
// the TV two cabinets hold), the objects they move whose heading no
// preference fixes turned square (optimize/squaring.h), planned on a
// second allowance of the same size and kept only at no higher total cost,
// unless it also has fewer gross misses. An eviction
// can also take the object's other relation partners along, moved rigidly
// with it.
// Then each movable object whose heading no preference fixes is turned
// square to its nearest wall, on the same conditions (score not lowered):
// turned in place, or slid along the wall's normal to keep its gap to the
// wall; of the square headings that keep every tour, nearest first, the
// first that costs no more, else the cheapest, at any cost.
// Last, with the plannings left, each object with a preference still unmet
// and no angle grossly off has the places that would meet more freed, as
// in an eviction (the score must rise, with no new gross miss), kept only
// at no higher total cost.
// Last of all, with a tour proxy (PolishHooks::tour_proxy) and every tour
// found, chains look for
// a layout with the same score and a lower proxy
// (RearrangeGoal::kShorterTours); each chain's best is planned and the
// first whose tours are all found at a lower total cost is kept, which
// starts one more round (two at most, each with its own allowance).
// The order is fixed (objects ascending, candidates in preferred_poses
// order) and the chains are seeded (PolishHooks::seed), so the result is a
// function of the layout and the seeds, whatever the thread count.

#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

#include "geometry/pose.h"
#include "geometry/scene.h"
#include "optimize/costs.h"
#include "planning/tour_types.h"

namespace hrs::optimize {

struct PolishHooks {
  //! Exact validity of `poses` after moving object `moved`. The rule that
  //! no stop is left without a free goal pose must judge every object whose
  //! pose differs from the layout polish() started from, not only `moved`:
  //! the rearrangement asks once per step that moves several.
  std::function<bool(const std::vector<geometry::Pose2>& poses, int moved)> valid;
  //! The geometric part of `valid` alone (inside, no overlap, door clear),
  //! cheaper; the rearrangement's search asks it on every step, and `valid`
  //! once per accepted step. Unset: `valid`.
  std::function<bool(const std::vector<geometry::Pose2>& poses, int moved)> fits;
  //! Moves object `object` to `to` (C-space included).
  std::function<void(int object, const geometry::Pose2& to)> place;
  //! Plans the tours of the layout `poses` (placed) and returns its terms.
  std::function<CostTerms(const std::vector<geometry::Pose2>& poses)> plan;
  //! The pose tried last was kept: snapshot its tours.
  std::function<void()> kept;
  //! The tours of the layout kept last (may be unset): the places along the
  //! walls that stay clear of their corridor are tried first.
  std::function<const std::vector<planning::Tour>&()> tours;
  //! The tour proxy of a layout (optimize/tour_proxy.h); unset, the
  //! shorter-tour rearrangement does not run.
  std::function<double(const std::vector<geometry::Pose2>& poses)> tour_proxy;
  //! Seeds the rearrangement's chains (one output for a seed).
  std::uint64_t seed = 0;
};

struct PolishResult {
  int tried = 0;  //!< poses planned
  int kept = 0;   //!< poses kept that meet more preferences
  int slid = 0;     //!< of `kept`, poses found sliding along a wall
  int swapped = 0;  //!< of `kept`, exchanges of two objects' places
  int evicted = 0;  //!< of `kept`, a held place freed by moving its holder
  int turned = 0;   //!< heading groups turned as one body (group_turns)
  int rearranged = 0;  //!< of `kept`, rearrangements found over the preferences alone
  int squared = 0;  //!< objects turned square to their wall (no heading preference)
  int shortened = 0;  //!< of `kept`, a shorter-tour rearrangement (RearrangeGoal::kShorterTours)
};

//! Polishes `poses` (the best layout, whose terms are `terms`) in place;
//! at most `max_tries` plannings, plus the allowances of their own: each
//! rearrangement goal's (one planning per chain, eight each; the shorter
//! tours' eight per round) and a gross miss's second round of evictions
//! (four); `stop` (may be null) ends it early.
PolishResult polish(const geometry::Scene& scene, const CostModel& model,
                    const std::vector<bool>& movable, std::vector<geometry::Pose2>& poses,
                    CostTerms& terms, const PolishHooks& hooks, int max_tries,
                    const std::atomic<bool>* stop = nullptr);

}  // namespace hrs::optimize
