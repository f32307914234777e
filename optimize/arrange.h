#pragma once
// SPDX-License-Identifier: GPL-3.0-or-later
// The preference arrangement of a design (beyond the paper; docs/optimize.md
// "Preferences"): after the tour annealing, a long and cheap annealing of
// the interior cost alone — no tour is planned — rearranges the best layout
// toward the scene's preferences (walls, relations) while every object stays
// valid and clear of the corridor that the found tours drive through
// (TourCorridor). The design loop then tours the arranged layout once and
// keeps it when it finds at least the same tours at a lower total cost.
//
// Why: a preference layout is a packing problem (a bed, two wardrobes and a
// sofa each want a wall slot of their own, the TV the spot across from the
// sofa). The tour annealing has a few hundred proposals, each planned, and
// finds such packings only in small rooms; the interior cost alone costs
// microseconds, so thousands of proposals fit in a fraction of one tour
// round. The corridor keeps the found paths collision-free (up to its
// sampling, which the final tour round certifies), so the search does not
// trade tours away. It uses the same annealer, moves and preference moves
// (optimize/annealer.h), so it is seeded, deterministic and valid at every
// step.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <random>
#include <vector>

#include "geometry/pose.h"
#include "geometry/scene.h"
#include "optimize/annealer.h"
#include "optimize/costs.h"
#include "planning/tour_types.h"

namespace hrs::optimize {

//! The chair's footprints at every waypoint of the found tours, bucketed on
//! a uniform grid: clear() tells whether an object footprint keeps `margin`
//! from all of them (separating axes on convex hulls; the margin covers the
//! motion between waypoints, planning::kWaypointStep apart).
class TourCorridor {
 public:
  TourCorridor(const geometry::Wheelchair& chair, const std::vector<planning::Tour>& tours,
               double margin = 0.05, double cell = 0.25);
  bool clear(const geometry::Polygon& footprint) const;
  //! How many of the chair's footprints along the tours `footprint` comes
  //! within the margin of (0 exactly when clear()): a graded clear(), the
  //! fewer the likelier a move keeps the tours.
  std::size_t blocked(const geometry::Polygon& footprint) const;
  std::size_t footprints() const { return shapes_.size(); }

 private:
  //! How many chair footprints `footprint` comes within the margin of,
  //! counting stopped at `limit`.
  std::size_t near(const geometry::Polygon& footprint, std::size_t limit) const;

