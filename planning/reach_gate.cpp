// SPDX-License-Identifier: GPL-3.0-or-later
#include "planning/reach_gate.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace hrs::planning {

ReachGate::ReachGate(const geometry::Scene& scene, const geometry::CSpace& cspace,
                     ReachGateOptions options)
    : scene_(&scene),
      cspace_(&cspace),
      options_(options),
      door_(geometry::door_start_pose(scene)) {
  const geometry::Box b = geometry::bounding_box(scene.room.polygon);
  diagonal_ = std::max(1e-9, std::hypot(b.xmax - b.xmin, b.ymax - b.ymin));
}

ReachGate::~ReachGate() = default;

void ReachGate::invalidate() {
  std::lock_guard lock(mutex_);
  current_ = false;
}

const geometry::ReachableSet* ReachGate::door_reach() const {
  std::lock_guard lock(mutex_);
  if (unavailable_) return nullptr;
  if (current_) return &reach_;
  const auto t0 = std::chrono::steady_clock::now();
  if (!grid_) {
    try {
      grid_ = std::make_unique<geometry::FreeGrid>(*scene_, options_.grid);
    } catch (const std::invalid_argument&) {
      unavailable_ = true;  // cells too coarse for this chair: no answers
      return nullptr;
    }
    if (!grid_->has_column_masks()) {
      unavailable_ = true;
      return nullptr;
    }
  }
  for (int i = 0; i < cspace_->object_count(); ++i) grid_->move_object(i, cspace_->object_pose(i));
  reach_.fill(*grid_, door_);
  current_ = true;
  ++fills_;
  fill_ms_ +=
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return &reach_;
}

bool ReachGate::refuses(const geometry::Pose2& from, const geometry::Pose2& to) const {
  const geometry::ReachableSet* reach = door_reach();
  return reach && reach->contains(from) != reach->contains(to);
}

double ReachGate::blockage(std::span<const GoalPose> goals) const {
  const geometry::ReachableSet* reach = door_reach();
  if (!reach || goals.empty()) return 1.0;
  double d = std::numeric_limits<double>::infinity();
  for (const GoalPose& g : goals) {
    if (reach->contains(g.pose)) return 0.0;
    d = std::min(d, reach->distance_to(g.pose));
  }
  return 0.5 + 0.5 * std::min(1.0, d / diagonal_);
}

bool ReachGate::walls_off(std::span<const GoalPose> goals) const {
  if (goals.empty()) return true;
  const geometry::ReachableSet* reach = door_reach();
  if (!reach || !reach->contains(door_)) return false;
  for (const GoalPose& g : goals)
    if (reach->contains(g.pose)) return false;
  return true;
}

std::vector<int> ReachGate::bordering(double within) const {
  std::vector<int> out;
  const geometry::ReachableSet* reach = door_reach();
  if (!reach) return out;
  constexpr double kStep = 0.1;  // metres between the footprint points tried
  for (int i = 0; i < cspace_->object_count(); ++i) {
    geometry::Object o = scene_->objects[i];
    o.pose = cspace_->object_pose(i);
    const geometry::Polygon fp = geometry::world_footprint(o);
    bool near = false;
    for (std::size_t e = 0; e < fp.size() && !near; ++e) {
      const geometry::Vec2 a = fp[e], b = fp[(e + 1) % fp.size()];
      const int n = std::max(1, static_cast<int>(std::ceil(geometry::norm(b - a) / kStep)));
      for (int s = 0; s < n && !near; ++s) {
        const geometry::Vec2 p = a + (static_cast<double>(s) / n) * (b - a);
        near = reach->distance_to({p.x, p.y, 0.0}) <= within;
      }
    }
    if (near) out.push_back(i);
  }
  return out;
}

std::uint64_t ReachGate::fills() const {
  std::lock_guard lock(mutex_);
  return fills_;
}

double ReachGate::fill_ms() const {
  std::lock_guard lock(mutex_);
  return fill_ms_;
}

}  // namespace hrs::planning
