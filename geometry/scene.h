// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The scene model (`hrspace-scene/1`, see docs/scene-format.md): plain
// data for the room, door, wheelchair, furniture, interior-design preferences
// and the AO graph (paper §III-A), with its JSON reader and writer. Validation
// of every rule of the format happens in the reader; errors are InputError
// with "FILE: /json/pointer: what is wrong".

#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/pose.h"

namespace hrs::geometry {

using Polygon = std::vector<Vec2>;  //!< vertices, counter-clockwise, not closed

//! Id of the AO graph's start node, the door: first node of every sequence
//! and tour, reserved (no object may use it).
inline constexpr std::string_view kStartNodeId = "door";

//! Numeric and size limits of the format (docs/scene-format.md, "Limits"):
//! within them every geometric construction of hrspace stays sound (no
//! vertex collapses under rounding, CGAL's filters never overflow) and every
//! computation on a scene is bounded in time and memory.
namespace limits {
inline constexpr double kCoordinate = 1000.0;    //!< |x|, |y| of every point and position, m
inline constexpr double kAngle = 1000.0;         //!< |angle| of every heading or angle, rad
inline constexpr double kMinLength = 1e-3;       //!< smallest size, width, depth, edge, radius, m
inline constexpr double kLength = 2000.0;        //!< largest length or distance, m
inline constexpr double kWeight = 1e6;           //!< largest weight
inline constexpr int kVisits = 100;              //!< largest activity.visits
inline constexpr int kSequences = 1000;          //!< largest activity.sequences (M)
inline constexpr std::size_t kObjects = 100;     //!< most objects
inline constexpr std::size_t kVertices = 1000;   //!< most vertices of a polygon
inline constexpr std::size_t kRelations = 1000;  //!< most relations
inline constexpr int kDepth = 64;                //!< deepest nesting of JSON arrays and objects
//! Largest input file or stream: a scene, a pose or pair CSV (64 MiB).
inline constexpr std::size_t kInputBytes = std::size_t{64} << 20;
}  // namespace limits

//! True if `p` is inside the simple polygon (even-odd crossings, doubles: for
//! filters and margins, not for exact predicates).
inline bool point_in_polygon(Vec2 p, const Polygon& poly) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2 a = poly[i], b = poly[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

//! The room: the inner face of the walls, any simple polygon.
struct Room {
  Polygon polygon;                            //!< counter-clockwise
  std::optional<std::array<double, 2>> size;  //!< set when the file used the `size` shorthand
  friend bool operator==(const Room&, const Room&) = default;
};

struct Door {
  Vec2 center;                 //!< middle of the opening, on the room boundary
  double width = 0.0;          //!< along the wall
  double clear_depth = 1.2;    //!< depth of the zone kept free of furniture
  std::optional<Pose2> start;  //!< explicit start pose of the wheelchair
  friend bool operator==(const Door&, const Door&) = default;
};

struct Wheelchair {
  double length = 0.0;          //!< along the heading
  double width = 0.0;           //!< across the heading
  double turning_radius = 0.0;  //!< Reeds-Shepp minimum turning radius
  friend bool operator==(const Wheelchair&, const Wheelchair&) = default;
};

//! The chair's rectangular footprint at `pose` (the pose is its centre),
//! counter-clockwise from the front-left corner.
inline Polygon chair_footprint(const Wheelchair& chair, const Pose2& pose) {
  const double hl = 0.5 * chair.length, hw = 0.5 * chair.width;
  Polygon p;
  for (Vec2 v : {Vec2{hl, hw}, Vec2{-hl, hw}, Vec2{-hl, -hw}, Vec2{hl, -hw}})
    p.push_back(to_world(pose, v));
  return p;
}

//! Preference for the nearest wall (interior-design cost, §III-D).
struct WallPreference {
  std::optional<double> distance;  //!< footprint-to-wall distance
  std::optional<double> angle;     //!< heading minus the wall's inward normal
  friend bool operator==(const WallPreference&, const WallPreference&) = default;
};

enum class Side { kFront = 0, kBack = 1, kLeft = 2, kRight = 3 };

//! Where the wheelchair may stop to use an object.
struct Approach {
  std::array<bool, 4> sides{true, true, true, true};  //!< indexed by Side
  double gap = 0.1;                                   //!< chair-to-object distance
  friend bool operator==(const Approach&, const Approach&) = default;
};

struct Object {
  std::string id;
  std::optional<std::array<double, 2>> size;  //!< [depth, width] when given as size
  Polygon footprint;  //!< local frame, counter-clockwise (from size or polygon)
  Pose2 pose;
  bool fixed = false;
  std::optional<WallPreference> wall;
  std::optional<Approach> approach;  //!< absent: defaults (all sides, gap 0.1)
  //! The approach rule in force (defaults when absent).
  Approach approach_or_default() const { return approach.value_or(Approach{}); }
  friend bool operator==(const Object&, const Object&) = default;
};

struct Relation {
  std::string a, b;
  std::optional<double> distance;  //!< target centre distance
  std::optional<double> angle;     //!< target of wrap(theta_a - theta_b)
  //! a's front (local +x) points at b's reference point: a TV that faces
  //! the bed, not merely a heading opposite to it.
  bool faces = false;
  double weight = 1.0;
  friend bool operator==(const Relation&, const Relation&) = default;
};

//! The AO graph: from -> {to: probability}; "door" is the start node.
struct Activity {
  std::map<std::string, std::map<std::string, double>> transitions;
  int sequences = 10;  //!< M
  int visits = 3;      //!< objects per tour after the door
  friend bool operator==(const Activity&, const Activity&) = default;
};

struct Weights {
  std::array<double, 3> path{1.0, 1.0, 1.0};  //!< length, rotation, clearance
  std::array<double, 2> interior{1.0, 1.0};   //!< pairwise distance, pairwise rotation
  //! Corridor width (m) below which the clearance cost grows: the cost of a
  //! waypoint is max(0, clearance_width − width). Default: 1.525 m, the
  //! wheelchair turning diameter of the ADA standards (2010, §304.3.1), so
  //! that ordinary rooms feel it; the paper's 0.915 m (the ADA's clear
  //! width of an accessible route) is never reached by a route a chair
  //! can drive, and the term then never shapes a layout.
  double clearance_width = 1.525;
  friend bool operator==(const Weights&, const Weights&) = default;
};

struct Scene {
  std::string name;
  Room room;
  Door door;
  Wheelchair wheelchair;
  std::vector<Object> objects;
  std::vector<Relation> relations;
  Activity activity;
  Weights weights;
  friend bool operator==(const Scene&, const Scene&) = default;

  //! Index of the object with this id, or -1.
  int find_object(std::string_view id) const;
};

//! Reads and validates a scene file. Throws InputError("FILE: /pointer: what").
Scene load_scene(const std::string& path);
//! The bytes of a regular file of at most limits::kInputBytes. Throws
//! InputError naming `path` for a path with a NUL character, a directory, a
//! device, FIFO or socket, a missing or unreadable file, or a larger one.
std::string read_input_file(const std::string& path);
//! A stream read to its end, at most limits::kInputBytes (InputError naming
//! `label` beyond; it reads at most 64 KiB past the limit).
std::string read_input_stream(std::istream& in, const std::string& label);
//! Parses and validates scene text; `label` names the source in messages.
Scene parse_scene(std::string_view text, const std::string& label);
//! Writes a scene as `hrspace-scene/1` JSON text (pretty-printed).
std::string write_scene(const Scene& scene);

//! The object's footprint in world coordinates (rotation in doubles).
Polygon world_footprint(const Object& object);
//! The footprint rotated by the object's heading, not yet translated: the
//! canonical geometry; world vertices are exactly these plus the position.
Polygon rotated_footprint(const Object& object);
//! Inward unit normal of the wall holding the door.
Vec2 door_inward_normal(const Scene& scene);
//! The rectangle inside the door that furniture must keep free.
Polygon door_clear_zone(const Scene& scene);
//! The wheelchair's start pose (explicit or the default just inside the door).
Pose2 door_start_pose(const Scene& scene);
//! Length, capped at `cap`, of the longest walk from "door" through the AO
//! graph that moves at every step (a transition of probability > 0 to another
//! node; staying is not a move).
int longest_walk(const Activity& activity, int cap);
//! Throws InputError("LABEL: /activity/visits: ...") when the AO graph has no
//! sequence of activity.visits moves: nothing to tour (design needs one).
void require_sequences(const Scene& scene, const std::string& label);
//! Warnings for the angles of a scene larger than 2π in magnitude (object and
//! start headings, wall and relation angles): legal, but they look like
//! degrees. One line each, "LABEL: /objects/0/pose/2: angle 90 is larger than
//! 2π in magnitude: radians are expected (90° would be 1.5708)".
std::vector<std::string> degree_like_angles(const Scene& scene, const std::string& label);
//! Area of a simple polygon (positive when counter-clockwise).
double signed_area(const Polygon& polygon);

}  // namespace hrs::geometry
