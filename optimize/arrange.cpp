// SPDX-License-Identifier: GPL-3.0-or-later
// The preference arrangement; see arrange.h.

#include "optimize/arrange.h"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <memory>

#include "geometry/polygon_ops.h"
#include "optimize/preferences.h"

namespace hrs::optimize {

namespace {

//! True when some edge normal of `a` or `b` separates them by more than `gap`.
bool separated(const geometry::Polygon& a, const geometry::Polygon& b, double gap) {
  return geometry::any_edge_axis(a, b, [gap](double overlap) { return overlap < -gap; });
}

}  // namespace

TourCorridor::TourCorridor(const geometry::Wheelchair& chair,
                           const std::vector<planning::Tour>& tours, double margin, double cell)
    : margin_(margin), cell_(cell) {
  for (const planning::Tour& t : tours) {
    if (!t.found) continue;
    for (const planning::Leg& leg : t.legs)
      for (const geometry::Pose2& w : leg.waypoints) {
        shapes_.push_back(geometry::chair_footprint(chair, w));
        boxes_.push_back(geometry::bounding_box(shapes_.back()));
      }
  }
  if (shapes_.empty()) return;
  double x1 = -1e300, y1 = -1e300;
  x0_ = y0_ = 1e300;
  for (const geometry::Box& b : boxes_) {
    x0_ = std::min(x0_, b.xmin);
    y0_ = std::min(y0_, b.ymin);
    x1 = std::max(x1, b.xmax);
    y1 = std::max(y1, b.ymax);
  }
  nx_ = std::max(1, static_cast<int>(std::ceil((x1 - x0_) / cell_)));
  ny_ = std::max(1, static_cast<int>(std::ceil((y1 - y0_) / cell_)));
  cells_.assign(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_), {});
  for (std::size_t s = 0; s < boxes_.size(); ++s) {
    const geometry::Box& b = boxes_[s];
    const int i0 = std::clamp(static_cast<int>((b.xmin - x0_) / cell_), 0, nx_ - 1);
    const int i1 = std::clamp(static_cast<int>((b.xmax - x0_) / cell_), 0, nx_ - 1);
    const int j0 = std::clamp(static_cast<int>((b.ymin - y0_) / cell_), 0, ny_ - 1);
    const int j1 = std::clamp(static_cast<int>((b.ymax - y0_) / cell_), 0, ny_ - 1);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i)
        cells_[static_cast<std::size_t>(j) * static_cast<std::size_t>(nx_) +
               static_cast<std::size_t>(i)]
            .push_back(static_cast<int>(s));
  }
}

std::size_t TourCorridor::near(const geometry::Polygon& footprint, std::size_t limit) const {
  if (shapes_.empty()) return 0;
  const geometry::Polygon h = geometry::convex_hull_doubles(footprint);
  geometry::Box b = geometry::bounding_box(h);
  b.xmin -= margin_;
  b.ymin -= margin_;
  b.xmax += margin_;
  b.ymax += margin_;
  const int i0 = static_cast<int>(std::floor((b.xmin - x0_) / cell_));
  const int i1 = static_cast<int>(std::floor((b.xmax - x0_) / cell_));
  const int j0 = static_cast<int>(std::floor((b.ymin - y0_) / cell_));
  const int j1 = static_cast<int>(std::floor((b.ymax - y0_) / cell_));
  // A footprint listed in several cells counts once.
  std::vector<int> hit;
  for (int j = std::max(0, j0); j <= std::min(ny_ - 1, j1); ++j)
    for (int i = std::max(0, i0); i <= std::min(nx_ - 1, i1); ++i)
      for (const int s : cells_[static_cast<std::size_t>(j) * static_cast<std::size_t>(nx_) +
                                static_cast<std::size_t>(i)]) {
        const geometry::Box& c = boxes_[static_cast<std::size_t>(s)];
        if (c.xmin > b.xmax || c.xmax < b.xmin || c.ymin > b.ymax || c.ymax < b.ymin) continue;
        if (std::find(hit.begin(), hit.end(), s) != hit.end()) continue;
        if (separated(h, shapes_[static_cast<std::size_t>(s)], margin_)) continue;
        hit.push_back(s);
        if (hit.size() >= limit) return hit.size();
      }
  return hit.size();
}

bool TourCorridor::clear(const geometry::Polygon& footprint) const { return near(footprint, 1) == 0; }

std::size_t TourCorridor::blocked(const geometry::Polygon& footprint) const {
  return near(footprint, shapes_.size());
}

