// SPDX-License-Identifier: GPL-3.0-or-later
#include "planning/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hrs::planning {

std::vector<geometry::Pose2> waypoints_of(const geometry::Pose2& start, const rs::Path& path,
                                          double step) {
  return rs::sample(start, path, step);
}

double rotation_of(const std::vector<geometry::Pose2>& waypoints) {
  double total = 0.0;
  for (std::size_t i = 1; i < waypoints.size(); ++i) {
    total += std::abs(geometry::wrap_angle(waypoints[i].theta - waypoints[i - 1].theta));
  }
  return total;
}

PathMetrics measure(const geometry::CSpace& cspace, const std::vector<geometry::Pose2>& waypoints,
                    double length, double reference_width) {
  std::vector<geometry::Clearance> clearances;
  clearances.reserve(waypoints.size());
  for (const geometry::Pose2& p : waypoints) clearances.push_back(cspace.clearance(p));
  return metrics_of(waypoints, length, clearances, reference_width);
}

PathMetrics metrics_of(const std::vector<geometry::Pose2>& waypoints, double length,
                       const std::vector<geometry::Clearance>& clearances,
                       double reference_width) {
  PathMetrics m;
  m.length = length;
  m.rotation = rotation_of(waypoints);
  m.waypoints = static_cast<int>(waypoints.size());
  if (waypoints.empty()) return m;
  double sum = 0.0, deficit = 0.0, narrowest = std::numeric_limits<double>::infinity();
  for (const geometry::Clearance& c : clearances) {
    const double w = c.left + c.right;
    sum += w;
    deficit += std::max(0.0, reference_width - w);
    narrowest = std::min(narrowest, w);
  }
  m.clearance = sum / static_cast<double>(waypoints.size());
  m.clearance_deficit = deficit / static_cast<double>(waypoints.size());
  m.min_clearance = narrowest;
  return m;
}

PathMetrics combine(const std::vector<PathMetrics>& parts) {
  PathMetrics m;
  double sum = 0.0, deficit = 0.0;
  m.min_clearance = std::numeric_limits<double>::infinity();
  for (const PathMetrics& p : parts) {
    m.length += p.length;
    m.rotation += p.rotation;
    m.waypoints += p.waypoints;
    sum += p.clearance * p.waypoints;
    deficit += p.clearance_deficit * p.waypoints;
    if (p.waypoints > 0) m.min_clearance = std::min(m.min_clearance, p.min_clearance);
  }
  if (m.waypoints > 0) {
    m.clearance = sum / m.waypoints;
    m.clearance_deficit = deficit / m.waypoints;
  } else {
    m.min_clearance = 0.0;
  }
  return m;
}

}  // namespace hrs::planning
