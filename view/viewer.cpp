// SPDX-License-Identifier: GPL-3.0-or-later
#include "view/viewer.h"

#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "access/accessibility.h"
#include "geometry/cspace.h"
#include "geometry/scene.h"
#include "planning/goals.h"
#include "rs/reeds_shepp.h"
#include "view/page.h"

namespace hrs::view {

namespace {

using geometry::Pose2;
using geometry::Vec2;
using json = nlohmann::json;

//! Millimetres (and milliradians) are enough for drawing and keep the page small.
double round4(double v) { return std::round(v * 1e4) / 1e4; }
json xy(Vec2 p) { return json::array({round4(p.x), round4(p.y)}); }
json xyt(const Pose2& p) { return json::array({round4(p.x), round4(p.y), round4(p.theta)}); }
json polygon(const geometry::Polygon& poly) {
  json out = json::array();
  for (const Vec2 v : poly) out.push_back(xy(v));
  return out;
}

//! "wall angle 88°", "→ bed 0.41 m": what an unmet preference is off by.
std::string unmet_text(const optimize::PreferenceCheck& c) {
  char buf[160];
  const double r = c.angular() ? c.residual * 180.0 / M_PI : c.residual;
  const char* unit = c.angular() ? "°" : " m";
  if (c.kind.starts_with("wall"))
    std::snprintf(buf, sizeof buf, "%s off by %.3g%s", c.kind == "wall_angle" ? "wall angle" : "wall distance", r, unit);
  else if (c.kind == "relation_faces")
    std::snprintf(buf, sizeof buf, "does not face %s (%.3g%s)", c.other.c_str(), r, unit);
  else
    std::snprintf(buf, sizeof buf, "%s to %s off by %.3g%s",
                  c.kind == "relation_angle" ? "angle" : "distance", c.other.c_str(), r, unit);
  return buf;
}

json objects_json(const optimize::DesignResult& result) {
  json out = json::array();
  for (const geometry::Object& o : result.layout.objects) {
    double front = 0.0;
    for (const Vec2 p : o.footprint) front = std::max(front, p.x);
    json unmet = json::array();
    for (const optimize::PreferenceCheck& c : result.preferences.checks)
      if (!c.met && c.object == o.id) unmet.push_back(unmet_text(c));
    out.push_back({{"id", o.id},
                   {"fixed", o.fixed},
                   {"poly", polygon(geometry::world_footprint(o))},
                   {"front", json::array({xy(geometry::to_world(o.pose, {front, -0.12})),
                                          xy(geometry::to_world(o.pose, {front, 0.12}))})},
                   {"unmet", unmet}});
  }
  return out;
}

//! One tour: its waypoints end to end, the index where each stop is reached,
//! the cusps (where consecutive segments of a leg change gear) and the route
//! width at every waypoint.
json tour_json(const geometry::Scene& layout, const planning::Tour& tour, double likelihood) {
  json path = json::array(), stops = json::array(), cusps = json::array(), width = json::array();
  for (const planning::Leg& leg : tour.legs) {
    const std::size_t first = path.empty() ? 0 : 1;  // legs share their joining waypoint
    for (std::size_t i = first; i < leg.waypoints.size(); ++i) {
      path.push_back(xyt(leg.waypoints[i]));
      width.push_back(std::round(access::route_width_at(layout, leg.waypoints[i]) * 1e3) / 1e3);
    }
    stops.push_back(path.size() - 1);
    double s = 0.0;
    for (std::size_t k = 0; k + 1 < leg.path.segments.size(); ++k) {
      s += leg.path.segments[k].length;
      if (leg.path.segments[k].gear != leg.path.segments[k + 1].gear)
        cusps.push_back(xyt(rs::pose_at(leg.from, leg.path, s)));
    }
  }
  return {{"sequence", tour.sequence}, {"likelihood", likelihood}, {"found", tour.found},
          {"length", round4(tour.metrics.length)}, {"path", path},
          {"stops", stops}, {"cusps", cusps}, {"width", width}};
}

//! The candidate goal poses of every object some sequence visits, placed
//! where the object stands, those in collision dropped (planning/goals.h).
json goals_json(const optimize::DesignResult& result) {
  std::set<std::string> visited;
  for (const optimize::Sequence& s : result.sequences) visited.insert(s.nodes.begin(), s.nodes.end());
  const geometry::CSpace cspace(result.layout);
  json out = json::array();
  for (const geometry::Object& o : result.layout.objects) {
    if (!visited.contains(o.id)) continue;
    json poses = json::array();
    for (const planning::GoalPose& g : planning::goal_poses(result.layout, o, o.pose, cspace))
      poses.push_back(xyt(g.pose));
    out.push_back({{"object", o.id}, {"poses", poses}});
  }
  return out;
}

json trace_json(const optimize::DesignResult& result) {
  json it = json::array(), current = json::array(), best = json::array(),
       proposed = json::array(), tours = json::array(), accepted = json::array();
  const auto finite = [](double v) { return std::isfinite(v) ? json(round4(v)) : json(nullptr); };
  for (const optimize::DesignStep& s : result.trace) {
    it.push_back(s.anneal.iteration + 1);
    current.push_back(finite(s.anneal.current_cost));
    best.push_back(finite(s.anneal.best_cost));
    proposed.push_back(s.anneal.valid ? finite(s.anneal.proposed_cost) : json(nullptr));
    tours.push_back(s.planned || s.rejected_early ? json(s.proposed.tours_found) : json(nullptr));
    accepted.push_back(s.anneal.accepted ? 1 : 0);
  }
  return {{"iteration", it}, {"current", current}, {"best", best}, {"proposed", proposed},
          {"tours_found", tours}, {"accepted", accepted}};
}

}  // namespace

std::string design_data(const optimize::DesignResult& result, const std::string& title,
                        const std::string& accessibility_json) {
  const geometry::Scene& scene = result.layout;
  const Vec2 n = geometry::door_inward_normal(scene);
  const Vec2 along{-n.y, n.x};
  const Vec2 c = scene.door.center;
  json tours = json::array();
  for (std::size_t k = 0; k < result.tours.size(); ++k)
    tours.push_back(tour_json(scene, result.tours[k],
                              k < result.sequences.size() ? result.sequences[k].likelihood : 0.0));
  json data = {
      {"format", "hrspace-view/1"},
      {"title", title},
      {"room", polygon(scene.room.polygon)},
      {"door",
       {{"a", xy(c - 0.5 * scene.door.width * along)},
        {"b", xy(c + 0.5 * scene.door.width * along)},
        {"zone", polygon(geometry::door_clear_zone(scene))}}},
      {"chair", {scene.wheelchair.length, scene.wheelchair.width}},
      {"objects", objects_json(result)},
      {"tours", tours},
      {"goals", goals_json(result)},
      {"trace", trace_json(result)},
      {"preferences", {{"met", result.preferences.met}, {"total", result.preferences.total}}},
      {"accessibility", accessibility_json.empty() ? json(nullptr) : json::parse(accessibility_json)}};
  return data.dump();
}

std::string design_html(const optimize::DesignResult& result, const std::string& title,
                        const std::string& accessibility_json) {
  std::string data = design_data(result, title, accessibility_json);
  // Inside <script>, "</" could end the element early; JSON allows "<\/".
  for (std::size_t p = 0; (p = data.find("</", p)) != std::string::npos; p += 3)
    data.replace(p, 2, "<\\/");
  std::string page = detail::kPage;
  const std::string marker = "HRSPACE_DATA_HERE";
  page.replace(page.find(marker), marker.size(), data);
  return page;
}

}  // namespace hrs::view
