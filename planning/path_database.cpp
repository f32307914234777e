#include "planning/path_database.h"

#include <algorithm>

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
  if (e.checked.size() != static_cast<std::size_t>(cspace.object_count())) return false;
  const double m = margin;
  geometry::Polygon fp;
  for (int i = 0; i < cspace.object_count(); ++i) {
    const Pose2& now = cspace.object_pose(i);
    if (now == e.checked[i]) continue;
    // The footprint where the object stands now, and its box grown by m.
    fp.clear();
    double xmin = 1e300, ymin = 1e300, xmax = -1e300, ymax = -1e300;
    for (const geometry::Vec2& v : scene.objects[i].footprint) {
      fp.push_back(geometry::to_world(now, v));
      xmin = std::min(xmin, fp.back().x), ymin = std::min(ymin, fp.back().y);
      xmax = std::max(xmax, fp.back().x), ymax = std::max(ymax, fp.back().y);
    }
    for (const geometry::Vec2& p : e.trace) {
      if (p.x < xmin - m || p.x > xmax + m || p.y < ymin - m || p.y > ymax + m) continue;
      if (geometry::point_in_polygon(p, fp)) return false;
      for (std::size_t k = 0, j = fp.size() - 1; k < fp.size(); j = k++)
        if (geometry::point_segment_distance(p, fp[j], fp[k]) <= m) return false;
    }
  }
  return true;
}

}  // namespace hrs::planning
