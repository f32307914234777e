// SPDX-License-Identifier: GPL-3.0-or-later
#include "planning/leg_measures.h"

#include <algorithm>
#include <cmath>

#include "planning/motion_validator.h"
#include "planning/moved_objects.h"
#include "planning/path_ops.h"

namespace hrs::planning {

namespace {

bool same_path(const rs::Path& a, const rs::Path& b) {
  return a.radius == b.radius && a.segments == b.segments;
}

}  // namespace

LegMeasures::LegMeasures(const geometry::Scene& scene, const geometry::CSpace& cspace,
                         double radius, double reference_width)
    : scene_(&scene),
      cspace_(&cspace),
      radius_(radius),
      reference_width_(reference_width),
      swept_reach_(cspace.swept_reach()) {
  for (int i = 0; i < cspace.object_count(); ++i) object_reach_.push_back(cspace.object_reach(i));
}

void LegMeasures::measure(Leg& leg, double step) {
  std::shared_ptr<const MetricsEntry> old;
  {
    std::lock_guard lock(mutex_);
    auto it = metrics_.find(leg.key);
    if (it != metrics_.end()) old = it->second;
  }
  std::vector<Pose2> now = layout_of(*cspace_);
  if (old && !(old->step == step && old->from == leg.from && same_path(old->path, leg.path)))
    old.reset();

  auto entry = std::make_shared<MetricsEntry>();
  entry->step = step;
  entry->from = leg.from;
  entry->path = leg.path;
  if (old) {
    std::vector<int> moved;
    for (std::size_t i = 0; i < now.size(); ++i)
      if (!(now[i] == old->layout[i])) moved.push_back(static_cast<int>(i));
    if (moved.empty()) {
      leg.waypoints = old->waypoints;
      leg.metrics = old->metrics;
      std::lock_guard lock(mutex_);
      ++counters_.metrics_same;
      return;
    }
    entry->waypoints = old->waypoints;
    entry->nearest = old->nearest;
    update_nearest(*entry, moved, now);
  } else {
    entry->waypoints = waypoints_of(leg.from, leg.path, step);
    entry->nearest.reserve(entry->waypoints.size());
    for (const Pose2& p : entry->waypoints) entry->nearest.push_back(cspace_->nearest_obstacles(p));
  }
  std::vector<geometry::Clearance> clearances;
  clearances.reserve(entry->nearest.size());
  for (const auto& n : entry->nearest) clearances.push_back(n.clearance);
  entry->metrics = metrics_of(entry->waypoints, leg.path.length(), clearances, reference_width_);
  entry->layout = std::move(now);
  leg.waypoints = entry->waypoints;
  leg.metrics = entry->metrics;
  std::lock_guard lock(mutex_);
  ++(old ? counters_.metrics_updated : counters_.metrics_fresh);
  metrics_[leg.key] = std::move(entry);
}

void LegMeasures::update_nearest(MetricsEntry& entry, const std::vector<int>& moved,
                                 const std::vector<Pose2>& now) const {
  auto moved_object = [&](int owner) {
    return std::find(moved.begin(), moved.end(), owner) != moved.end();
  };
  for (std::size_t w = 0; w < entry.waypoints.size(); ++w) {
    const Pose2& p = entry.waypoints[w];
    geometry::CSpace::NearestObstacles& n = entry.nearest[w];
    if (moved_object(n.left) || moved_object(n.right)) {
      n = cspace_->nearest_obstacles(p);  // the nearest obstacle moved: afresh
      continue;
    }
    for (int k : moved) {
      // Object k's boundary lies within object_reach of its position, so
      // it is at least |p - position| - reach away: farther than both
      // sides' values (1 nm over the rounding), it cannot lower either.
      const double far = std::max(n.clearance.left, n.clearance.right) + object_reach_[k] + 1e-9;
      const double dx = p.x - now[k].x, dy = p.y - now[k].y;
      if (dx * dx + dy * dy > far * far) continue;
      const geometry::Clearance d = cspace_->object_clearance(p, k);
      if (d.left < n.clearance.left) {
        n.clearance.left = d.left;
        n.left = k;
      }
      if (d.right < n.clearance.right) {
        n.clearance.right = d.right;
        n.right = k;
      }
    }
  }
}

bool LegMeasures::moves_out_of_reach(const CertifiedEntry& e, const std::vector<Pose2>& now) const {
  // A piece is at most e.piece long: its reference point stays within
  // e.piece of its start.
  return moved_objects_clear(*scene_, e.layout, now, e.starts,
                             e.piece + swept_reach_ + kOffsetSlack, true);
}

double LegMeasures::certified_prefix(const Leg& leg, double piece) {
  std::vector<Pose2> now = layout_of(*cspace_);
  std::shared_ptr<const CertifiedEntry> old;
  {
    std::lock_guard lock(mutex_);
    auto it = certified_.find(leg.key);
    if (it != certified_.end()) {
      const CertifiedEntry& e = *it->second;
      if (e.piece == piece && e.from == leg.from && same_path(e.path, leg.path)) {
        if (e.layout == now) {
          ++counters_.certified_same;
          return e.prefix;
        }
        old = it->second;
      }
    }
  }
  auto entry = std::make_shared<CertifiedEntry>();
  entry->from = leg.from;
  entry->path = leg.path;
  entry->piece = piece;
  const bool kept = old && moves_out_of_reach(*old, now);
  if (kept) {
    entry->prefix = old->prefix;
    entry->starts = old->starts;
  } else {
    MotionValidator validator(*cspace_, radius_);
    entry->prefix = validator.certified_prefix(leg.from, leg.path, piece);
    // The pieces certified_prefix() checks.
    for_each_piece(leg.from, leg.path, piece, radius_, [&](const PathPiece& q) {
      entry->starts.push_back(q.start.position());
      return true;
    });
  }
  entry->layout = std::move(now);
  const double prefix = entry->prefix;
  std::lock_guard lock(mutex_);
  ++(kept ? counters_.certified_kept : counters_.certified_fresh);
  certified_[leg.key] = std::move(entry);
  return prefix;
}

LegMeasures::Counters LegMeasures::counters() const {
  std::lock_guard lock(mutex_);
  return counters_;
}

}  // namespace hrs::planning
