// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A resolution-complete leg planner (beyond the paper): a best-first search
// of a pose lattice with exact Reeds–Shepp edges, in the spirit of Hybrid A*
// (Dolgov et al. 2008) and of state lattices (Pivtoraiko & Kelly 2005). The
// RRT of §III-B gives up after its iteration cap; on a leg that needs a long
// manoeuvre through a narrow opening it often gives up on a path that
// exists. This search answers such a leg: a certified path, or "no path at
// this resolution".
//
// The lattice. Its nodes are the *canonical poses*: the centre of every cell
// of an h × h grid over the room's bounding box, at every one of K headings
// (θ_k = 2πk/K). From each node six motions are driven: straight ahead and
// arcs of turning radius r through 2 heading steps to the left and to the
// right, forwards and backwards. Each motion's end is snapped to its cell's
// centre and to the nearest heading, and the edge is the exact shortest RS
// path between the two canonical poses. The snap makes the edge set
// translation-invariant, so the edge paths are computed once per heading;
// an edge is used when the continuous checks (MotionValidator) certify it.
// The graph is therefore fixed by (scene, h, K, r), and which nodes are
// reached does not depend on the order of the search: the best-first search
// and a plain breadth-first search give the same answer
// (tests/planning/lattice_test.cpp).
//
// The ends. The start joins the canonical poses of its own and the 8
// neighbouring cells at its nearest heading and the two beside it, by
// certified RS paths; the goal is joined from every node within
// `shot_radius` of it that the search settles, by a certified RS path
// (Hybrid A*'s analytic expansion). A direct RS path from start to goal is
// tried first. The answer:
// - kFound: the path start → nodes → goal, checked again as a whole from the
//   start (its end within 1e-9 of the goal);
// - kNoPath: every node reachable from the start was settled, none joined
//   the goal: no path exists at this resolution;
// - kBudget: `max_expansions` nodes were settled first (nothing proven).
// A query's memory grows with the nodes it reaches (a hash map), never with
// the size of the lattice.
//
// The order is A*'s with the RS length to the goal as the estimate, weighted
// by `heuristic_weight` (>= 1 trades optimality for speed; the answer's
// found/not found is the same for any weight). Deterministic.

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "geometry/cspace.h"
#include "geometry/pose.h"
#include "geometry/scene.h"
#include "planning/motion_validator.h"
#include "rs/reeds_shepp.h"

namespace hrs::planning {

struct LatticeOptions {
  double cell = 0.1;                //!< h: grid cell side, metres
  int headings = 32;                //!< K: headings over the full circle
  double straight = 0.3;            //!< length of the straight motion, metres
  int turn_steps = 2;               //!< heading steps of an arc motion
  double shot_radius = 2.0;         //!< goal joined from nodes this close, metres
  std::size_t max_expansions = 60000;   //!< nodes settled before kBudget
  double heuristic_weight = 1.5;    //!< A* weight (0: breadth-first by cost)
  bool breadth_first = false;       //!< FIFO order instead of A* (tests)
};

enum class LatticeAnswer { kFound, kNoPath, kBudget };

struct LatticeResult {
  LatticeAnswer answer = LatticeAnswer::kNoPath;
  rs::Path path;                    //!< from `from` to `to` when found
  std::size_t expansions = 0;       //!< nodes settled
  std::size_t reached = 0;          //!< nodes reached (settled or queued)
  std::uint64_t checks = 0;         //!< continuous checks
  bool found() const { return answer == LatticeAnswer::kFound; }
};

class LatticePlanner {
 public:
  //! The lattice over `scene`'s room for a chair of turning radius `radius`
  //! in `cspace` (shared, read-only).
  LatticePlanner(const geometry::Scene& scene, const geometry::CSpace& cspace, double radius,
                 LatticeOptions options = {});

  LatticeResult plan(const geometry::Pose2& from, const geometry::Pose2& to);

  const LatticeOptions& options() const { return options_; }
  //! The canonical pose of node `node` (for tests).
  geometry::Pose2 node_pose(std::size_t node) const;
  std::size_t node_count() const { return static_cast<std::size_t>(nx_) * ny_ * options_.headings; }

 private:
  struct Edge {
    int dx = 0, dy = 0, heading = 0;  //!< target cell offset and heading
    rs::Path path;                    //!< exact RS path between the canonical poses
  };
  //! The node of a pose's cell and nearest heading, or -1 outside the grid.
  std::int64_t node_of(const geometry::Pose2& pose) const;
  //! The path start → node → … → node `last` → goal, from the parent links.
  rs::Path assemble(std::int64_t last, const rs::Path& shot) const;

  const geometry::CSpace* cspace_;
  double radius_;
  LatticeOptions options_;
  double x0_ = 0.0, y0_ = 0.0;
  int nx_ = 0, ny_ = 0;
  std::vector<std::vector<Edge>> edges_;  //!< per heading
  MotionValidator validator_;
  //! What a query knows of a node it reached. Kept in a hash map, so a
  //! query's memory grows with the nodes it reaches, not with the lattice.
  struct Visit {
    double cost = 0.0;         //!< best cost so far
    std::int64_t parent = -1;  //!< parent node; -1: joined from the start
    std::int32_t via = -1;     //!< edge index from the parent, or start path index
    bool settled = false;
  };
  std::unordered_map<std::int64_t, Visit> visits_;  //!< per query
  std::vector<rs::Path> start_paths_;               //!< start → node paths (Visit::via)
};

}  // namespace hrs::planning
