// SPDX-License-Identifier: GPL-3.0-or-later
// The accessibility report (access/accessibility.h).

#include "access/accessibility.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <stdexcept>
#include <nlohmann/json.hpp>
#include <sstream>

#include "geometry/error.h"
#include "geometry/free_grid.h"
#include "geometry/polygon_ops.h"

namespace hrs::access {

namespace {

using geometry::Polygon;
using geometry::Pose2;
using geometry::Vec2;
using nlohmann::json;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kTurningGrid = 0.05;  //!< m, candidate centres of the turning circle

//! Every boundary of the layout as polygons: the room, then each footprint.
std::vector<Polygon> boundaries(const geometry::Scene& layout) {
  std::vector<Polygon> out{layout.room.polygon};
  for (const auto& o : layout.objects) out.push_back(geometry::world_footprint(o));
  return out;
}

//! Distance along the ray p + t·d (t > 0) to the first polygon edge.
double ray_hit(const std::vector<Polygon>& polys, Vec2 p, Vec2 d) {
  double best = kInf;
  for (const Polygon& poly : polys)
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Vec2 a = poly[i], b = poly[(i + 1) % poly.size()];
      const Vec2 e{b.x - a.x, b.y - a.y};
      const double den = d.x * e.y - d.y * e.x;
      if (den == 0.0) continue;  // parallel
      const Vec2 ap{a.x - p.x, a.y - p.y};
      const double t = (ap.x * e.y - ap.y * e.x) / den;
      const double u = (ap.x * d.y - ap.y * d.x) / den;
      if (t > 0.0 && u >= 0.0 && u <= 1.0) best = std::min(best, t);
    }
  return best;
}

//! Crossing-number test (a point on an edge counts as inside or outside;
//! callers ask about grid centres with a positive distance to every edge).
bool inside(const Polygon& poly, Vec2 p) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2 a = poly[i], b = poly[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

Polygon rectangle(const Pose2& pose, double length, double width) {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  const double l = length / 2, w = width / 2;
  const Vec2 local[4] = {{l, -w}, {l, w}, {-l, w}, {-l, -w}};
  Polygon out;
  for (const Vec2& q : local) out.push_back({pose.x + c * q.x - s * q.y, pose.y + s * q.x + c * q.y});
  return out;
}

//! Sign of the turn a → b → c, zero within a relative tolerance.
int turn(Vec2 a, Vec2 b, Vec2 c) {
  const double v = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  const double scale = 1e-12 * (std::abs(b.x - a.x) + std::abs(b.y - a.y)) *
                       (std::abs(c.x - a.x) + std::abs(c.y - a.y));
  return v > scale ? 1 : (v < -scale ? -1 : 0);
}

//! Segments ab and cd cross at a point interior to both.
bool cross(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  return turn(a, b, c) * turn(a, b, d) < 0 && turn(c, d, a) * turn(c, d, b) < 0;
}

//! p lies inside the convex, counter-clockwise `rect`, off its edges.
bool strictly_inside(const Polygon& rect, Vec2 p) {
  for (std::size_t i = 0; i < rect.size(); ++i)
    if (turn(rect[i], rect[(i + 1) % rect.size()], p) <= 0) return false;
  return true;
}

//! The search's double-precision test (certified afterwards): the convex
//! `rect` lies in the room and its interior meets no footprint's. Touching
//! counts as free, as with the exact predicates.
bool rect_free(const Polygon& rect, const Polygon& room, const std::vector<Polygon>& footprints) {
  Vec2 mid{0.0, 0.0};
  for (const Vec2 v : rect) mid = {mid.x + v.x / rect.size(), mid.y + v.y / rect.size()};
  if (!inside(room, mid)) return false;
  const auto meets = [&](const Polygon& poly) {
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Vec2 a = poly[i], b = poly[(i + 1) % poly.size()];
      if (strictly_inside(rect, a)) return true;
      for (std::size_t j = 0; j < rect.size(); ++j)
        if (cross(a, b, rect[j], rect[(j + 1) % rect.size()])) return true;
    }
    return false;
  };
  if (meets(room)) return false;
  for (const Polygon& f : footprints)
    if (meets(f) || inside(f, mid)) return false;
  return true;
}

//! The runs of consecutive samples with width below `limit`.
std::vector<Stretch> runs_below(const std::vector<Pose2>& poses, const std::vector<double>& s,
                                const std::vector<double>& w, double limit) {
  std::vector<Stretch> out;
  for (std::size_t i = 0; i < w.size();) {
    if (!(w[i] < limit)) {
      ++i;
      continue;
    }
    Stretch st;
    st.from_m = s[i];
    st.min_width = kInf;
    std::size_t j = i;
    for (; j < w.size() && w[j] < limit; ++j) {
      st.points.push_back({poses[j].x, poses[j].y});
      if (w[j] < st.min_width) st.min_width = w[j], st.where = poses[j];
    }
    st.to_m = s[j - 1];
    out.push_back(std::move(st));
    i = j;
  }
  return out;
}

json pose_json(const Pose2& p) { return json::array({p.x, p.y, p.theta}); }

json stretch_json(const Stretch& s) {
  return {{"from_m", s.from_m}, {"to_m", s.to_m}, {"length_m", s.to_m - s.from_m},
          {"min_width_m", s.min_width}, {"where", pose_json(s.where)}};
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

}  // namespace

Rules Rules::named(const std::string& name, const std::string& what) {
  Rules r;
  if (name == "ada") return r;
  if (name == "iso") {
    r.name = "iso";
    r.turning_diameter = 1.5;  // ISO 21542 turning circle; the rest as ADA
    r.t_shape = false;         // ISO 21542 gives the circle only
    return r;
  }
  throw InputError(what + ": unknown rule set '" + name + "' (expected ada or iso)");
}

int Report::failures() const {
  int n = (tours_total - tours_found) + (door_pass ? 0 : 1) + (turning.fits ? 0 : 1);
  for (const auto& r : routes) n += r.pass ? 0 : 1;
  for (const auto& s : stops) n += s.clear_floor ? 0 : 1;
  return n;
}

bool Report::pass() const {
  if (!door_pass || !turning.fits) return false;
  for (const auto& r : routes)
    if (!r.pass) return false;
  for (const auto& s : stops)
    if (!s.clear_floor) return false;
  return tours_found == tours_total;
}

std::vector<Polygon> t_shape(const Pose2& pose, double side, double arm) {
  const auto at = [&](double x, double y) {
    const Vec2 c = geometry::to_world(pose, {x, y});
    return Pose2{c.x, c.y, pose.theta};
  };
  std::vector<Polygon> out{rectangle(at(0.0, side / 2 - arm / 2), side, arm)};
  if (side > arm) out.push_back(rectangle(at(0.0, -arm / 2), arm, side - arm));
  return out;
}

double route_width_at(const geometry::Scene& layout, const Pose2& pose) {
  const auto polys = boundaries(layout);
  const Vec2 p{pose.x, pose.y};
  const Vec2 left{-std::sin(pose.theta), std::cos(pose.theta)};
  return ray_hit(polys, p, left) + ray_hit(polys, p, {-left.x, -left.y});
}

namespace {

//! The T-shaped space (ADA §304.3.2), turned to the direction of each room
//! edge and by quarter turns of it, in two passes:
//! - coarse: at the turning circle's candidate centres (`centres`, spacing
//!   `step`, with their clearance),
//!   the T eroded by half a cell diagonal δ (side and arm 2δ smaller, same
//!   centre). A T that fits at some centre c contains, for the grid centre g
//!   nearest c (|g − c| ≤ δ), the eroded T at g; so every fitting T leaves an
//!   eroded candidate;
//! - fine: around each candidate, centres every kFineStep across its cell,
//!   with the full T. The first free one (double precision) that the exact
//!   predicates certify is kept. A T whose slack is below kFineStep in some
//!   direction may be missed: the search errs towards "does not fit".
constexpr double kFineStep = 0.0025;  //!< m
constexpr std::size_t kTurns = 4;      //!< wall directions tried (each with its quarter turns)
//! Polygon edges the T search may visit (about a second): a room too large
//! or too cluttered for it gets "not found, search incomplete".
constexpr long long kTWork = 400'000'000;

void find_t_shape(const geometry::Scene& layout, const std::vector<Polygon>& polys,
                  const std::vector<Polygon>& footprints,
                  const std::vector<std::pair<Vec2, double>>& centres, const Rules& rules,
                  double step, Turning& out) {
  out.t_evaluated = true;
  const double side = rules.turning_diameter, arm = rules.t_arm_width;
  const double delta = step * std::sqrt(0.5);
  if (arm <= 2 * delta) return;
  // The eroded T's inner radius about its centre (0 when the centre is
  // outside it): every candidate centre needs that much clearance.
  const double es = side - 2 * delta, ea = arm - 2 * delta;
  double inner = 0.0;
  if (ea >= es / 2) inner = std::min(es / 2, std::hypot(ea / 2, es / 2 - ea));
  // Directions (mod 90°) of the room's walls, longest total wall first; at
  // most kTurns of them, so a room with many wall directions stays bounded.
  std::vector<std::pair<double, double>> walls;  // (direction, total length)
  const Polygon& room = layout.room.polygon;
  for (std::size_t i = 0; i < room.size(); ++i) {
    const Vec2 a = room[i], b = room[(i + 1) % room.size()];
    double t = std::fmod(std::atan2(b.y - a.y, b.x - a.x), M_PI / 2);
    if (t < 0) t += M_PI / 2;
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    auto it = std::find_if(walls.begin(), walls.end(),
                           [&](const auto& w) { return std::abs(w.first - t) < 1e-9; });
    if (it == walls.end())
      walls.emplace_back(t, len);
    else
      it->second += len;
  }
  std::stable_sort(walls.begin(), walls.end(),
                   [](const auto& a, const auto& b) { return a.second > b.second; });
  std::vector<double> turns;
  for (std::size_t i = 0; i < walls.size() && i < kTurns; ++i) turns.push_back(walls[i].first);
  std::size_t edges = 0;
  for (const Polygon& poly : polys) edges += poly.size();
  long long work = 0;  // polygon edges visited by the coarse and fine tests
  const auto free_t = [&](const Pose2& pose, double sd, double ar) {
    for (const Polygon& part : t_shape(pose, sd, ar))
      if (!rect_free(part, room, footprints)) return false;
    return true;
  };
  const auto certified = [&](const Pose2& pose) {
    for (const Polygon& part : t_shape(pose, side, arm)) {
      if (!geometry::inside_with_contact(part, room)) return false;
      for (const Polygon& f : footprints)
        if (geometry::overlap_beyond_contact(part, f)) return false;
    }
    return true;
  };
  const int fine = static_cast<int>(std::ceil(step / kFineStep));
  for (const auto& [c, r] : centres) {
    if (r + 1e-9 < inner) continue;
    const double x = c.x, y = c.y;
    for (const double t0 : turns)
      for (int q = 0; q < 4; ++q) {
        const double theta = t0 + q * M_PI / 2;
        if ((work += static_cast<long long>(edges)) > kTWork) {
          out.t_complete = false;
          return;
        }
        if (!free_t({x, y, theta}, es, ea)) continue;
        for (int i = 0; i <= fine; ++i)
          for (int j = 0; j <= fine; ++j) {
            const Pose2 pose{x - step / 2 + i * step / fine, y - step / 2 + j * step / fine, theta};
            if ((work += static_cast<long long>(edges)) > kTWork) {
              out.t_complete = false;
              return;
            }
            if (!free_t(pose, side, arm) || !certified(pose)) continue;
            out.t_fits = true;
            out.t_pose = pose;
            return;
          }
      }
  }
}

}  // namespace

Report evaluate(const geometry::Scene& layout, const std::vector<planning::Tour>& tours,
                const Rules& rules) {
  Report rep;
  rep.rules = rules;
  rep.tours_total = static_cast<int>(tours.size());
  const auto polys = boundaries(layout);
  std::vector<Polygon> footprints(polys.begin() + 1, polys.end());

  // Routes and stops of the found tours.
  for (std::size_t k = 0; k < tours.size(); ++k) {
    const planning::Tour& t = tours[k];
    if (!t.found) continue;
    ++rep.tours_found;
    std::vector<Pose2> poses;
    for (const auto& leg : t.legs) {
      for (const Pose2& q : leg.waypoints)
        if (poses.empty() || q.x != poses.back().x || q.y != poses.back().y) poses.push_back(q);
      Stop stop;
      stop.tour = static_cast<int>(k);
      stop.object = leg.to_id;
      stop.pose = leg.to;
      const Polygon rect = rectangle(leg.to, rules.floor_length, rules.floor_width);
      stop.clear_floor = geometry::inside_with_contact(rect, layout.room.polygon);
      for (const Polygon& f : footprints)
        if (stop.clear_floor && geometry::overlap_beyond_contact(rect, f)) stop.clear_floor = false;
      rep.stops.push_back(std::move(stop));
    }
    Route route;
    route.tour = static_cast<int>(k);
    std::vector<double> s, w;
    double along = 0.0;
    route.narrowest = kInf;
    for (std::size_t i = 0; i < poses.size(); ++i) {
      if (i > 0) along += std::hypot(poses[i].x - poses[i - 1].x, poses[i].y - poses[i - 1].y);
      s.push_back(along);
      const Vec2 p{poses[i].x, poses[i].y};
      const Vec2 left{-std::sin(poses[i].theta), std::cos(poses[i].theta)};
      w.push_back(ray_hit(polys, p, left) + ray_hit(polys, p, {-left.x, -left.y}));
      if (w.back() < route.narrowest) route.narrowest = w.back(), route.narrowest_at = poses[i];
    }
    route.length_m = along;
    route.below_width = runs_below(poses, s, w, rules.route_width);
    for (const Stretch& st : route.below_width)
      if (st.min_width < rules.route_narrow_width || st.to_m - st.from_m > rules.narrow_length)
        route.failing.push_back(st);
    route.pass = route.failing.empty();
    rep.routes.push_back(std::move(route));
  }

  // Turning space: the largest circle centred in the door's reachable set.
  std::optional<geometry::FreeGrid> grid;
  try {
    grid.emplace(layout, geometry::FreeGridOptions{0.025, 64});
  } catch (const std::invalid_argument&) {
    // A room too large for the certified grid: the turning space is not
    // evaluated (largest_diameter stays 0, fits false).
  }
  geometry::ReachableSet reach;
  if (grid) reach.fill(*grid, geometry::door_start_pose(layout));
  const auto [x0, y0, x1, y1] = geometry::bounding_box(layout.room.polygon);
  // The grid step keeps the work (centres × edges) bounded in large rooms.
  std::size_t edges = 0;
  for (const Polygon& poly : polys) edges += poly.size();
  const double step = std::max(kTurningGrid, std::sqrt((x1 - x0) * (y1 - y0) *
                                                       static_cast<double>(edges) / 2e7));
  rep.turning.grid_m = step;
  // The candidate centres (in the room, reached from the door, outside every
  // footprint) with their clearance: the circle's, then the T's candidates.
  std::vector<std::pair<Vec2, double>> centres;
  for (double y = y0 + step / 2; grid && y < y1; y += step)
    for (double x = x0 + step / 2; x < x1; x += step) {
      const Vec2 c{x, y};
      if (!inside(layout.room.polygon, c) || !reach.column_reached({x, y, 0.0})) continue;
      bool in_object = false;
      for (const Polygon& f : footprints) in_object = in_object || inside(f, c);
      if (in_object) continue;
      double r = kInf;
      for (const Polygon& poly : polys)
        for (std::size_t i = 0; i < poly.size(); ++i)
          r = std::min(r, geometry::point_segment_distance(c, poly[i], poly[(i + 1) % poly.size()]));
      centres.emplace_back(c, r);
      if (2 * r > rep.turning.largest_diameter) rep.turning.largest_diameter = 2 * r, rep.turning.centre = c;
    }
  rep.turning.circle_fits = rep.turning.largest_diameter >= rules.turning_diameter;
  if (grid && !rep.turning.circle_fits && rules.t_shape)
    find_t_shape(layout, polys, footprints, centres, rules, step, rep.turning);
  rep.turning.fits = rep.turning.circle_fits || rep.turning.t_fits;
  const Vec2 from = rep.turning.t_fits ? Vec2{rep.turning.t_pose.x, rep.turning.t_pose.y}
                                        : rep.turning.centre;
  for (const Stop& st : rep.stops) {
    const double d = std::hypot(st.pose.x - from.x, st.pose.y - from.y);
    auto it = std::find_if(rep.turning.distance_to_stops.begin(), rep.turning.distance_to_stops.end(),
                           [&](const auto& e) { return e.first == st.object; });
    if (it == rep.turning.distance_to_stops.end())
      rep.turning.distance_to_stops.emplace_back(st.object, d);
  }

  rep.door_width = layout.door.width;
  rep.door_pass = layout.door.width >= rules.door_width;
  return rep;
}

std::string report_json(const Report& r) {
  json routes = json::array();
  for (const Route& x : r.routes) {
    json below = json::array(), failing = json::array();
    for (const auto& s : x.below_width) below.push_back(stretch_json(s));
    for (const auto& s : x.failing) failing.push_back(stretch_json(s));
    routes.push_back({{"tour", x.tour}, {"length_m", x.length_m}, {"narrowest_m", x.narrowest},
                      {"narrowest_at", pose_json(x.narrowest_at)},
                      {"below_route_width", below}, {"failing", failing}, {"pass", x.pass}});
  }
  json stops = json::array();
  for (const Stop& s : r.stops)
    stops.push_back({{"tour", s.tour}, {"object", s.object}, {"pose", pose_json(s.pose)},
                     {"clear_floor_space", s.clear_floor}});
  json dist = json::object();
  for (const auto& [id, d] : r.turning.distance_to_stops) dist[id] = d;
  json doc = {
      {"format", "hrspace-accessibility/1"},
      {"rules",
       {{"name", r.rules.name},
        {"route_width_m", r.rules.route_width},
        {"route_narrow_width_m", r.rules.route_narrow_width},
        {"narrow_length_m", r.rules.narrow_length},
        {"turning_diameter_m", r.rules.turning_diameter},
        {"t_shape", r.rules.t_shape},
        {"t_arm_width_m", r.rules.t_arm_width},
        {"clear_floor_m", {r.rules.floor_width, r.rules.floor_length}},
        {"door_width_m", r.rules.door_width}}},
      {"pass", r.pass()},
      {"tours", {{"found", r.tours_found}, {"total", r.tours_total}}},
      {"routes", routes},
      {"stops", stops},
      {"turning_space",
       {{"rule_m", r.rules.turning_diameter},
        {"largest_diameter_m", r.turning.largest_diameter},
        {"centre", json::array({r.turning.centre.x, r.turning.centre.y})},
        {"circle_pass", r.turning.circle_fits},
        {"t_shape",
         {{"evaluated", r.turning.t_evaluated},
          {"pass", r.turning.t_fits},
          {"complete", r.turning.t_complete},
          {"pose", r.turning.t_fits ? pose_json(r.turning.t_pose) : json(nullptr)}}},
        {"pass", r.turning.fits},
        {"grid_m", r.turning.grid_m},
        {"distance_to_stops_m", dist}}},
      {"door", {{"rule_m", r.rules.door_width}, {"width_m", r.door_width}, {"pass", r.door_pass}}}};
  return doc.dump(1) + "\n";
}

std::string summary_json(const Report& r) {
  int routes_pass = 0, floors = 0;
  double narrowest = kInf;
  for (const auto& x : r.routes) {
    routes_pass += x.pass ? 1 : 0;
    narrowest = std::min(narrowest, x.narrowest);
  }
  for (const auto& s : r.stops) floors += s.clear_floor ? 1 : 0;
  json j = {{"rules", r.rules.name},
            {"pass", r.pass()},
            {"routes_pass", routes_pass},
            {"routes", static_cast<int>(r.routes.size())},
            {"narrowest_route_m", std::isfinite(narrowest) ? json(narrowest) : json(nullptr)},
            {"clear_floor_spaces", floors},
            {"stops", static_cast<int>(r.stops.size())},
            {"turning_diameter_m", r.turning.largest_diameter},
            {"turning_pass", r.turning.fits},
            {"turning_t_shape", r.turning.t_fits},
            {"door_pass", r.door_pass}};
  return j.dump();
}

std::string svg_overlay(const Report& r) {
  std::ostringstream s;
  for (const Route& x : r.routes)
    for (const Stretch& st : x.below_width) {
      const bool fail = std::any_of(x.failing.begin(), x.failing.end(),
                                    [&](const Stretch& f) { return f.from_m == st.from_m; });
      s << "<polyline fill=\"none\" stroke=\"" << (fail ? "#d62728" : "#ff7f0e")
        << "\" stroke-width=\"0.06\" stroke-opacity=\"0.7\" points=\"";
      for (const Vec2& p : st.points) s << num(p.x) << ',' << num(p.y) << ' ';
      s << "\"/>\n";
    }
  for (const Stop& st : r.stops) {
    const Polygon rect = rectangle(st.pose, r.rules.floor_length, r.rules.floor_width);
    s << "<polygon fill=\"none\" stroke=\"" << (st.clear_floor ? "#2ca02c" : "#d62728")
      << "\" stroke-width=\"0.015\" stroke-dasharray=\"0.05 0.03\" points=\"";
    for (const Vec2& p : rect) s << num(p.x) << ',' << num(p.y) << ' ';
    s << "\"/>\n";
  }
  if (r.turning.t_fits) {
    for (const Polygon& part : t_shape(r.turning.t_pose, r.rules.turning_diameter, r.rules.t_arm_width)) {
      s << "<polygon fill=\"#2ca02c\" fill-opacity=\"0.12\" stroke=\"#2ca02c\" stroke-width=\"0.02\" points=\"";
      for (const Vec2& p : part) s << num(p.x) << ',' << num(p.y) << ' ';
      s << "\"/>\n";
    }
  } else if (r.turning.largest_diameter > 0.0) {
    s << "<circle cx=\"" << num(r.turning.centre.x) << "\" cy=\"" << num(r.turning.centre.y)
      << "\" r=\"" << num(std::min(r.turning.largest_diameter, r.rules.turning_diameter) / 2)
      << "\" fill=\"" << (r.turning.fits ? "#2ca02c" : "#d62728")
      << "\" fill-opacity=\"0.12\" stroke=\"" << (r.turning.fits ? "#2ca02c" : "#d62728")
      << "\" stroke-width=\"0.02\"/>\n";
  }
  return s.str();
}

std::string summary_line(const Report& r) {
  int routes_pass = 0, floors = 0;
  for (const auto& x : r.routes) routes_pass += x.pass ? 1 : 0;
  for (const auto& s : r.stops) floors += s.clear_floor ? 1 : 0;
  std::ostringstream s;
  s << "accessibility (" << r.rules.name << "): " << (r.pass() ? "pass" : "fail") << "; routes "
    << routes_pass << "/" << r.routes.size() << " wide enough, clear floor at " << floors << "/"
    << r.stops.size() << " stops, turning circle " << num(r.turning.largest_diameter) << " m ("
    << (r.turning.circle_fits ? "fits" : "does not fit")
    << (r.turning.t_evaluated ? (r.turning.t_fits ? ", T-shape fits" : ", nor a T-shape") : "")
    << "), door " << num(r.door_width) << " m";
  return s.str();
}

}  // namespace hrs::access
