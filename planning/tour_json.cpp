// SPDX-License-Identifier: GPL-3.0-or-later
#include "planning/tour_json.h"

#include <nlohmann/json.hpp>

#include "planning/metrics.h"

namespace hrs::planning {

namespace {

using nlohmann::json;

json pose_json(const Pose2& p) { return json::array({p.x, p.y, p.theta}); }

json segments_json(const rs::Path& path) {
  json out = json::array();
  for (const rs::Segment& s : path.segments) {
    out.push_back({{"steer", std::string(1, static_cast<char>(s.steer))},
                   {"gear", s.gear},
                   {"length", s.length}});
  }
  return out;
}

json waypoints_json(const std::vector<Pose2>& waypoints) {
  json out = json::array();
  for (const Pose2& p : waypoints) out.push_back(pose_json(p));
  return out;
}

json metrics_json(const PathMetrics& m) {
  return {{"length", m.length},
          {"rotation", m.rotation},
          {"clearance", m.clearance},
          {"min_clearance", m.min_clearance},
          {"clearance_deficit", m.clearance_deficit}};
}

json tour_object(const Tour& tour, std::optional<double> likelihood) {
  json t;
  t["sequence"] = tour.sequence;
  if (likelihood) t["likelihood"] = *likelihood;
  t["found"] = tour.found;
  json legs = json::array();
  for (const Leg& leg : tour.legs) {
    legs.push_back({{"from_id", leg.from_id},
                    {"to_id", leg.to_id},
                    {"from", pose_json(leg.from)},
                    {"to", pose_json(leg.to)},
                    {"length", leg.path.length()},
                    {"segments", segments_json(leg.path)},
                    {"waypoints", waypoints_json(leg.waypoints)},
                    {"reused", leg.source != LegSource::kPlanned},
                    {"iterations", leg.stats.iterations}});
  }
  t["legs"] = std::move(legs);
  t["metrics"] = metrics_json(tour.metrics);
  t["stats"] = {{"legs_planned", tour.stats.legs_planned},
                {"legs_failed", tour.stats.legs_failed},
                {"legs_reused", tour.stats.legs_reused},
                {"legs_repaired", tour.stats.legs_repaired},
                {"legs_rejected", tour.stats.legs_rejected},
                {"backtracks", tour.stats.backtracks},
                {"capped", tour.stats.capped},
                {"rrt_iterations", tour.stats.rrt_iterations},
                {"collision_checks", tour.stats.collision_checks},
                {"time_ms", tour.stats.time_ms}};
  return t;
}

}  // namespace

std::string plan_json(const Pose2& from, const Pose2& to, const LegResult& result, double radius,
                      std::optional<bool> impossible) {
  json j;
  j["found"] = result.found;
  j["from"] = pose_json(from);
  j["to"] = pose_json(to);
  j["radius"] = radius;
  j["length"] = result.found ? result.path.length() : 0.0;
  j["segments"] = segments_json(result.path);
  j["waypoints"] =
      result.found ? waypoints_json(waypoints_of(from, result.path, kWaypointStep)) : json::array();
  j["iterations"] = result.stats.iterations;
  j["tree_nodes"] = result.stats.tree_nodes;
  j["collision_checks"] = result.stats.collision_checks;
  j["time_ms"] = result.stats.time_ms;
  if (impossible) j["impossible"] = *impossible;
  return j.dump();
}

std::string tour_json(const Tour& tour, std::optional<double> likelihood) {
  return tour_object(tour, likelihood).dump();
}

std::string tours_json(const std::vector<Tour>& tours, const std::vector<double>& likelihoods,
                       bool timings, int indent) {
  json all = json::array();
  for (std::size_t i = 0; i < tours.size(); ++i) {
    json t = tour_object(
        tours[i], i < likelihoods.size() ? std::optional<double>(likelihoods[i]) : std::nullopt);
    if (!timings) t["stats"].erase("time_ms");
    all.push_back(std::move(t));
  }
  return json{{"tours", std::move(all)}}.dump(indent);
}

}  // namespace hrs::planning
