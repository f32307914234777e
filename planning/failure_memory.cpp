// SPDX-License-Identifier: GPL-3.0-or-later
#include "planning/failure_memory.h"

#include "planning/moved_objects.h"

namespace hrs::planning {

bool FailureMemory::repeats(const LegKey& key, const geometry::Pose2& from,
                            const geometry::Pose2& to, const geometry::CSpace& cspace) const {
  const auto it = failures_.find(key);
  if (it == failures_.end()) return false;
  const Failure& f = it->second;
  if (!(f.from == from) || !(f.to == to)) return false;
  // Where each moved object stood then and stands now: a query near a node
  // could have hit it then or could hit it now.
  return moved_objects_clear(*scene_, f.layout, layout_of(cspace), f.points, margin_, true);
}

void FailureMemory::record(const LegKey& key, const geometry::Pose2& from,
                           const geometry::Pose2& to, std::vector<geometry::Pose2> layout,
                           std::vector<geometry::Vec2> points) {
  failures_[key] = Failure{from, to, std::move(layout), std::move(points)};
}

int FailureMemory::failed_in_a_row(const LegKey& key) const {
  const auto it = in_a_row_.find(key);
  return it == in_a_row_.end() ? 0 : it->second;
}

void FailureMemory::count_fresh_plan(const LegKey& key, bool found) {
  if (found)
    in_a_row_.erase(key);
  else
    ++in_a_row_[key];
}

}  // namespace hrs::planning
