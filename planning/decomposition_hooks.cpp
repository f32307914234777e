// SPDX-License-Identifier: GPL-3.0-or-later
#include "planning/decomposition_hooks.h"

#include <algorithm>
#include <cmath>

#include "geometry/polygon_ops.h"
#include "geometry/random.h"

namespace hrs::planning {

DecompositionSampler::DecompositionSampler(const rs::Decomposition& decomposition,
                                           const geometry::Scene& scene)
    : decomposition_(&decomposition) {
  const geometry::Box b = geometry::bounding_box(scene.room.polygon);
  cx_ = 0.5 * (b.xmin + b.xmax);
  cy_ = 0.5 * (b.ymin + b.ymax);
  // The decomposition samples x in [−W, W] for a room of width W (doubled
  // room, start at its centre): halve to land in the room's box.
  const auto& o = decomposition.options();
  sx_ = o.room_width > 0.0 ? 0.5 * (b.xmax - b.xmin) / o.room_width : 0.0;
  sy_ = o.room_depth > 0.0 ? 0.5 * (b.ymax - b.ymin) / o.room_depth : 0.0;
}

Pose2 DecompositionSampler::sample(std::mt19937_64& rng) {
  const auto& samples = decomposition_->samples();
  const std::size_t n = samples.size();
  const std::size_t i =
      std::min(n - 1, static_cast<std::size_t>(uniform01(rng) * static_cast<double>(n)));
  const Pose2& p = samples[i].pose;
  return {cx_ + sx_ * p.x, cy_ + sy_ * p.y, p.theta};
}

double DecompositionSteering::distance(const Pose2& from, const Pose2& to, double radius) {
  const double d = decomposition_->predicted_length(from, to);
  return std::isfinite(d) ? d : rs::shortest_length(from, to, radius);
}

rs::Path DecompositionSteering::path(const Pose2& from, const Pose2& to, double radius) {
  if (auto p = decomposition_->predicted_path(from, to)) return *std::move(p);
  return rs::shortest_path(from, to, radius);
}

}  // namespace hrs::planning
