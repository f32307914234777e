// SPDX-License-Identifier: GPL-3.0-or-later
// Replaying the planning of recorded layouts (design.h, replay_planning):
// the planners compared on the same layouts, without an annealing.

#include <chrono>
#include <optional>
#include <stdexcept>

#include "optimize/design.h"
#include "optimize/tour_round.h"

namespace hrs::optimize {

namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}
}  // namespace

ReplayResult replay_planning(const geometry::Scene& scene,
                             const std::vector<std::vector<Pose2>>& layouts,
                             const DesignOptions& options) {
  ReplayResult out;
  const std::vector<Sequence> sequences = scene_sequences(scene);
  const auto t0 = Clock::now();
  TourRound round(scene, options, sequences);
  out.setup_s = seconds_since(t0);
  std::optional<planning::ReuseCounters> legs;
  for (std::size_t r = 0; r < layouts.size(); ++r) {
    const auto& poses = layouts[r];
    if (static_cast<int>(poses.size()) != round.cspace().object_count())
      throw std::invalid_argument("replay_planning: layout size differs from the scene's objects");
    round.place(poses);
    const auto p0 = Clock::now();
    out.tours_invalidated += round.plan(static_cast<int>(r), legs).dropped;
    out.planning_s += seconds_since(p0);
    for (const planning::Tour& t : round.tours()) {
      ++out.tours_total;
      if (!t.found) continue;
      ++out.tours_found;
      out.tour_length += t.metrics.length;
    }
  }
  out.layouts = static_cast<int>(layouts.size());
  if (round.reuse()) out.counters = round.reuse()->totals();
  return out;
}

}  // namespace hrs::optimize
