// SPDX-License-Identifier: GPL-3.0-or-later
#include "planning/path_database.h"

#include "planning/moved_objects.h"

namespace hrs::planning {

const PathDatabase::Entry* PathDatabase::find(const LegKey& key) const {
  const auto it = entries_.find(key);
  return it == entries_.end() ? nullptr : &it->second;
}

std::optional<rs::Path> PathDatabase::transformed(const LegKey& key, const Pose2& from,
                                                  const Pose2& to) const {
  const Entry* e = find(key);
  if (!e) return std::nullopt;
  if (pose_gap(relative_pose(e->from, e->to), relative_pose(from, to)) > kRigidTolerance)
    return std::nullopt;
  return e->path;  // segments are intrinsic: driven from `from` they end at `to`
}

void PathDatabase::put(const LegKey& key, const Pose2& from, const Pose2& to, const rs::Path& path,
                       std::vector<Pose2> checked) {
  Entry e{path, from, to, std::move(checked), {}};
  if (!e.checked.empty())
    for (const Pose2& p : rs::sample(from, path, kTraceStep)) e.trace.push_back(p.position());
  entries_[key] = std::move(e);
}

bool PathDatabase::still_free(const Entry& e, const geometry::CSpace& cspace,
                              const geometry::Scene& scene, double margin) {
  // The old poses blocked nothing then: only where the objects stand now counts.
  return moved_objects_clear(scene, e.checked, layout_of(cspace), e.trace, margin, false);
}

}  // namespace hrs::planning
