// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Exact, conservative configuration space of the wheelchair among furniture
// and walls (docs/design-notes.md "Exact, conservative collision"; the paper's planner,
// §III-B, needs these collision checks for every RRT edge).
//
// The heading circle is cut into K slices. For each slice, the footprint swept
// by the chair rotating across the slice is covered by a convex polygon S_k;
// each convex obstacle piece A gives the C-obstacle piece A ⊕ (−S_k). Pieces
// are stored as half-planes whose offsets are support values rounded outward
// with an explicit floating-point error bound, so a "free" answer is certified:
// the true footprint cannot touch an obstacle. Moving an object translates its
// pieces (offsets shift by n·t); rotating it recomputes only its own pieces.
//
// Motions are checked without sampling: a straight segment stays in one slice
// and is tested as a segment against convex pieces; an arc is split at slice
// borders and each sub-arc's centre path is covered by the triangle (start,
// end, tangent intersection), tested by separating axes.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/pose.h"
#include "geometry/scene.h"

namespace hrs::geometry {

struct CSpaceOptions {
  int slices = 72;  //!< K, orientation slices over the full circle
};

//! Distances from a position to the nearest obstacle boundary on each side of
//! its heading (closed half-planes), metres.
struct Clearance {
  double left = 0.0;
  double right = 0.0;
};

class CSpace {
 public:
  //! Builds the C-space for the scene's room, wheelchair and object poses.
  explicit CSpace(const Scene& scene, CSpaceOptions options = {});

  int slices() const { return slices_; }
  //! Number of object poses kept (same order as scene.objects).
  int object_count() const { return static_cast<int>(objects_.size()); }
  const Pose2& object_pose(int index) const { return objects_[index].pose; }

  //! True only if the chair at `pose` is certainly inside the room and clear of
  //! all furniture.
  bool is_free(const Pose2& pose) const;
  //! Straight motion from `start` along its heading by the signed `length`
  //! (negative: reverse). True only if every pose on it is free.
  bool straight_free(const Pose2& start, double length) const;
  //! Arc of the given turning radius: `turn` > 0 steers left, < 0 right; |turn|
  //! is the arc angle (radians) and the heading changes by gear·turn.
  bool arc_free(const Pose2& start, double radius, double turn, int gear) const;

  //! Moves object `index` to `pose`: a pure translation shifts its cached
  //! pieces, a rotation recomputes them; other objects are untouched.
  void move_object(int index, const Pose2& pose);

  //! Nearest obstacle boundary (furniture or wall) left and right of `pose`.
  Clearance clearance(const Pose2& pose) const;
  //! clearance() and which obstacle gives each side's value: the index of an
  //! object, kWalls, or kNothing (no boundary on that side). The values are
  //! clearance()'s to the last bit.
  struct NearestObstacles {
    Clearance clearance;
    int left = kNothing, right = kNothing;
  };
  static constexpr int kWalls = -1;
  static constexpr int kNothing = -2;
  NearestObstacles nearest_obstacles(const Pose2& pose) const;
  //! clearance() against object `index` alone (infinity on a side without
  //! its boundary). Since clearance() is the minimum over walls and objects
  //! of exactly these values, a clearance measured before object i moved is
  //! brought up to date by min(old, object_clearance(pose, i)) on each side
  //! whose nearest obstacle was not i (used by planning::LegMeasures).
  Clearance object_clearance(const Pose2& pose, int index) const;

  //! Every point of object `index`'s footprint lies within this distance of
  //! its position, whatever its pose (metres).
  double object_reach(int index) const;
  //! Every slice's swept cover S_k lies within this distance of the chair's
  //! reference point (metres; the half diagonal plus the covers' bulge).
  //! With object_reach(): a motion whose reference point stays within d of
  //! a point q is never reported blocked by an object whose position is
  //! farther than d + swept_reach() + object_reach() + 1 mm (offsets round
  //! outward by far less) from q, wherever that object is.
  double swept_reach() const;

  //! Total convex C-obstacle pieces over all slices (for reports).
  std::size_t piece_count() const;

 private:
  struct Halfplane {
    double nx, ny, c;  //!< {p : nx·px + ny·py <= c}
  };
  using Box = geometry::Box;
  //! One convex obstacle piece (furniture piece or wall piece) in the world.
  struct ConvexPiece {
    std::vector<Vec2> local;    //!< vertices relative to the owner's position (rotated)
    std::vector<Vec2> normals;  //!< outward edge normals of `local`
  };
  struct ObjectState {
    Pose2 pose;
    Polygon footprint;                  //!< local frame (unrotated)
    std::vector<Polygon> local_pieces;  //!< convex pieces of footprint, local frame
    std::vector<ConvexPiece> pieces;    //!< rotated by pose.theta
    std::vector<Vec2> world_boundary;   //!< world footprint for clearance
    Box world_box{};                    //!< bounding box of world_boundary
  };
  //! A C-obstacle piece in one slice: half-planes at the origin (base) and in
  //! the world, plus its bounding box.
  struct SlicePiece {
    std::int32_t owner;          //!< object index, or -1 for walls
    std::int32_t piece;          //!< index of the convex piece within its owner
    std::uint32_t first, count;  //!< range in the slice's half-plane arrays
    Box base_box, box;
  };
  struct Slice {
    std::vector<Vec2> swept;          //!< points whose hull covers the swept footprint
    std::vector<Vec2> swept_normals;  //!< outward normals of the hull of `swept`
    std::vector<SlicePiece> pieces;
    std::vector<Halfplane> base, world;
  };

  //! What a query sweeps, for the exact refinement of a slice-level hit.
  struct Motion {
    enum Kind { kPose, kStraight, kArc } kind;
    Pose2 start;
    double length;  //!< straight: signed length
    Vec2 centre;    //!< arc: centre of rotation
    double radius;  //!< arc: turning radius
    double side;    //!< arc: +1 centre on the left, −1 on the right
    double ha, hb;  //!< arc: heading range of this sub-arc
  };

  int slice_of(double theta) const;
  bool refine_hits(const SlicePiece& piece, const Motion& motion, int depth) const;
  //! A pose or a straight motion against `piece`: one separating-axis test.
  bool straight_hits(const SlicePiece& piece, const Motion& motion) const;
  //! An arc against `piece`: the cover of the sub-arc, split while undecided.
  bool arc_hits(const SlicePiece& piece, const Motion& motion, int depth) const;
  int arc_triangle(const Motion& m, double ha, double hb, Vec2 (&tri)[3], Vec2* axes) const;
  void build_slice_shapes(const Wheelchair& chair);
  void build_walls(const Polygon& room, double reach);
  void rebuild_object_pieces(int index);
  //! Sets the world footprint and its box from the pose.
  static void set_world_boundary(ObjectState& s);
  void place_object(int index);
  void fill_piece(const Slice& slice, const ConvexPiece& shape, SlicePiece& out,
                  std::vector<Halfplane>& base) const;
  bool hits(const Slice& slice, const SlicePiece& piece, const Vec2* pts, int n, const Vec2* axes,
            int naxes) const;
  bool points_free(int slice, const Vec2* pts, int n, const Vec2* axes, int naxes,
                   const Motion& motion) const;
  const ConvexPiece& shape_of(const SlicePiece& piece) const;

  int slices_ = 72;
  Vec2 corners_[4];  //!< chair footprint corners, chair frame
  Box room_box_{};
  Polygon room_;
  std::vector<ConvexPiece> walls_;
  std::vector<ObjectState> objects_;
  std::vector<Slice> slice_data_;
};

}  // namespace hrs::geometry
