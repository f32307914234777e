// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Refusing impossible legs once their RRT has run a while, and measuring how
// blocked a layout is (beyond the paper; docs/optimize.md "Refused legs",
// docs/optimize.md "Blocked layouts"). The annealer's proposals often wall
// an object, or the door itself, off from the rest of the room; the RRT of
// §III-B then spends its whole iteration budget on every leg into the
// walled-off part, and the cost cannot tell a nearly open layout from a
// sealed one.
//
// The gate keeps a geometry::FreeGrid (a certified outer approximation of
// the free poses) in step with the C-space's layout and fills, once per
// layout and only when first asked, the set of cells the door's start pose
// reaches (geometry::ReachableSet). A leg with one end inside that set and
// the other outside is joined by no collision-free motion of any vehicle:
// it is refused (the planners ask after kRefuseAfter RRT iterations, so
// that layouts whose legs are all found soon need no fill). A leg with both
// ends outside is never refused (the grid says nothing about it). Every tour
// leaves from the door, so in practice every leg's start is inside the set.
//
// Thread-safety: invalidate() between planning rounds only; the queries are
// const and thread-safe (the first one fills the set under a lock; later
// ones read it).

#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include "geometry/cspace.h"
#include "geometry/free_grid.h"
#include "geometry/pose.h"
#include "geometry/scene.h"
#include "planning/goals.h"

namespace hrs::planning {

struct ReachGateOptions {
  //! Largest cell side, metres, and heading slices (at most 64: the fill
  //! works on one 64-bit word per column). 2.5 cm and 64 slices keep the
  //! certified margin at about 5 cm for the shipped chair.
  geometry::FreeGridOptions grid{0.025, 64};
};

class ReachGate {
 public:
  //! `scene` gives the room, the chair and the door; `cspace` the current
  //! object poses (read at the first query after invalidate()). Both must
  //! outlive the gate.
  ReachGate(const geometry::Scene& scene, const geometry::CSpace& cspace,
            ReachGateOptions options = {});
  ~ReachGate();

  //! The layout changed: the next query brings the grid to it.
  void invalidate();
  //! True when no collision-free motion joins `from` and `to` (certified).
  bool refuses(const geometry::Pose2& from, const geometry::Pose2& to) const;
  //! The cells the door reaches in the current layout; null when the grid
  //! cannot be built for this chair (cells too coarse) or the door's start
  //! pose is not free.
  const geometry::ReachableSet* door_reach() const;

  //! How walled off from the door a stop with goal poses `goals` is, in
  //! [0, 1] (the grade b of optimize/costs.h): 0 when the door reaches one
  //! of them; else 1/2 + 1/2 · min(1, d / D), d the distance from the nearest
  //! goal pose to the door's reachable region (ReachableSet::distance_to)
  //! and D the diagonal of the room's bounding box; 1 when no goal pose is
  //! free or the grid is unavailable.
  double blockage(std::span<const GoalPose> goals) const;
  //! True when no tour can reach a stop with free goal poses `goals`
  //! (certified): there are none, or the door's start is free and reaches
  //! none of them in the grid. False when unknown (grid unavailable).
  bool walls_off(std::span<const GoalPose> goals) const;

  //! Objects whose footprint comes within `within` metres (in the plane) of
  //! the door's reachable region: the walls of the door's pocket when the
  //! layout is blocked. Index order; empty when the grid is unavailable.
  std::vector<int> bordering(double within) const;

  //! Fills run and their total time (ms), for reports.
  std::uint64_t fills() const;
  double fill_ms() const;

 private:
  const geometry::Scene* scene_;
  const geometry::CSpace* cspace_;
  ReachGateOptions options_;
  geometry::Pose2 door_;
  double diagonal_ = 1.0;
  mutable std::mutex mutex_;  //!< guards everything below
  mutable std::unique_ptr<geometry::FreeGrid> grid_;
  mutable geometry::ReachableSet reach_;
  mutable bool current_ = false;
  mutable bool unavailable_ = false;
  mutable std::uint64_t fills_ = 0;
  mutable double fill_ms_ = 0.0;
};

}  // namespace hrs::planning
