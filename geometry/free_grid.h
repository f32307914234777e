// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A certified outer approximation of the free configuration space, for
// proving that a leg cannot be planned (beyond the paper: the annealer's
// blocking proposals make the RRT of §III-B spend its whole iteration budget
// on legs that have no solution; see docs/planner.md "Infeasibility proofs").
//
// The pose space (room box × heading circle) is cut into cells: an nx × ny
// grid of at most `cell` metres over the room's bounding box, times K heading
// slices. A cell is *blocked* only if every pose in it collides. The test uses
// a "core": the chair's rectangle shrunk on every side by
//   m = R·Δ/2 + d/2 + ε,
// placed at the cell's centre and mid heading, where R is the chair's
// half-diagonal, Δ the slice width, d the cell's diagonal and ε = 1 mm. A pose
// q in the cell differs from the centre by at most Δ/2 in heading and d/2 in
// position, so each point of the chair at the centre moves by at most
// R·Δ/2 + d/2 (a rotation by φ moves a point at radius r by 2r·sin(φ/2) <= rφ):
// the core at the centre lies inside the chair at every q. If the core's
// interior meets an obstacle's interior (furniture, or the outside of the
// room), every pose in the cell collides. Cores are rasterized per slice as
// C-obstacles A ⊕ (−core), convex, by horizontal scanlines through the cell
// centres; the ε of slack absorbs the (sub-picometre) rounding of these
// constructions, so "blocked" is certified while "not blocked" may be
// conservative.
//
// A path of free poses is continuous, so it crosses only cells that are not
// blocked, from each to one of its 26 neighbours (θ wraps). If the start's and
// the goal's cells are in different components of the unblocked cells, no
// collision-free motion at all joins them, for any car or planner.
//
// Moving an object updates counts per cell (how many C-obstacle pieces cover
// its centre) for that object only. Thread-safety: const members may be
// called concurrently; a ReachabilityQuery holds the per-thread scratch.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/pose.h"
#include "geometry/scene.h"

namespace hrs::geometry {

struct FreeGridOptions {
  double cell = 0.025;  //!< largest cell side, metres
  int slices = 144;     //!< heading slices over the full circle
};

class FreeGrid {
 public:
  //! The grid for the scene's room, chair and object poses. Throws
  //! std::invalid_argument when the cells are too coarse for the chair (the
  //! core would vanish) or the grid would exceed 64 M cells.
  explicit FreeGrid(const Scene& scene, FreeGridOptions options = {});

  //! Moves object `index` to `pose`: its old cover is removed, its new added.
  void move_object(int index, const Pose2& pose);
  const Pose2& object_pose(int index) const { return objects_[index].pose; }
  int object_count() const { return static_cast<int>(objects_.size()); }

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  int slices() const { return slices_; }
  std::size_t cell_count() const { return counts_.size(); }
  //! Shrink of the core on each side (m above), metres.
  double core_margin() const { return margin_; }

  //! Linear index of (ix, iy, k); k is the slice (fastest), then x, then y.
  std::size_t index(int ix, int iy, int k) const {
    return (static_cast<std::size_t>(iy) * nx_ + ix) * slices_ + k;
  }
  //! The inverse of index().
  void coords(std::size_t cell, int& ix, int& iy, int& k) const {
    k = static_cast<int>(cell % slices_);
    const std::size_t xy = cell / slices_;
    ix = static_cast<int>(xy % nx_), iy = static_cast<int>(xy / nx_);
  }
  //! The cell holding `pose` (clamped to the grid: poses whose centre is
  //! outside the room's box are never free anyway).
  std::size_t cell_of(const Pose2& pose) const;
  //! True if every pose in the cell certainly collides.
  bool blocked(std::size_t cell) const { return counts_[cell] != 0; }
  //! The cell's centre position and mid heading.
  Pose2 centre(std::size_t cell) const;
  //! Cell sizes (metres) and slice width (radians).
  double hx() const { return hx_; }
  double hy() const { return hy_; }
  double slice_width() const { return dtheta_; }
  //! Number of blocked cells (for reports and tests).
  std::size_t blocked_count() const;
  //! With at most 64 slices: bit k of column (ix, iy) is set when cell
  //! (ix, iy, k) is not blocked (kept up to date by move_object()).
  bool has_column_masks() const { return !free_mask_.empty(); }
  std::uint64_t free_slices(std::size_t column) const { return free_mask_[column]; }
  std::size_t column_of(const Pose2& pose) const { return cell_of(pose) / slices_; }

