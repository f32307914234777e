#pragma once
// SPDX-License-Identifier: GPL-3.0-or-later
// Rearrangements: the polish's search over the preferences alone, for
// angles still grossly off once no single move mends them, and then for any
// preference still unmet (docs/optimize.md "Preferences"). A bed that holds
// the only wall a desk can share with its wardrobe has to move to another
// wall, and the dresser that stands by the bed has to follow it: moves that
// raise the score only together, which no one- or two-object move of the
// polish finds.
//
// Each chain is a Metropolis walk (Metropolis et al. 1953, the acceptance
// rule min(1, exp(-dE/T))) over valid layouts, with a geometric cooling
// schedule. A step takes one object with an unmet preference (or, one step
// in four, any movable object) to one of its preferred poses or wall places
// (half the draws from each list: an object has a handful of preferred
// poses against about a hundred wall places; an object without a wall
// distance has its places round its relation partners instead, and one
// with neither a uniform position within 1 m of where it stands), moving the
// one or two movable objects that hold the place to places of their own. Its energy is
//   E = -score + gross + 0.05 * (metres moved) + 0.5 * (moved objects in the
//       kept tours' corridor),
// score and gross as below (kShorterTours adds the tour proxy over
// kPreferencePenalty, and draws any movable object). Nothing is planned:
// the chains return their best layouts, and the polish plans them.

#include <atomic>
#include <cstdint>
#include <functional>
#include <numbers>
#include <vector>

#include "geometry/pose.h"
#include "geometry/scene.h"
#include "optimize/costs.h"
#include "optimize/preferences.h"

namespace hrs::optimize {

//! A heading this far off its preference (radians, 20°) is a gross miss:
//! a bed turned sideways, a TV facing away.
inline constexpr double kGrossAngle = 20.0 * std::numbers::pi / 180.0;

//! The number of angle preferences of `r` more than kGrossAngle off.
int gross_misses(const PreferenceReport& r);

//! What the polish increases: preferences met, less one for every angle
//! preference grossly missed. A layout that meets an angle at the price of
//! a distance is better (a designer sees a wrong heading at a glance); one
//! that meets a distance at the price of a gross angle is not.
int polish_score(const PreferenceReport& r);

//! The other objects whose footprints `object`'s overlaps at `poses`
//! (beyond contact), ascending; at most three are listed.
std::vector<int> holders(const geometry::Scene& scene, const std::vector<geometry::Pose2>& poses,
                         int object);

//! What a rearrangement needs from the design.
struct RearrangeHooks {
  //! The geometric checks of `poses` after moving `moved` (inside, no
  //! overlap, door clear), asked on every step.
  std::function<bool(const std::vector<geometry::Pose2>& poses, int moved)> fits;
  //! The full checks (`fits` and no stop left without a free goal pose),
  //! asked once per accepted step, with one of the objects it moved; the
  //! stop rule must judge every object whose pose differs from the layout
  //! searched from, not only `moved`.
  std::function<bool(const std::vector<geometry::Pose2>& poses, int moved)> valid;
  //! Whether object `object` at `to` stays clear of the kept tours' corridor.
  std::function<bool(int object, const geometry::Pose2& to)> clear;
  //! The tour proxy of a layout (optimize/tour_proxy.h); kShorterTours
  //! runs only when it is set.
  std::function<double(const std::vector<geometry::Pose2>& poses)> tour_proxy;
  //! Seeds the chains (one output for a seed).
  std::uint64_t seed = 0;
};

//! What a chain's best layout must achieve against the layout searched from.
enum class RearrangeGoal {
  //! Fewer angles grossly off, at a score no lower (kept at any cost).
  kFewerGross,
  //! A higher score, with no more angles grossly off (kept only at no
  //! higher total cost): the misses no one- to three-object move of the
  //! polish mends, a distance among them.
  kHigherScore,
  //! A lower tour proxy (RearrangeHooks::tour_proxy) by more than
  //! kProxyMargin of it, at a score no lower and no more angles grossly
  //! off (kept only at a lower total cost, every tour found): a layout at
  //! least as good on preferences whose stops lie closer along the likely
  //! tours.
  kShorterTours,
};

//! kShorterTours' energy weighs the tour proxy (in units of the total
//! cost) by this: a preference term costs at most kPreferencePenalty in
//! the total cost, and one preference in the chains' energy.
inline constexpr double kProxyWeight = 1.0 / kPreferencePenalty;
//! kShorterTours' layouts lower the proxy by more than this share of it.
inline constexpr double kProxyMargin = 0.01;

//! One chain's best layout: the moves from the layout searched from, its
//! preference report and its energy.
struct Rearrangement {
  double energy = 0.0;
  double proxy = 0.0;  //!< the tour proxy (kShorterTours only; else 0)
  PreferenceReport report;
  GroupMove move;
};

//! Runs the chains from `poses` (whose preference report is `report`) and
//! returns each chain's best layout that meets `goal`, distinct ones only,
//! lowest energy first; each goal seeds its chains apart. kHigherScore's
//! and kShorterTours' chains draw square headings for the movable objects
//! whose heading no preference fixes and square those they moved before
//! returning (squaring.h); empty when `report` has nothing to mend (no
//! gross miss for kFewerGross, no unmet preference for kHigherScore) or,
//! for kShorterTours, without a tour proxy. `stop` (may be null) ends the
//! chains early.
std::vector<Rearrangement> rearrangements(const geometry::Scene& scene, const CostModel& model,
                                          const std::vector<bool>& movable,
                                          const std::vector<geometry::Pose2>& poses,
                                          const PreferenceReport& report,
                                          const RearrangeHooks& hooks,
                                          const std::atomic<bool>* stop = nullptr,
                                          RearrangeGoal goal = RearrangeGoal::kFewerGross);

}  // namespace hrs::optimize
