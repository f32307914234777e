// SPDX-License-Identifier: GPL-3.0-or-later
// The final polish of a design; see polish.h.

#include "optimize/polish.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "optimize/preferences.h"

namespace hrs::optimize {

namespace {

//! The objects related to `object` by a relation, ascending.
std::vector<int> partners(const geometry::Scene& scene, int object) {
  std::vector<int> out;
  for (const geometry::Relation& r : scene.relations) {
    const int a = scene.find_object(r.a), b = scene.find_object(r.b);
    if (a < 0 || b < 0) continue;
    if (a == object && std::find(out.begin(), out.end(), b) == out.end()) out.push_back(b);
    if (b == object && std::find(out.begin(), out.end(), a) == out.end()) out.push_back(a);
  }
  std::sort(out.begin(), out.end());
  return out;
}

//! True when a preference fixes the object's heading: a wall angle, a
//! relation angle, or facing a partner.
bool heading_fixed(const geometry::Scene& scene, int object) {
  const geometry::Object& o = scene.objects[static_cast<std::size_t>(object)];
  if (o.wall && o.wall->angle) return true;
  for (const geometry::Relation& r : scene.relations) {
    const int a = scene.find_object(r.a), b = scene.find_object(r.b);
    if (r.angle && (a == object || b == object)) return true;
    if (r.faces && a == object) return true;
  }
  return false;
}

//! Headings this close to square (radians, about 0.06°) are left alone.
constexpr double kSquareTolerance = 1e-3;

}  // namespace

PolishResult polish(const geometry::Scene& scene, const CostModel& model,
                    const std::vector<bool>& movable, std::vector<geometry::Pose2>& poses,
                    CostTerms& terms, const PolishHooks& hooks, int max_tries,
                    const std::atomic<bool>* stop) {
  PolishResult out;
  PreferenceReport report = check_preferences(scene, model, poses);
  // Two passes: a pose kept in the first can make a partner's pose meet its
  // relation in the second.
  for (int pass = 0; pass < 2 && report.met < report.total; ++pass) {
    for (std::size_t i = 0; i < poses.size(); ++i) {
      if (!movable[i] || out.tried >= max_tries || (stop && stop->load())) continue;
      const std::string& id = scene.objects[i].id;
      const bool unmet = std::any_of(report.checks.begin(), report.checks.end(),
                                     [&](const PreferenceCheck& c) {
                                       return !c.met && (c.object == id || c.other == id);
                                     });
      if (!unmet) continue;
      const int object = static_cast<int>(i);
      for (const geometry::Pose2& to : preferred_poses(scene, model, poses, object)) {
        if (out.tried >= max_tries || (stop && stop->load())) break;
        std::vector<geometry::Pose2> p = poses;
        p[i] = to;
        if (!hooks.valid(p, object)) continue;
        const PreferenceReport next = check_preferences(scene, model, p);
        // Alone, or with one relation partner moved to one of its own
        // preferred poses (a bed turned round with the TV that faces it).
        std::vector<std::pair<int, geometry::Pose2>> moves{{object, to}};
        PreferenceReport best = next;
        if (next.met <= report.met) {
          for (const int j : partners(scene, object)) {
            if (!movable[static_cast<std::size_t>(j)]) continue;
            for (const geometry::Pose2& to_j : preferred_poses(scene, model, p, j)) {
              std::vector<geometry::Pose2> q = p;
              q[static_cast<std::size_t>(j)] = to_j;
              if (!hooks.valid(q, j)) continue;
              PreferenceReport both = check_preferences(scene, model, q);
              if (both.met > best.met) {
                best = std::move(both);
                moves = {{object, to}, {j, to_j}};
              }
            }
          }
        }
        if (best.met <= report.met) continue;
        ++out.tried;
        std::vector<geometry::Pose2> q = poses;
        CostTerms t;
        for (const auto& [k, pose] : moves) {
          q[static_cast<std::size_t>(k)] = pose;
          hooks.place(k, pose);
        }
        t = hooks.plan(q);
        if (t.tours_found >= terms.tours_found) {
          poses = std::move(q);
          terms = t;
          report = std::move(best);
          ++out.kept;
          hooks.kept();
          break;
        }
        for (auto it = moves.rbegin(); it != moves.rend(); ++it)
          hooks.place(it->first, poses[static_cast<std::size_t>(it->first)]);
      }
    }
  }
  // Square to the room: an object whose heading no preference fixes is
  // turned to the nearest heading parallel or perpendicular to its nearest
  // wall (a lamp at 10° looks wrong to a designer), when the layout stays
  // valid, no preference is lost and the tours found stay found.
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const int object = static_cast<int>(i);
    if (!movable[i] || heading_fixed(scene, object) || out.tried >= max_tries ||
        (stop && stop->load()))
      continue;
    const double normal = model.wall_normal_angle(model.nearest_wall(object, poses[i]));
    const double off = geometry::wrap_angle(poses[i].theta - normal);
    const double square = std::round(off / (std::numbers::pi / 2)) * (std::numbers::pi / 2);
    if (std::abs(off - square) < kSquareTolerance) continue;
    std::vector<geometry::Pose2> p = poses;
    p[i].theta = geometry::wrap_angle(normal + square);
    if (!hooks.valid(p, object)) continue;
    PreferenceReport next = check_preferences(scene, model, p);
    if (next.met < report.met) continue;
    ++out.tried;
    hooks.place(object, p[i]);
    const CostTerms t = hooks.plan(p);
    if (t.tours_found >= terms.tours_found) {
      poses = std::move(p);
      terms = t;
      report = std::move(next);
      ++out.squared;
      hooks.kept();
    } else {
      hooks.place(object, poses[i]);
    }
  }
  return out;
}

}  // namespace hrs::optimize