  std::vector<geometry::Polygon> shapes_;  //!< chair footprints (convex)
  std::vector<geometry::Box> boxes_;
  std::vector<std::vector<int>> cells_;    //!< shape indices per grid cell
  double margin_, cell_;
  double x0_ = 0.0, y0_ = 0.0;
  int nx_ = 0, ny_ = 0;
};

struct ArrangeHooks {
  //! Exact validity of `poses` after moving object `moved`, with the other
  //! objects where the last set() put them. Required.
  std::function<bool(const std::vector<geometry::Pose2>& poses, int moved)> valid;
  //! Object `object` is now at `to` for valid()'s purposes (the design moves
  //! it in its C-space too, so that valid()'s covered-stop rule sees it).
  std::function<void(int object, const geometry::Pose2& to)> set;
  //! A preference move (AnnealCallbacks::preferred); may be unset.
  std::function<std::optional<geometry::Pose2>(const std::vector<geometry::Pose2>& poses,
                                               int object, std::mt19937_64& rng)>
      preferred;
};

struct ArrangeOptions {
  //! Proposals per movable object (the cost is microseconds a proposal).
  int iterations_per_object = 300;
  //! t_start = this × the input's interior cost; cooling to t_start × t_end_ratio.
  double t_start_fraction = 0.3;
  double t_end_ratio = 1e-4;
  //! Added to the interior cost of every proposal (may be unset): an energy
  //! of the arrangement only, not a cost of the design (opening_pull()).
  std::function<double(const std::vector<geometry::Pose2>& poses)> extra;
};

//! The opening arrangement's pull, per metre between an object's footprint
//! and its nearest wall, on each movable object without a wall distance
//! preference, counted up to 1 m: at most an eighth of one unmet preference
//! (kPreferencePenalty), so that no preference is given up for it.
inline constexpr double kOpeningPull = 0.25;

//! The energy that draws the movable objects without a wall distance
//! preference to the walls (kOpeningPull · min(1 m, distance to the
//! nearest wall) each): free-standing furniture against the walls leaves
//! the room's middle to the wheelchair's manoeuvres. Interior-design
//! systems place such pieces by a prior on their distance to the nearest
//! wall (Yu et al., "Make it Home", SIGGRAPH 2011, §4.1); this is the
//! simplest such prior. Empty when no object is concerned.
std::function<double(const std::vector<geometry::Pose2>& poses)> opening_pull(
    const geometry::Scene& scene, const CostModel& model, const std::vector<bool>& movable);

//! The opening arrangement's work bound: proposals per movable object
//! times the footprints' vertices in the scene (300 × 256).
inline constexpr std::size_t kOpeningWork = 300 * 256;
//! The opening arrangement's proposals per movable object: the
//! arrangement's 300 while 300 times the scene's footprint vertices stays
//! within kOpeningWork (64 box footprints), else kOpeningWork over the
//! vertices (0: no opening). Every check of a proposal is linear in the
//! footprints' vertices and moves the C-space; at the format's limits (100
//! objects of 1000 vertices) 300 proposals an object would outlast the
//! design's first iteration many times over.
int opening_proposals_per_object(const geometry::Scene& scene);

struct ArrangeResult {
  std::vector<geometry::Pose2> poses;  //!< the best valid layout seen (the input if none)
  double interior_before = 0.0;        //!< interior cost (weighted) of the input
  double interior_after = 0.0;         //!< of `poses`
  int proposals = 0;
  int accepted = 0;
};

//! Anneals the interior cost of `poses` (objects with movable[i] false stay);
//! `moves` supplies the move kinds and the jump bounds (its temperatures and
//! iterations are replaced). The hooks' set() state is back at `poses` on
//! return. Deterministic in `seed`.
ArrangeResult arrange(const CostModel& model, const std::vector<bool>& movable,
                      const std::vector<geometry::Pose2>& poses, const AnnealOptions& moves,
                      const ArrangeOptions& options, const ArrangeHooks& hooks,
                      std::uint64_t seed, const std::atomic<bool>* stop = nullptr);

//! Rounds of arrange_toured() a design runs at most: each starts from the
//! last kept one, with the corridor of its re-planned tours, and a round
//! that is not kept ends them.
inline constexpr int kArrangeRounds = 3;

//! What arrange_toured() needs beyond ArrangeHooks.
struct ToursHooks {
  //! Moves object `object` to `to` (C-space included).
  std::function<void(int object, const geometry::Pose2& to)> place;
  //! Tours the placed layout `poses` and returns its terms.
  std::function<CostTerms(const std::vector<geometry::Pose2>& poses)> plan;
};

//! What arrange_toured() did (report.json `arrange`).
struct ArrangeReport {
  bool kept = false;  //!< a round was kept
  int rounds = 0, rounds_kept = 0;
  int proposals = 0;
  //! Preferences met and tours found before the first round and in the
  //! layout kept last (the input's when none was kept).
  int met_before = 0, met_after = 0;
  int tours_found_before = 0, tours_found_after = 0;
  double ms = 0.0;  //!< the annealings' time (the tour rounds not included)
  //! Adds round `r` (the first when `first`) to this summary.
  void add(const ArrangeReport& r, bool first) {
    if (first) {
      met_before = met_after = r.met_before;
      tours_found_before = tours_found_after = r.tours_found_before;
    }
    ++rounds;
    proposals += r.proposals;
    ms += r.ms;
    if (!r.kept) return;
    kept = true;
    ++rounds_kept;
    met_after = r.met_after;
    tours_found_after = r.tours_found_after;
  }
};

//! The arrangement of a toured layout `poses` (placed; its terms `terms`,
//! its tours `tours`): the stops of the found tours stay (their goal poses
//! move with them, and the path to them would be lost), every move keeps
//! clear of the found tours' corridor, and the arranged layout is toured
//! once and kept (`poses`, `terms` updated; else placed back) when it finds
//! at least as many tours at a lower total cost.
ArrangeReport arrange_toured(const geometry::Scene& scene, const CostModel& model,
                             const std::vector<bool>& movable,
                             const std::vector<planning::Tour>& tours,
                             std::vector<geometry::Pose2>& poses, CostTerms& terms,
                             const AnnealOptions& moves, const ArrangeHooks& hooks,
                             const ToursHooks& toured, std::uint64_t seed,
                             const std::atomic<bool>* stop = nullptr);

}  // namespace hrs::optimize