ArrangeResult arrange(const CostModel& model, const std::vector<bool>& movable,
                      const std::vector<geometry::Pose2>& poses, const AnnealOptions& moves,
                      const ArrangeOptions& options, const ArrangeHooks& hooks,
                      std::uint64_t seed, const std::atomic<bool>* stop) {
  assert(hooks.valid && hooks.set);
  ArrangeResult out;
  const auto interior = [&](const std::vector<geometry::Pose2>& p) {
    return model.interior_terms(model.interior(p)).total() + (options.extra ? options.extra(p) : 0.0);
  };
  out.interior_before = interior(poses);
  out.poses = poses;
  out.interior_after = out.interior_before;
  const int n = static_cast<int>(std::count(movable.begin(), movable.end(), true));
  if (n == 0 || !(out.interior_before > 0.0)) return out;

  AnnealOptions schedule = moves;
  schedule.iterations = options.iterations_per_object * n;
  schedule.t_start = std::max(1e-9, options.t_start_fraction * out.interior_before);
  schedule.t_end = schedule.t_start * options.t_end_ratio;
  AnnealCallbacks cb;
  cb.move_valid = hooks.valid;
  cb.cost = [&](const std::vector<geometry::Pose2>& p, const Move& move, const Acceptance&) {
    if (move.object >= 0) hooks.set(move.object, move.to);
    return interior(p);
  };
  cb.rejected = [&](const Move& move) { hooks.set(move.object, move.from); };
  cb.preferred = hooks.preferred;
  // A seed of its own, so that the tour annealing's draws are those of its
  // seed whatever the arrangement drew.
  std::mt19937_64 rng(seed ^ 0x9e3779b97f4a7c15ULL);
  const AnnealResult r = anneal(poses, movable, schedule, cb, rng, stop);
  for (std::size_t i = 0; i < poses.size(); ++i)
    if (r.final_poses[i] != poses[i]) hooks.set(static_cast<int>(i), poses[i]);
  out.proposals = r.proposals;
  out.accepted = r.accepted;
  if (r.best_valid && r.best_cost < out.interior_before) {
    out.poses = r.best;
    out.interior_after = r.best_cost;
  }
  return out;
}

std::function<double(const std::vector<geometry::Pose2>& poses)> opening_pull(
    const geometry::Scene& scene, const CostModel& model, const std::vector<bool>& movable) {
  std::vector<int> loose;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const auto& wall = scene.objects[i].wall;
    if (movable[i] && !(wall && wall->distance)) loose.push_back(static_cast<int>(i));
  }
  if (loose.empty()) return {};
  const int edges = static_cast<int>(scene.room.polygon.size());
  // Each loose object's term at the pose it was last computed for: a
  // proposal moves one object, so one term is computed again (the others
  // are compared by pose only).
  struct Term {
    geometry::Pose2 at;
    double value = -1.0;
  };
  auto terms = std::make_shared<std::vector<Term>>(loose.size());
  return [&scene, &model, loose, edges, terms](const std::vector<geometry::Pose2>& poses) {
    double energy = 0.0;
    for (std::size_t k = 0; k < loose.size(); ++k) {
      const auto i = static_cast<std::size_t>(loose[k]);
      Term& t = (*terms)[k];
      if (t.value < 0.0 || t.at != poses[i]) {
        geometry::Object o = scene.objects[i];
        o.pose = poses[i];
        const geometry::Polygon footprint = geometry::world_footprint(o);
        double d = 1.0;
        for (int e = 0; e < edges && d > 0.0; ++e) d = std::min(d, model.wall_distance(footprint, e));
        t = {poses[i], kOpeningPull * d};
      }
      energy += t.value;
    }
    return energy;
  };
}

int opening_proposals_per_object(const geometry::Scene& scene) {
  std::size_t vertices = 0;
  for (const auto& o : scene.objects) vertices += o.footprint.size();
  const ArrangeOptions defaults;
  const std::size_t per_object = static_cast<std::size_t>(defaults.iterations_per_object);
  if (vertices * per_object <= kOpeningWork) return defaults.iterations_per_object;
  return static_cast<int>(kOpeningWork / vertices);
}

ArrangeReport arrange_toured(const geometry::Scene& scene, const CostModel& model,
                             const std::vector<bool>& movable,
                             const std::vector<planning::Tour>& tours,
                             std::vector<geometry::Pose2>& poses, CostTerms& terms,
                             const AnnealOptions& moves, const ArrangeHooks& hooks,
                             const ToursHooks& toured, std::uint64_t seed,
                             const std::atomic<bool>* stop) {
  ArrangeReport report;
  report.rounds = 1;
  report.met_before = report.met_after = check_preferences(scene, model, poses).met;
  report.tours_found_before = report.tours_found_after = terms.tours_found;
  std::vector<bool> free = movable;
  for (const planning::Tour& t : tours)
    if (t.found)
      for (const std::string& id : t.sequence)
        if (const int k = scene.find_object(id); k >= 0) free[static_cast<std::size_t>(k)] = false;
  const TourCorridor corridor(scene.wheelchair, tours);
  ArrangeHooks clear = hooks;
  clear.valid = [&](const std::vector<geometry::Pose2>& p, int moved) {
    geometry::Object o = scene.objects[static_cast<std::size_t>(moved)];
    o.pose = p[static_cast<std::size_t>(moved)];
    return corridor.clear(geometry::world_footprint(o)) && hooks.valid(p, moved);
  };
  const auto t0 = std::chrono::steady_clock::now();
  const ArrangeResult a = arrange(model, free, poses, moves, {}, clear, seed, stop);
  report.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  report.proposals = a.proposals;
  if (a.poses == poses || (stop && stop->load())) return report;
  const auto place_all = [&](const std::vector<geometry::Pose2>& from,
                             const std::vector<geometry::Pose2>& to) {
    for (std::size_t i = 0; i < to.size(); ++i)
      if (from[i] != to[i]) toured.place(static_cast<int>(i), to[i]);
  };
  place_all(poses, a.poses);
  const CostTerms t = toured.plan(a.poses);
  report.met_after = check_preferences(scene, model, a.poses).met;
  report.tours_found_after = t.tours_found;
  report.kept = t.tours_found >= terms.tours_found && t.total() < terms.total();
  if (report.kept) {
    report.rounds_kept = 1;
    poses = a.poses;
    terms = t;
  } else {
    place_all(a.poses, poses);
  }
  return report;
}

}  // namespace hrs::optimize
