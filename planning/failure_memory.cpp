#include "planning/failure_memory.h"

namespace hrs::planning {

bool FailureMemory::repeats(const LegKey& key, const geometry::Pose2& from,
                            const geometry::Pose2& to, const geometry::CSpace& cspace) const {
  const auto it = failures_.find(key);
  if (it == failures_.end()) return false;
  const Failure& f = it->second;
  if (!(f.from == from) || !(f.to == to)) return false;
  for (int i = 0; i < cspace.object_count(); ++i) {
    const geometry::Pose2& now = cspace.object_pose(i);
    if (now == f.layout[i]) continue;
    // Where the object stood then and stands now, each box grown by the
    // queries' reach, must hold none of the run's query centres.
    for (const geometry::Pose2& pose : {f.layout[i], now}) {
      geometry::Object o = scene_->objects[i];
      o.pose = pose;
      geometry::Box b = geometry::bounding_box(geometry::world_footprint(o));
      b.xmin -= reach_, b.ymin -= reach_, b.xmax += reach_, b.ymax += reach_;
      for (const geometry::Vec2& p : f.points)
        if (p.x >= b.xmin && p.x <= b.xmax && p.y >= b.ymin && p.y <= b.ymax) return false;
    }
  }
  return true;
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
