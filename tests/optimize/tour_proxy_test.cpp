// SPDX-License-Identifier: GPL-3.0-or-later
// The tour proxy (optimize/tour_proxy.h) against a brute force: every
// combination of one stop per visited object enumerated (no dynamic
// programme, no caches), with its own free test (winding numbers, where
// the proxy counts crossings), on 1000 scrambled layouts of the shipped
// rooms and the objects of each moved one or two at a time; and a
// chair too large for any stop, where every leg is charged as unfound.

#include "optimize/tour_proxy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>

#include "optimize/design.h"
#include "optimize/sequences.h"
#include "polish_support.h"
#include "rs/reeds_shepp.h"
#include "scramble.h"

namespace hrs::optimize {
namespace {

using geometry::Pose2;
using geometry::Vec2;

std::vector<std::vector<planning::GoalPose>> local_goals(const geometry::Scene& scene) {
  std::vector<std::vector<planning::GoalPose>> out;
  for (const geometry::Object& o : scene.objects) out.push_back(planning::local_goal_poses(scene, o));
  return out;
}

// Winding number of `poly` round `p` (non-zero: inside), a second method
// beside the proxy's crossing count.
int winding(Vec2 p, const geometry::Polygon& poly) {
  int w = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2 a = poly[i], b = poly[(i + 1) % poly.size()];
    const double side = (b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y);
    if (a.y <= p.y) {
      if (b.y > p.y && side > 0) ++w;
    } else if (b.y <= p.y && side < 0) {
      --w;
    }
  }
  return w;
}

// The proxy by enumeration (see tour_proxy.h for what it charges).
double brute_force(const geometry::Scene& scene, const CostModel& model,
                   const std::vector<std::vector<planning::GoalPose>>& local,
                   const std::vector<Pose2>& poses, int& turned_away) {
  const std::size_t n = poses.size();
  std::vector<geometry::Polygon> fp;
  for (std::size_t i = 0; i < n; ++i) {
    geometry::Object o = scene.objects[i];
    o.pose = poses[i];
    fp.push_back(geometry::world_footprint(o));
  }
  const auto is_free = [&](Vec2 p, std::size_t own) {
    if (winding(p, scene.room.polygon) == 0) return false;
    for (std::size_t j = 0; j < n; ++j)
      if (j != own && winding(p, fp[j]) != 0) return false;
    return true;
  };
  // Object i's free stops: per side, of that side's goal poses (in slot
  // order) placed with the object, the free one nearest the middle.
  const auto stops = [&](std::size_t i) {
    std::vector<Pose2> out;
    for (int side = 0; side < 4; ++side) {
      std::vector<planning::GoalPose> of;
      for (const auto& g : local[i])
        if (static_cast<int>(g.side) == side) of.push_back(g);
      if (of.empty()) continue;
      // The free one nearest the middle slot; of two equally near, the
      // lower.
      const double mid = static_cast<double>((of.size() - 1) / 2);
      std::optional<Pose2> best;
      double best_d = 0.0;
      for (std::size_t j = 0; j < of.size(); ++j) {
        const Pose2 l = of[j].pose;
        const Vec2 c = geometry::to_world(poses[i], l.position());
        const Pose2 s{c.x, c.y, geometry::wrap_angle(poses[i].theta + l.theta)};
        bool ok = is_free(c, i);
        for (const Vec2 v : geometry::chair_footprint(scene.wheelchair, s)) ok = ok && is_free(v, i);
        const double d = std::abs(static_cast<double>(j) - mid);
        if (!ok) {
          ++turned_away;
        } else if (!best || d < best_d) {
          best = s, best_d = d;
        }
      }
      if (best) out.push_back(*best);
    }
    return out;
  };
  const auto& w = scene.weights.path;
  const double r = scene.wheelchair.turning_radius;
  double total = 0.0;
  for (std::size_t k = 0; k < model.sequences().size(); ++k) {
    const auto& nodes = model.sequences()[k].nodes;
    const double legs = static_cast<double>(nodes.size() - 1);
    // The stops of each visit; visits without one are charged and skipped.
    std::vector<std::vector<Pose2>> visit;
    std::vector<double> alpha;
    double missed = 0.0;
    for (std::size_t i = 1; i < nodes.size(); ++i) {
      const int o = scene.find_object(nodes[i]);
      std::vector<Pose2> s = o >= 0 ? stops(static_cast<std::size_t>(o))
                                    : std::vector<Pose2>{geometry::door_start_pose(scene)};
      const double a = model.object_weight(nodes[i]);
      if (s.empty()) {
        missed += a * (w[0] * model.unfound_length() / legs + w[1] * model.unfound_length() / legs / r);
        continue;
      }
      visit.push_back(std::move(s));
      alpha.push_back(a);
    }
    double best = std::numeric_limits<double>::infinity();
    std::function<void(std::size_t, const Pose2&, double)> walk = [&](std::size_t v, const Pose2& at,
                                                                      double sum) {
      if (v == visit.size()) {
        best = std::min(best, sum);
        return;
      }
      for (const Pose2& s : visit[v])
        walk(v + 1, s,
             sum + alpha[v] * (w[0] * rs::shortest_length(at, s, r) +
                               w[1] * std::abs(geometry::wrap_angle(s.theta - at.theta))));
    };
    walk(0, geometry::door_start_pose(scene), 0.0);
    total += model.sequence_weight(static_cast<int>(k)) * (best + missed);
  }
  return total;
}

TEST(TourProxy, MatchesBruteForceOnScrambledRooms) {
  int layouts = 0, steps = 0, turned_away = 0;
  for (const char* file : {"bedroom.json", "office.json", "living_room.json", "l_studio.json"}) {
    const geometry::Scene scene =
        geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/scenes/" + file);
    const CostModel model = testing::bounded_model(scene);
    const auto local = local_goals(scene);
    const TourProxy proxy(scene, model, local);
    const std::vector<bool> movable = testing::movable_of(scene);
    for (std::uint64_t seed = 1; seed <= 250; ++seed) {
      geometry::Scene work = testing::scrambled(scene, movable, seed);
      if (seed % 2 == 0) work = testing::askew_free_headings(scene, work, movable, seed);
      const std::vector<Pose2> poses = testing::poses_of(work);
      const double want = brute_force(scene, model, local, poses, turned_away);
      const double got = proxy.value(poses);
      ASSERT_TRUE(std::isfinite(got)) << file << " seed " << seed;
      EXPECT_NEAR(got, want, 1e-9 * std::max(1.0, want)) << file << " seed " << seed;
      ++layouts;
      // Then one or two objects at a time moved to their poses in another
      // scrambled layout, as a chain moves them (the proxy's caches
      // recompute only what moved).
      const std::vector<Pose2> other =
          testing::poses_of(testing::scrambled(scene, movable, seed + 1000));
      std::vector<Pose2> step = poses;
      for (std::size_t i = 0; i < step.size(); i += 1 + seed % 2) {
        step[i] = other[i];
        if (seed % 3 == 0 && i + 1 < step.size()) step[i + 1] = other[i + 1];
        const double w = brute_force(scene, model, local, step, turned_away);
        EXPECT_NEAR(proxy.value(step), w, 1e-9 * std::max(1.0, w))
            << file << " seed " << seed << " step " << i;
        ++steps;
      }
    }
  }
  EXPECT_EQ(layouts, 1000);
  EXPECT_GT(steps, 3000);
  // The free test turned stops away (its two methods were compared).
  EXPECT_GT(turned_away, 100);
  std::printf("layouts %d, single moves %d, stops turned away %d\n", layouts, steps, turned_away);
}

TEST(TourProxy, ChargesEveryLegAsUnfoundWhenNoStopIsFree) {
  // A chair longer than the room: every stop's corners leave it.
  geometry::Scene scene =
      geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/scenes/bedroom.json");
  const CostModel model = testing::bounded_model(scene);
  const auto local = local_goals(scene);
  geometry::Scene huge = scene;
  huge.wheelchair.length = 100.0;
  const TourProxy proxy(huge, model, local);
  // By hand: each sequence's legs at α̂ · (w_l · U / legs + w_r · U / legs / r).
  const auto& w = scene.weights.path;
  const double u = model.unfound_length(), r = scene.wheelchair.turning_radius;
  double want = 0.0;
  for (std::size_t k = 0; k < model.sequences().size(); ++k) {
    const auto& nodes = model.sequences()[k].nodes;
    const double legs = static_cast<double>(nodes.size() - 1);
    double sum = 0.0;
    for (std::size_t i = 1; i < nodes.size(); ++i)
      sum += model.object_weight(nodes[i]) * (w[0] * u / legs + w[1] * u / legs / r);
    want += model.sequence_weight(static_cast<int>(k)) * sum;
  }
  EXPECT_GT(want, 0.0);
  EXPECT_NEAR(proxy.value(testing::poses_of(scene)), want, 1e-9 * want);
  // With the chair it has, the shipped layout's stops are free and the
  // proxy is far below that.
  const TourProxy normal(scene, model, local);
  EXPECT_LT(normal.value(testing::poses_of(scene)), 0.5 * want);
}

}  // namespace
}  // namespace hrs::optimize
