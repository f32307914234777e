// SPDX-License-Identifier: GPL-3.0-or-later
// A tour-length proxy of a layout; see tour_proxy.h.

#include "optimize/tour_proxy.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rs/reeds_shepp.h"

namespace hrs::optimize {

TourProxy::TourProxy(const geometry::Scene& scene, const CostModel& model,
                     const std::vector<std::vector<planning::GoalPose>>& local)
    : scene_(scene), model_(model), door_(geometry::door_start_pose(scene)) {
  for (const auto& goals : local) {
    std::vector<std::vector<geometry::Pose2>> sides;
    for (int side = 0; side < 4; ++side) {
      std::vector<const planning::GoalPose*> of;
      for (const planning::GoalPose& g : goals)
        if (static_cast<int>(g.side) == side) of.push_back(&g);
      if (of.empty()) continue;
      // From the middle outwards, the nearer of two equally far first.
      const std::size_t mid = (of.size() - 1) / 2;
      std::vector<geometry::Pose2> order;
      for (std::size_t d = 0; order.size() < of.size(); ++d) {
        if (d <= mid) order.push_back(of[mid - d]->pose);
        if (d > 0 && mid + d < of.size()) order.push_back(of[mid + d]->pose);
      }
      sides.push_back(std::move(order));
    }
    stops_.push_back(std::move(sides));
  }
  stops_.resize(scene.objects.size());
  for (const geometry::Object& o : scene.objects) alpha_.push_back(model.object_weight(o.id));
  for (const Sequence& s : model.sequences()) {
    std::vector<int> n;
    for (std::size_t i = 0; i < s.nodes.size(); ++i)
      n.push_back(i == 0 ? -1 : scene.find_object(s.nodes[i]));
    nodes_.push_back(std::move(n));
  }
  // The distinct legs (ordered pairs of nodes), for the leg cache. A visit
  // without free stops is skipped, so a sequence's leg into object c can
  // start at any node before it: every ordered pair of a sequence is listed.
  // Nodes are -1 (the door) to objects − 1: a dense table finds a listed leg
  // in one step (a scene at the format's limits lists millions of pairs).
  const std::size_t side = scene.objects.size() + 1;
  std::vector<int> listed(side * side, -1);
  for (const auto& n : nodes_) {
    std::vector<int> ids(n.size() * n.size(), -1);
    for (std::size_t i = 0; i < n.size(); ++i)
      for (std::size_t j = i + 1; j < n.size(); ++j) {
        int& id = listed[static_cast<std::size_t>(n[i] + 1) * side + static_cast<std::size_t>(n[j] + 1)];
        if (id < 0) {
          id = static_cast<int>(leg_cache_.size());
          leg_cache_.push_back(Leg{n[i], n[j], {}, {}, {}, false});
        }
        ids[i * n.size() + j] = id;
      }
    legs_.push_back(std::move(ids));
  }
}

double TourProxy::value(const std::vector<geometry::Pose2>& poses) const {
  const std::size_t n = scene_.objects.size();
  const auto overlap = [](const geometry::Box& a, const geometry::Box& b) {
    return a.xmin <= b.xmax && b.xmin <= a.xmax && a.ymin <= b.ymax && b.ymin <= a.ymax;
  };
  // The objects that moved since the last call (all, the first time): their
  // footprints, and the boxes round where their stops' chairs can stand.
  std::vector<geometry::Box> was;  // the moved objects' old and new boxes
  std::vector<char> recheck(n, cached_ ? 0 : 1);
  if (!cached_) {
    at_ = poses;
    fp_.assign(n, {});
    box_.assign(n, {});
    reach_.assign(n, {});
    free_.assign(n, {});
    seq_.assign(nodes_.size(), 0.0);
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (cached_ && poses[i] == at_[i]) continue;
    if (cached_) was.push_back(box_[i]);
    recheck[i] = 1;
    at_[i] = poses[i];
    geometry::Object o = scene_.objects[i];
    o.pose = poses[i];
    fp_[i] = geometry::world_footprint(o);
    box_[i] = geometry::bounding_box(fp_[i]);
    std::vector<geometry::Vec2> reach;
    for (const auto& side : stops_[i])
      for (const geometry::Pose2& l : side) {
        const geometry::Vec2 c = geometry::to_world(poses[i], l.position());
        const geometry::Pose2 st{c.x, c.y, geometry::wrap_angle(poses[i].theta + l.theta)};
        for (const geometry::Vec2 v : geometry::chair_footprint(scene_.wheelchair, st)) reach.push_back(v);
        reach.push_back(c);
      }
    reach_[i] = geometry::bounding_box(reach);
    if (cached_) was.push_back(box_[i]);
  }
  const bool first = !cached_;
  cached_ = true;
  // A stop's free test looks at points inside its object's reach box, and
  // a footprint only answers for points in its own box: an object that did
  // not move keeps its free stops unless a moved footprint's old or new
  // box meets its reach.
  for (std::size_t u = 0; u < n && !first; ++u)
    for (std::size_t b = 0; b < was.size() && !recheck[u]; ++b)
      recheck[u] = overlap(reach_[u], was[b]);
  const auto blocked = [&](geometry::Vec2 p, std::size_t own) {
    if (!geometry::point_in_polygon(p, scene_.room.polygon)) return true;
    for (std::size_t j = 0; j < n; ++j) {
      if (j == own) continue;
      const geometry::Box& b = box_[j];
      if (p.x < b.xmin || p.x > b.xmax || p.y < b.ymin || p.y > b.ymax) continue;
      if (geometry::point_in_polygon(p, fp_[j])) return true;
    }
    return false;
  };
  std::vector<char> changed(n, first ? 1 : 0);  // free stops differ from the last call's
  std::vector<geometry::Pose2> now;
  for (std::size_t u = 0; u < n; ++u) {
    if (!recheck[u]) continue;
    now.clear();
    for (const std::vector<geometry::Pose2>& side : stops_[u])
      for (const geometry::Pose2& l : side) {
        const geometry::Vec2 c = geometry::to_world(poses[u], l.position());
        const geometry::Pose2 st{c.x, c.y, geometry::wrap_angle(poses[u].theta + l.theta)};
        bool free = !blocked(c, u);
        for (const geometry::Vec2 v : geometry::chair_footprint(scene_.wheelchair, st))
          free = free && !blocked(v, u);
        if (free) {
          now.push_back(st);
          break;
        }
      }
    if (now != free_[u]) {
      free_[u] = now;
      changed[u] = 1;
    }
  }
  const std::vector<geometry::Pose2> door{door_};
  const auto stops_of = [&](int o) -> const std::vector<geometry::Pose2>& {
    return o >= 0 ? free_[static_cast<std::size_t>(o)] : door;
  };
  const auto& w = scene_.weights.path;
  const double radius = scene_.wheelchair.turning_radius;
  // Leg l's cost matrix, recomputed when either end's free stops changed.
  const auto leg = [&](int l) -> const std::vector<double>& {
    Leg& g = leg_cache_[static_cast<std::size_t>(l)];
    const auto& a = stops_of(g.from);
    const auto& b = stops_of(g.to);
    if (g.valid && g.from_stops == a && g.to_stops == b) return g.cost;
    g.from_stops = a, g.to_stops = b, g.valid = true;
    g.cost.resize(a.size() * b.size());
    for (std::size_t s = 0; s < a.size(); ++s)
      for (std::size_t t = 0; t < b.size(); ++t)
        g.cost[s * b.size() + t] = w[0] * rs::shortest_length(a[s], b[t], radius) +
                                   w[1] * std::abs(geometry::wrap_angle(b[t].theta - a[s].theta));
    return g.cost;
  };
  double total = 0.0;
  std::vector<double> cost, next;
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    const std::vector<int>& nodes = nodes_[k];
    const std::size_t m = nodes.size();
    // A sequence none of whose objects' free stops changed keeps its value.
    if (std::none_of(nodes.begin(), nodes.end(),
                     [&](int o) { return o >= 0 && changed[static_cast<std::size_t>(o)]; }) &&
        !first) {
      total += seq_[k];
      continue;
    }
    const double legs_in = static_cast<double>(std::max<std::size_t>(1, m - 1));
    std::size_t last = 0;  // the node the chair stands at
    cost.assign(1, 0.0);
    double missed = 0.0;  // legs charged as unfound
    for (std::size_t i = 1; i < m; ++i) {
      const int o = nodes[i];
      const double a = o >= 0 ? alpha_[static_cast<std::size_t>(o)] : 0.0;
      const std::size_t to = stops_of(o).size();
      if (to == 0) {
        missed += a * (w[0] * model_.unfound_length() / legs_in +
                       w[1] * model_.unfound_length() / legs_in / radius);
        continue;
      }
      const std::vector<double>& c = leg(legs_[k][last * m + i]);
      next.assign(to, std::numeric_limits<double>::infinity());
      for (std::size_t s = 0; s < cost.size(); ++s)
        for (std::size_t t = 0; t < to; ++t) next[t] = std::min(next[t], cost[s] + a * c[s * to + t]);
      cost.swap(next);
      last = i;
    }
    seq_[k] = model_.sequence_weight(static_cast<int>(k)) *
              (*std::min_element(cost.begin(), cost.end()) + missed);
    total += seq_[k];
  }
  return total;
}

}  // namespace hrs::optimize
