// SPDX-License-Identifier: GPL-3.0-or-later
#include "optimize/costs.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "geometry/error.h"
#include "optimize/preferences.h"

namespace hrs::optimize {

using geometry::point_segment_distance;
using geometry::segments_cross;
using geometry::Vec2;

namespace {

double squared(double v) { return v * v; }

//! A bounded preference term: kPreferencePenalty · (1 − exp(−z²/2)),
//! z = residual / max(2 · tolerance, floor).
double bounded_term(double residual, double tolerance, double floor) {
  const double z = residual / std::max(2.0 * tolerance, floor);
  return kPreferencePenalty * -std::expm1(-0.5 * z * z);
}

}  // namespace

double facing_error(const Pose2& a, const Pose2& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  if (dx == 0.0 && dy == 0.0) return 0.0;
  return geometry::wrap_angle(std::atan2(dy, dx) - a.theta);
}

CostModel::CostModel(const geometry::Scene& scene, std::vector<Sequence> sequences)
    : scene_(scene), sequences_(std::move(sequences)) {
  double total = 0.0;
  for (const auto& s : sequences_) total += s.likelihood;
  for (const auto& s : sequences_) seq_weight_.push_back(total > 0.0 ? s.likelihood / total : 0.0);

  const auto alpha = object_scales(sequences_);
  // ᾱ: the L̂-weighted mean of α over leg ends.
  double mean = 0.0;
  for (std::size_t k = 0; k < sequences_.size(); ++k) {
    const auto& nodes = sequences_[k].nodes;
    if (nodes.size() < 2) continue;
    double sum = 0.0;
    for (std::size_t i = 1; i < nodes.size(); ++i) sum += alpha.at(nodes[i]);
    mean += seq_weight_[k] * sum / static_cast<double>(nodes.size() - 1);
  }
  for (const auto& [id, a] : alpha) alpha_hat_[id] = mean > 0.0 ? a / mean : 0.0;
  alpha_scene_ = alpha_hat_;

  const auto& room = scene_.room.polygon;
  for (std::size_t i = 0; i < room.size(); ++i)
    perimeter_ += geometry::norm(room[(i + 1) % room.size()] - room[i]);

  for (std::size_t r = 0; r < scene_.relations.size(); ++r) {
    const auto& rel = scene_.relations[r];
    const int a = scene_.find_object(rel.a), b = scene_.find_object(rel.b);
    if (a < 0 || b < 0)
      throw InputError("relation names an unknown object: " + rel.a + ", " + rel.b);
    relations_.push_back({a, b, static_cast<int>(r)});
  }
}

void CostModel::set_uniform_alpha(bool on) {
  alpha_hat_ = alpha_scene_;
  if (on)
    for (auto& [id, a] : alpha_hat_) a = 1.0;
}

double CostModel::object_weight(const std::string& id) const {
  auto it = alpha_hat_.find(id);
  return it == alpha_hat_.end() ? 0.0 : it->second;
}

double CostModel::wall_distance(const geometry::Polygon& footprint, int edge) const {
  const auto& room = scene_.room.polygon;
  const Vec2 a = room[edge], b = room[(edge + 1) % room.size()];
  double d = std::numeric_limits<double>::infinity();
  const std::size_t n = footprint.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 p = footprint[i], q = footprint[(i + 1) % n];
    if (segments_cross(a, b, p, q)) return 0.0;
    d = std::min(d, point_segment_distance(p, a, b));
    d = std::min(d, point_segment_distance(a, p, q));
    d = std::min(d, point_segment_distance(b, p, q));
  }
  return d;
}

double CostModel::wall_normal_angle(int edge) const {
  const auto& room = scene_.room.polygon;
  const Vec2 d = room[(edge + 1) % room.size()] - room[edge];
  return std::atan2(d.x, -d.y);  // direction of (−d.y, d.x): left of a ccw edge
}

int CostModel::nearest_wall(int object, const Pose2& pose) const {
  geometry::Object o = scene_.objects[object];
  o.pose = pose;
  const auto footprint = geometry::world_footprint(o);
  const int edges = static_cast<int>(scene_.room.polygon.size());
  std::vector<double> dist(edges);
  double best = std::numeric_limits<double>::infinity();
  for (int e = 0; e < edges; ++e) best = std::min(best, dist[e] = wall_distance(footprint, e));
  const double target = o.wall && o.wall->angle ? *o.wall->angle : 0.0;
  int chosen = -1;
  double chosen_err = std::numeric_limits<double>::infinity();
  for (int e = 0; e < edges; ++e) {
    if (dist[e] > best + kWallTieTolerance) continue;
    const double err = std::abs(geometry::wrap_angle(pose.theta - wall_normal_angle(e) - target));
    if (err < chosen_err) chosen = e, chosen_err = err;
  }
  return chosen;
}

