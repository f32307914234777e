// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Infeasibility proofs for legs (beyond the paper; the proposed planner's
// opt-in `proofs` technique): geometry::FreeGrid certifies an outer
// approximation of the free C-space, so two poses in different components of
// it are joined by no motion at all. The oracle owns the grid, brings it to
// the current layout once per iteration, and keeps one reachability search
// per thread that asks (its own lock, so tours ask in parallel).
//
// Not ReachGate's grid, on purpose. The gate's fill works on one 64-bit word
// per column, so its grid has at most 64 heading slices; the oracle's search
// takes any count and uses 144 by default. Its cores are shrunk by
// R·Δ/2 + d/2 + 1 mm (geometry/free_grid.h): about 3.3 cm for the shipped
// chair at 144 slices against 5 cm at 64, so it blocks more cells and
// separates tighter pockets. On the gate's own grid the oracle would also
// prove almost nothing new: when the gate is on (it is optional), a leg
// with one end in the door's component of that grid and one outside is
// refused once its RRT has run 300 iterations, one with both ends in it is
// connected there, and every tour's legs start in it.

#include <cstddef>
#include <memory>
#include <mutex>
#include <vector>

#include "geometry/cspace.h"
#include "geometry/free_grid.h"
#include "geometry/pose.h"
#include "geometry/scene.h"

namespace hrs::planning {

class ProofOracle {
 public:
  //! `cspace` holds the current layout; the grid is built on the first proof
  //! with cells of `grid`, and a search may visit at most `max_cells`.
  ProofOracle(const geometry::Scene& scene, const geometry::CSpace& cspace,
              geometry::FreeGridOptions grid, std::size_t max_cells);
  ~ProofOracle();

  //! The layout changed: the grid is moved to it before the next proof.
  void invalidate();
  //! True when no motion joins `from` and `to` in the current layout
  //! (false: not proven, also when the grid's cells are too coarse for the
  //! chair). Thread-safe.
  bool disconnected(const geometry::Pose2& from, const geometry::Pose2& to) const;

 private:
  const geometry::Scene* scene_;
  const geometry::CSpace* cspace_;
  geometry::FreeGridOptions grid_options_;
  std::size_t max_cells_;
  mutable std::mutex mutex_;  //!< guards everything below
  mutable std::unique_ptr<geometry::FreeGrid> grid_;
  mutable bool current_ = false;
  mutable bool unavailable_ = false;
  mutable std::vector<std::unique_ptr<geometry::ReachabilityQuery>> idle_;
};

}  // namespace hrs::planning
