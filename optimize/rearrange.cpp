// SPDX-License-Identifier: GPL-3.0-or-later
// Rearrangements over the preferences alone; see rearrange.h.

#include "optimize/rearrange.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <string>

#include "geometry/polygon_ops.h"
#include "geometry/random.h"
#include "optimize/squaring.h"

namespace hrs::optimize {

namespace {

//! Chains run, Metropolis steps per movable object (at most kMaxSteps a
//! chain), the temperature's start and end (in units of the score), what a
//! metre moved costs, and what a moved object in the kept tours' corridor
//! costs.
constexpr int kChains = 8;
constexpr int kStepsPerObject = 400;
constexpr int kMaxSteps = 2000;
constexpr double kHot = 1.0;
constexpr double kCold = 0.1;
//! The shorter tours' chains start from a layout whose score they must
//! keep, and run colder: as hot as the others, they wandered off with most
//! of a room's objects moved (16 to 18 of zoo room 310's), whose planned
//! tours the proxy no longer foretold (docs/BENCHMARKS.md, 2026-11-30,
//! "shorter tours").
constexpr double kHotShorter = 0.3;
constexpr double kColdShorter = 0.03;
constexpr double kMetre = 0.05;
constexpr double kInCorridor = 0.5;

//! The share of steps whose object is drawn among all movable objects,
//! not only those with an unmet preference.
constexpr double kAnyObject = 0.25;

//! How far an object without preferences is drawn from where it stands
//! (metres): far enough to leave a place or the approach to it, near
//! enough to keep the tours round it.
constexpr double kAsideRadius = 1.0;

//! Draws a holder makes for a place of its own before the step is dropped.
constexpr int kHolderDraws = 8;

}  // namespace

int gross_misses(const PreferenceReport& r) {
  int n = 0;
  for (const PreferenceCheck& c : r.checks) n += c.angular() && c.residual > kGrossAngle;
  return n;
}

int polish_score(const PreferenceReport& r) { return r.met - gross_misses(r); }

std::vector<int> holders(const geometry::Scene& scene, const std::vector<geometry::Pose2>& poses,
                         int object) {
  geometry::Object o = scene.objects[static_cast<std::size_t>(object)];
  o.pose = poses[static_cast<std::size_t>(object)];
  const geometry::Polygon f = geometry::world_footprint(o);
  std::vector<int> found;
  for (std::size_t j = 0; j < poses.size() && found.size() < 3; ++j) {
    if (static_cast<int>(j) == object) continue;
    geometry::Object other = scene.objects[j];
    other.pose = poses[j];
    if (geometry::overlap_beyond_contact(f, geometry::world_footprint(other)))
      found.push_back(static_cast<int>(j));
  }
  return found;
}

std::vector<Rearrangement> rearrangements(const geometry::Scene& scene, const CostModel& model,
                                          const std::vector<bool>& movable,
                                          const std::vector<geometry::Pose2>& poses,
                                          const PreferenceReport& report,
                                          const RearrangeHooks& hooks,
                                          const std::atomic<bool>* stop, RearrangeGoal goal) {
  std::vector<Rearrangement> found;
  const int gross0 = gross_misses(report), score0 = polish_score(report);
  const bool fewer_gross = goal == RearrangeGoal::kFewerGross;
  const bool shorter = goal == RearrangeGoal::kShorterTours;
  if (shorter ? !hooks.tour_proxy : fewer_gross ? gross0 == 0 : report.met == report.total)
    return found;
  // The tour proxy of a layout (0 but for kShorterTours).
  const auto proxy_of = [&](const std::vector<geometry::Pose2>& q) {
    return shorter ? hooks.tour_proxy(q) : 0.0;
  };
  const double proxy0 = proxy_of(poses);
  // Whether a layout with report `r` and tour proxy `p` meets the goal.
  const auto meets = [&](const PreferenceReport& r, double p) {
    if (shorter)
      return polish_score(r) >= score0 && gross_misses(r) <= gross0 &&
             p < proxy0 * (1.0 - kProxyMargin);
    return fewer_gross ? gross_misses(r) < gross0 && polish_score(r) >= score0
                       : polish_score(r) > score0 && gross_misses(r) <= gross0;
  };
  std::vector<int> free_objects;
  for (std::size_t i = 0; i < poses.size(); ++i)
    if (movable[i]) free_objects.push_back(static_cast<int>(i));
  if (free_objects.empty()) return found;
  // What object k at `a` adds to the energy (zero where it was).
  const auto moved_cost = [&](int k, const geometry::Pose2& a) {
    const geometry::Pose2& b = poses[static_cast<std::size_t>(k)];
    if (a == b) return 0.0;
    return kMetre * std::hypot(a.x - b.x, a.y - b.y) + (hooks.clear(k, a) ? 0.0 : kInCorridor);
  };
  // `at` with object k's heading turned square to the wall nearest it in
  // `at` (the nearest multiple of 90° from that wall's normal) when no
  // preference fixes it. Its wall places (computed once, from where it
  // stands, and keeping that heading on every wall), its places round its
  // partners and its aside draws take that heading: square on every wall
  // of an axis-parallel room, as a designer would put an armchair (taken to
  // another wall with the heading it had, it stood 42° off square there).
  // A wall at another angle, or the place a moved object leaves (a
  // holder's fallback, with that object's heading), can still leave it
  // askew; square_moved() turns such objects of a chain's best layout.
  // Only the higher score's (and the shorter tours') chains square: a
  // layout they find is kept only
  // at no higher cost, and the squaring after the polish's other stages
  // then finds the object where it was left. The fewer gross misses'
  // chains keep every heading they do not mean to mend: a turned object's
  // front, where the wheelchair stops, moves with it, and squared draws
  // there left more layouts losing a tour (zoo seeds 1-3, gross misses in
  // 6 designs against 2; docs/BENCHMARKS.md 2026-11-30, "square headings
  // in the higher-score rearrangement").
  std::vector<bool> free_heading(poses.size(), false);
  for (std::size_t k = 0; k < poses.size() && !fewer_gross; ++k)
    free_heading[k] = movable[k] && !heading_fixed(scene, static_cast<int>(k));
  const auto squared = [&](int k, const std::vector<geometry::Pose2>& at) {
    std::vector<geometry::Pose2> out = at;
    geometry::Pose2& p = out[static_cast<std::size_t>(k)];
    if (!free_heading[static_cast<std::size_t>(k)]) return out;
    const double normal = model.wall_normal_angle(model.nearest_wall(k, p));
    const double quarter = std::numbers::pi / 2;
    p.theta = geometry::wrap_angle(
        normal + std::round(geometry::wrap_angle(p.theta - normal) / quarter) * quarter);
    return out;
  };
  // Each object's wall places, computed once from the layout searched from,
  // its heading squared (an object with a wall distance and no wall angle
  // keeps its heading there).
  std::vector<std::optional<std::vector<geometry::Pose2>>> slides(poses.size());
  const auto slides_of = [&](int k) -> const std::vector<geometry::Pose2>& {
    auto& w = slides[static_cast<std::size_t>(k)];
    if (!w) {
      const std::vector<geometry::Pose2> from = squared(k, poses);
      w = wall_slides(scene, model, from, k, kWallSlideStep);
      // A free object's places round its relation partners instead.
      if (w->empty()) w = relation_slides(scene, from, k, kWallSlideStep);
    }
    return *w;
  };
  const geometry::Box box = geometry::bounding_box(scene.room.polygon);
  // A place for object k (now at `now`): half the draws among its
  // `preferred` poses, half among its wall places (or places round its
  // partners) and `extra` (when given). An object with none of these (no
  // preference: a chair, an armchair) gets a uniform position within
  // kAsideRadius of where it stands, with its heading, in half the draws
  // when `extra` is given: such an object would otherwise never leave a
  // place another needs, nor the way to it.
  const auto draw = [&](std::mt19937_64& rng, const std::vector<geometry::Pose2>& preferred, int k,
                        const geometry::Pose2& now,
                        const geometry::Pose2* extra) -> std::optional<geometry::Pose2> {
    const std::vector<geometry::Pose2>& walls = slides_of(k);
    if (preferred.empty() && walls.empty() && (!extra || uniform01(rng) < 0.5)) {
      // Uniform in the disc of kAsideRadius round it, in the room's box.
      const double r = kAsideRadius * std::sqrt(uniform01(rng));
      const double a = 2.0 * std::numbers::pi * uniform01(rng);
      return geometry::Pose2{std::clamp(now.x + r * std::cos(a), box.xmin, box.xmax),
                             std::clamp(now.y + r * std::sin(a), box.ymin, box.ymax), now.theta};
    }
    const std::size_t others = walls.size() + (extra ? 1 : 0);
    if (preferred.empty() && others == 0) return std::nullopt;
    if (!preferred.empty() && (others == 0 || uniform01(rng) < 0.5))
      return preferred[uniform_index(rng, preferred.size())];
    const std::size_t i = uniform_index(rng, others);
    return i < walls.size() ? walls[i] : *extra;
  };
  // Turns each object of `r` whose heading no preference fixes square to
  // its nearest wall (squaring.h; the first square pose that is valid and
  // keeps the goal), in move order: a chain takes an armchair to another
  // wall with the heading it had, which may be askew there.
  // The energy is the moved layout's again; an object squared back onto
  // the pose it had leaves the move.
  const auto square_moved = [&](Rearrangement& r) {
    std::vector<geometry::Pose2> q = poses;
    for (const auto& [k, pose] : r.move) q[static_cast<std::size_t>(k)] = pose;
    bool changed = false;
    for (auto& [k, pose] : r.move) {
      if (heading_fixed(scene, k)) continue;
      for (SquarePlace& sq : square_places(scene, model, q, k, r.report, hooks.valid)) {
        std::vector<geometry::Pose2> s = q;
        s[static_cast<std::size_t>(k)] = sq.pose;
        const double p = proxy_of(s);
        if (!meets(sq.report, p)) continue;
        pose = q[static_cast<std::size_t>(k)] = sq.pose;
        r.report = std::move(sq.report);
        r.proxy = p;
        changed = true;
        break;
      }
    }
    if (!changed) return;
    std::erase_if(r.move, [&](const auto& m) { return m.second == poses[static_cast<std::size_t>(m.first)]; });
    r.energy = -polish_score(r.report) + gross_misses(r.report) + kProxyWeight * r.proxy;
    for (const auto& [k, pose] : r.move) r.energy += moved_cost(k, pose);
  };
  const int steps = std::min(kMaxSteps, kStepsPerObject * static_cast<int>(free_objects.size()));
  for (int chain = 0; chain < kChains; ++chain) {
    // The higher score's chains draw other walks than the fewer gross
    // misses' (the polish runs both from the same layout when the first
    // keeps nothing).
    const int stream = chain + (fewer_gross ? 0 : shorter ? 2 * kChains : kChains);
    std::mt19937_64 rng(splitmix64(hooks.seed ^ splitmix64(static_cast<std::uint64_t>(stream))));
    std::vector<geometry::Pose2> q = poses;
    PreferenceReport rq = report;
    std::vector<double> moved(poses.size(), 0.0);  // moved_cost per object in q
    double travel = 0.0;                           // their sum
    double pq = proxy0;
    double eq = -polish_score(rq) + gross_misses(rq) + kProxyWeight * pq;
    std::optional<Rearrangement> best;
    for (int step = 0; step < steps && !(stop && stop->load()); ++step) {
      const double hot = shorter ? kHotShorter : kHot, cold = shorter ? kColdShorter : kCold;
      const double t =
          hot * std::pow(cold / hot, static_cast<double>(step) / std::max(1, steps - 1));
      // The object: one with an unmet preference, or (kAnyObject) any.
      std::vector<int> pool;
      if (!shorter && uniform01(rng) >= kAnyObject)
        for (const PreferenceCheck& c : rq.checks) {
          if (c.met) continue;
          for (const std::string& who : {c.object, c.other}) {
            const int k = who.empty() ? -1 : scene.find_object(who);
            if (k >= 0 && movable[static_cast<std::size_t>(k)] &&
                std::find(pool.begin(), pool.end(), k) == pool.end())
              pool.push_back(k);
          }
        }
      if (pool.empty()) pool = free_objects;
      const int o = pool[uniform_index(rng, pool.size())];
      const std::optional<geometry::Pose2> to =
          [&] {
            const std::vector<geometry::Pose2> sq = squared(o, q);
            return draw(rng, preferred_poses(scene, model, sq, o), o, sq[static_cast<std::size_t>(o)],
                        nullptr);
          }();
      if (!to) continue;
      std::vector<geometry::Pose2> next = q;
      next[static_cast<std::size_t>(o)] = *to;
      if (!hooks.fits(next, o)) {
        // One or two movable holders of the place move to places of their
        // own, or to the place the object leaves.
        const std::vector<int> held = holders(scene, next, o);
        if (held.empty() || held.size() > 2 || std::any_of(held.begin(), held.end(), [&](int j) {
              return !movable[static_cast<std::size_t>(j)];
            }))
          continue;
        bool placed = true;
        for (const int j : held) {
          const std::vector<geometry::Pose2> preferred =
              preferred_poses(scene, model, squared(j, next), j);
          bool ok = false;
          for (int attempt = 0; attempt < kHolderDraws && !ok; ++attempt) {
            // An aside draw is centred where the holder's last draw put it
            // (where it stands, at the first): the draws walk away from a
            // crowded spot.
            const geometry::Pose2 now = squared(j, next)[static_cast<std::size_t>(j)];
            const std::optional<geometry::Pose2> theirs =
                draw(rng, preferred, j, now, &q[static_cast<std::size_t>(o)]);
            next[static_cast<std::size_t>(j)] = *theirs;  // `extra` makes one exist
            ok = hooks.fits(next, j);
          }
          if (!ok) {
            placed = false;
            break;
          }
        }
        if (!placed || !hooks.fits(next, o)) continue;
      }
      PreferenceReport rn = check_preferences(scene, model, next);
      std::vector<std::pair<int, double>> changed;
      double travel_next = travel;
      for (const int k : free_objects)
        if (next[static_cast<std::size_t>(k)] != q[static_cast<std::size_t>(k)]) {
          const double c = moved_cost(k, next[static_cast<std::size_t>(k)]);
          travel_next += c - moved[static_cast<std::size_t>(k)];
          changed.push_back({k, c});
        }
      const double pn = proxy_of(next);
      const double en = -polish_score(rn) + gross_misses(rn) + travel_next + kProxyWeight * pn;
      if (en > eq && uniform01(rng) >= std::exp((eq - en) / t)) continue;
      // The full checks only on what is accepted, once: every moved object
      // already fits, and the stop check looks at all of them.
      if (!changed.empty() && !hooks.valid(next, changed.front().first)) continue;
      for (const auto& [k, c] : changed) moved[static_cast<std::size_t>(k)] = c;
      q = std::move(next), rq = std::move(rn), eq = en, travel = travel_next, pq = pn;
      if (meets(rq, pq) && (!best || eq < best->energy)) {
        GroupMove move;
        for (const int k : free_objects)
          if (q[static_cast<std::size_t>(k)] != poses[static_cast<std::size_t>(k)])
            move.push_back({k, q[static_cast<std::size_t>(k)]});
        best = Rearrangement{eq, pq, rq, std::move(move)};
      }
    }
    if (best && !fewer_gross) square_moved(*best);
    if (best && std::none_of(found.begin(), found.end(),
                             [&](const Rearrangement& f) { return f.move == best->move; }))
      found.push_back(std::move(*best));
  }
  std::stable_sort(found.begin(), found.end(), [](const Rearrangement& a, const Rearrangement& b) {
    return a.energy < b.energy;
  });
  return found;
}

}  // namespace hrs::optimize