InteriorCosts CostModel::interior(const std::vector<Pose2>& poses) const {
  assert(poses.size() == scene_.objects.size());
  InteriorCosts c;
  const PreferenceTolerances tol;
  for (const auto& r : relations_) {
    const auto& rel = scene_.relations[r.relation];
    const Pose2 &a = poses[r.a], &b = poses[r.b];
    if (rel.distance) {
      const double e = geometry::norm(a.position() - b.position()) - *rel.distance;
      c.distance += rel.weight * (bounded_ ? bounded_term(std::abs(e), std::max(
                                                 tol.relation_distance,
                                                 tol.relation_distance_share * *rel.distance),
                                                 kDistanceScaleFloor)
                                           : squared(e));
    }
    if (rel.angle) {
      const double e = geometry::wrap_angle(a.theta - b.theta - *rel.angle);
      c.rotation += rel.weight * (bounded_ ? bounded_term(std::abs(e), tol.relation_angle, kAngleScaleFloor) : squared(e));
    }
    if (rel.faces) {
      const double e = facing_error(a, b);
      c.rotation += rel.weight * (bounded_ ? bounded_term(std::abs(e), tol.relation_angle, kAngleScaleFloor) : squared(e));
    }
  }
  for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
    const auto& wall = scene_.objects[i].wall;
    if (!wall || (!wall->distance && !wall->angle)) continue;
    const int idx = static_cast<int>(i);
    const int e = nearest_wall(idx, poses[i]);
    if (wall->distance) {
      geometry::Object o = scene_.objects[i];
      o.pose = poses[i];
      const double r = wall_distance(geometry::world_footprint(o), e) - *wall->distance;
      c.distance += bounded_ ? bounded_term(std::abs(r), tol.wall_distance, kDistanceScaleFloor) : squared(r);
    }
    if (wall->angle) {
      const double r = geometry::wrap_angle(poses[i].theta - wall_normal_angle(e) - *wall->angle);
      c.rotation += bounded_ ? bounded_term(std::abs(r), tol.wall_angle, kAngleScaleFloor) : squared(r);
    }
  }
  return c;
}

std::array<double, 3> CostModel::tour_costs(int k, const planning::Tour& tour,
                                            std::span<const double> blockage) const {
  const auto& nodes = sequences_[k].nodes;
  std::array<double, 3> c{0.0, 0.0, 0.0};
  const std::size_t legs = nodes.size() - 1;
  if (!tour.found) {
    // Legs the planner could join (stats.depth) are charged half their
    // share, the others 1 + b/2; each share at the largest length, rotation
    // and clearance deficit a found leg of its length can have (see the header).
    const std::size_t joined = std::min<std::size_t>(std::max(tour.stats.depth, 0), legs);
    for (std::size_t i = 1; i < nodes.size(); ++i) {
      const double b = i - 1 < blockage.size() ? blockage[i - 1] : 0.0;
      const double share = i <= joined ? 0.5 : 1.0 + 0.5 * b;
      const double weight = share * object_weight(nodes[i]);
      const double length = unfound_length() / static_cast<double>(legs);
      c[0] += weight * length;
      c[1] += weight * length / scene_.wheelchair.turning_radius;
      c[2] += weight * scene_.weights.clearance_width;
    }
    return c;
  }
  assert(tour.legs.size() == legs);
  for (std::size_t i = 0; i < tour.legs.size(); ++i) {
    const double w = object_weight(nodes[i + 1]);
    const auto& m = tour.legs[i].metrics;
    c[0] += w * m.length;
    c[1] += w * m.rotation;
    c[2] += w * m.clearance_deficit;
  }
  return c;
}

double CostModel::tour_total(int k, const planning::Tour& tour,
                             std::span<const double> blockage) const {
  const auto c = tour_costs(k, tour, blockage);
  const auto& wp = scene_.weights.path;
  const double l = seq_weight_[k];
  return wp[0] * l * c[0] + wp[1] * l * c[1] + wp[2] * l * c[2];
}

CostTerms CostModel::interior_terms(const InteriorCosts& interior) const {
  CostTerms t;
  t.interior_distance = scene_.weights.interior[0] * interior.distance;
  t.interior_rotation = scene_.weights.interior[1] * interior.rotation;
  return t;
}

CostTerms CostModel::evaluate(const std::vector<Pose2>& poses,
                              const std::vector<planning::Tour>& tours,
                              const std::vector<std::vector<double>>* blockage,
                              int tours_counted) const {
  return evaluate(interior(poses), tours, blockage, tours_counted);
}

CostTerms CostModel::evaluate(const InteriorCosts& interior,
                              const std::vector<planning::Tour>& tours,
                              const std::vector<std::vector<double>>* blockage,
                              int tours_counted) const {
  assert(tours.size() == sequences_.size());
  assert(!blockage || blockage->size() == tours.size());
  CostTerms t = interior_terms(interior);
  const auto& wp = scene_.weights.path;
  const std::size_t counted =
      tours_counted < 0 ? tours.size() : std::min(tours.size(), std::size_t(tours_counted));
  for (std::size_t k = 0; k < counted; ++k) {
    const auto c = tour_costs(static_cast<int>(k), tours[k],
                              blockage ? std::span<const double>((*blockage)[k])
                                       : std::span<const double>());
    const double l = seq_weight_[k];
    const double length = wp[0] * l * c[0], rotation = wp[1] * l * c[1],
                 clearance = wp[2] * l * c[2];
    ++t.tours_total;
    if (tours[k].found) {
      ++t.tours_found;
      t.path_length += length;
      t.path_rotation += rotation;
      t.path_clearance += clearance;
    } else {
      t.unfound_penalty += length + rotation + clearance;
    }
  }
  return t;
}

}  // namespace hrs::optimize