 private:
  struct ObjectState {
    Pose2 pose;
    std::vector<Polygon> local_pieces;  //!< convex pieces, object frame
  };
  //! Adds `delta` to every cell of slice k whose centre lies in A ⊕ (−core_k).
  void rasterize(const Polygon& piece, int k, int delta);
  void cover_object(int index, int delta);

  int nx_ = 0, ny_ = 0, slices_ = 0;
  double xmin_ = 0, ymin_ = 0, hx_ = 0, hy_ = 0, dtheta_ = 0;
  double margin_ = 0;
  std::vector<std::array<Vec2, 4>> cores_;  //!< per slice: the core's corners, rotated
  std::vector<ObjectState> objects_;
  std::vector<std::uint16_t> counts_;
  std::vector<std::uint64_t> free_mask_;  //!< per column (iy·nx + ix), slices <= 64 only
};

//! Every cell joined to one start cell by unblocked cells (26-neighbours, as
//! ReachabilityQuery): a certified outer approximation of the poses any
//! collision-free motion from the start can reach. Needs a grid with at
//! most 64 slices; the fill works on whole columns of slices at once (one
//! 64-bit mask per (x, y) column), so a room-sized fill takes about a
//! millisecond. Beyond the paper: the tours' refusal of impossible legs and
//! the annealer's escape from blocked layouts (docs/optimize.md).
class ReachableSet {
 public:
  //! Fills from `start` (a free pose). Empty when its cell is blocked.
  void fill(const FreeGrid& grid, const Pose2& start);
  //! True when `pose`'s cell was reached.
  bool contains(const Pose2& pose) const;
  //! True when some slice of the column holding `pose` was reached.
  bool column_reached(const Pose2& pose) const;
  //! Distance (metres, 8-neighbour chamfer over the columns, through blocked
  //! columns too) from `pose`'s column to the nearest reached column; 0 on a
  //! reached column, +inf when nothing was reached.
  double distance_to(const Pose2& pose) const;
  //! Reached columns / all columns.
  double column_share() const;

 private:
  const FreeGrid* grid_ = nullptr;
  std::vector<std::uint64_t> reached_;  //!< per column: reached slices
  std::vector<std::uint32_t> queue_;
  std::size_t reached_columns_ = 0;
  std::vector<double> distance_;  //!< per column, see distance_to()
  void chamfer();
};

//! Bidirectional search of the unblocked cells between two poses' cells;
//! holds the scratch, one per thread.
class ReachabilityQuery {
 public:
  enum class Answer {
    kDisconnected,  //!< proof: no collision-free motion joins the poses
    kConnected,     //!< the cells are joined (the motion may still not exist)
    kUnknown,       //!< search budget spent, or an end cell blocked (not free)
  };
  //! Searches at most `max_cells` cells in all.
  Answer query(const FreeGrid& grid, const Pose2& a, const Pose2& b,
               std::size_t max_cells = 2'000'000);
  //! Cells visited by the last query.
  std::size_t visited() const { return visited_.size(); }

 private:
  std::vector<std::uint64_t> marks_[2];  //!< bitsets: reached from a, from b
  std::vector<std::size_t> visited_;     //!< cells marked, to clear them after
  std::vector<std::size_t> queue_[2];
};

}  // namespace hrs::geometry
