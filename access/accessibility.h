// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// An accessibility report of a designed layout (beyond the paper): is the
// wheelchair's route wide enough along every found tour, is there a clear
// floor space at each stop, does a turning circle fit in the free space the
// door reaches, and is the door wide enough. The rules are data (Rules),
// with the figures of the 2010 ADA Standards for Accessible Design:
//   §403.5.1 route clear width 915 mm, narrowing to 815 mm for at most 610 mm;
//   §304.3   turning space: a 1525 mm circle, or a T-shaped space within a
//            1525 mm square, arms and base 915 mm wide (§304.3.2);
//   §305.3   clear floor space 760 × 1220 mm at each element used;
//   §404.2.3 door clear width 815 mm.
// The `iso` preset changes the turning circle to ISO 21542's 1500 mm, has
// no T-shaped alternative, and keeps the other ADA figures. Han, Law, Latombe and Kunz (2002) checked
// building plans against ADA rules with motion planning; this report does
// it for one room's layout and the tours hrspace found in it.
//
// How each figure is measured (docs/accessibility.md):
// - route width at a waypoint of a found tour: the length of the line
//   through the chair's centre, perpendicular to its heading, between the
//   first obstacle boundaries (room walls, furniture) on either side, in
//   double precision from the exact polygons;
// - clear floor space: the 760 × 1220 mm rectangle centred on the chair's
//   pose at the stop (long side along its heading) lies inside the room and
//   overlaps no footprint (exact predicates, geometry/polygon_ops.h);
// - turning space: centres on a 5 cm grid whose cell the door's reachable
//   set holds (geometry::ReachableSet, an outer approximation), the circle
//   of the largest distance to every wall and footprint; the largest found
//   is within a grid diagonal (7 cm at 5 cm spacing) of the largest that fits
//   anywhere on that set (rooms with many edges get a coarser grid, reported);
//   when no circle fits, the T-shaped space is tried at the same centres,
//   turned to the four longest walls' directions and by quarter turns (with
//   a work bound, reported when reached); the first free one
//   found in double precision is certified with the exact predicates
//   (geometry/polygon_ops.h) before it counts;
// - door: the scene's door width.

#include <string>
#include <vector>

#include "geometry/pose.h"
#include "geometry/scene.h"
#include "planning/tour_types.h"

namespace hrs::access {

struct Rules {
  std::string name = "ada";
  double route_width = 0.915;         //!< m, ADA §403.5.1
  double route_narrow_width = 0.815;  //!< m, allowed for at most narrow_length
  double narrow_length = 0.610;       //!< m
  double turning_diameter = 1.525;    //!< m, ADA §304.3 (ISO 21542: 1.5)
  bool t_shape = true;                //!< a T-shaped space may replace the circle (ADA §304.3.2)
  double t_arm_width = 0.915;         //!< m, width of the T's arms and base
  double floor_width = 0.760;         //!< m, ADA §305.3
  double floor_length = 1.220;        //!< m
  double door_width = 0.815;          //!< m, ADA §404.2.3
  //! "ada" or "iso"; InputError naming `what` for any other name.
  static Rules named(const std::string& name, const std::string& what = "--rules");
};

//! A stretch of a tour where the route is narrower than a width.
struct Stretch {
  double from_m = 0.0, to_m = 0.0;  //!< arc length along the tour
  double min_width = 0.0;           //!< m
  geometry::Pose2 where;            //!< the chair's pose at the narrowest point
  std::vector<geometry::Vec2> points;  //!< the stretch's waypoints (for drawing)
};

struct Route {
  int tour = 0;                       //!< index of the tour (most likely first)
  double length_m = 0.0;              //!< along the waypoints
  double narrowest = 0.0;             //!< m
  geometry::Pose2 narrowest_at;
  std::vector<Stretch> below_width;   //!< narrower than route_width
  std::vector<Stretch> failing;       //!< narrower than route_narrow_width, or longer than narrow_length
  bool pass = true;
};

struct Stop {
  int tour = 0;
  std::string object;
  geometry::Pose2 pose;  //!< the chair's pose at the stop
  bool clear_floor = false;
};

struct Turning {
  bool fits = false;                //!< the circle fits, or the T-shaped space does
  bool circle_fits = false;
  geometry::Vec2 centre{0.0, 0.0};  //!< of the largest circle found
  double largest_diameter = 0.0;    //!< m (0 when the door reaches nothing)
  double grid_m = 0.0;              //!< spacing of the candidate centres
  //! The T-shaped space: tried when no circle fits and the rules allow it.
  bool t_evaluated = false;
  bool t_fits = false;
  //! False when the T search stopped at its work bound before trying every
  //! candidate (a room too large or too cluttered); t_fits is then false.
  bool t_complete = true;
  geometry::Pose2 t_pose;  //!< centre of its square; the bar lies along +y of this frame
  //! From the circle's centre, or from the T's when only the T fits.
  std::vector<std::pair<std::string, double>> distance_to_stops;  //!< object, m
};

struct Report {
  Rules rules;
  std::vector<Route> routes;  //!< one per found tour
  std::vector<Stop> stops;    //!< every stop of every found tour
  Turning turning;
  double door_width = 0.0;
  bool door_pass = false;
  int tours_total = 0, tours_found = 0;
  //! Every found route, every stop, the turning space and the door pass.
  bool pass() const;
  //! The checks that fail: unfound tours, failing routes, stops without a
  //! clear floor space, the turning space and the door (0 exactly when pass()).
  int failures() const;
};

//! The report of `layout` (a designed scene) and its `tours`.
Report evaluate(const geometry::Scene& layout, const std::vector<planning::Tour>& tours,
                const Rules& rules);

//! The T-shaped turning space at `pose` as two rectangles: the bar (the
//! square's side long, the arm width deep, along the square's +y edge) and
//! the stem (the arm width wide, down to the square's −y edge).
std::vector<geometry::Polygon> t_shape(const geometry::Pose2& pose, double side, double arm);
//! Route width at `pose`: the clear length of the line through the pose's
//! position perpendicular to its heading, between the first wall or
//! footprint boundary on the left and on the right.
double route_width_at(const geometry::Scene& layout, const geometry::Pose2& pose);

//! accessibility.json text: the rules and every figure with its rule, value and pass.
std::string report_json(const Report& report);
//! The compact summary report.json carries under "accessibility".
std::string summary_json(const Report& report);
//! SVG elements in room coordinates (metres, y up) for design.svg.
std::string svg_overlay(const Report& report);
//! One line for stdout, e.g. "accessibility (ada): pass 3/4: route ..."
std::string summary_line(const Report& report);

}  // namespace hrs::access
