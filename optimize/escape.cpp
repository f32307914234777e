// SPDX-License-Identifier: GPL-3.0-or-later
// The design loop's escape from walled-in layouts; see escape.h.

#include "optimize/escape.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "geometry/polygon_ops.h"
#include "geometry/random.h"
#include "optimize/preferences.h"

namespace hrs::optimize {

using geometry::Vec2;

int EscapePolicy::separate(std::vector<Pose2>& poses, std::uint64_t seed, const ValidFn& valid,
                           const PlaceFn& place, int& passes) {
  static constexpr int kSeparateDraws = 500;
  static constexpr int kSeparatePasses = 6;
  passes = 0;
  if (!escape_ || layout_violation(round_.scene()).empty()) return 0;
  std::mt19937_64 rng(splitmix64(seed ^ 0x7365'7061'7261'7465ULL));
  const geometry::Box box = geometry::bounding_box(scene_.room.polygon);
  int moved = 0;
  while (passes < kSeparatePasses && !layout_violation(round_.scene()).empty()) {
    ++passes;
    const int before = moved;
    for (std::size_t i = 0; i < poses.size(); ++i) {
      const int o = static_cast<int>(i);
      if (!movable_[i] || object_fits(round_.scene(), o)) continue;
      std::optional<Pose2> found;
      std::vector<Pose2> p = poses;
      for (int draw = 0; draw < kSeparateDraws && !found; ++draw) {
        Pose2 to = poses[i];
        to.x = box.xmin + uniform01(rng) * (box.xmax - box.xmin);
        to.y = box.ymin + uniform01(rng) * (box.ymax - box.ymin);
        to.theta = geometry::wrap_angle(to.theta + std::floor(uniform01(rng) * 4.0) *
                                                       (std::numbers::pi / 2));
        p[i] = to;
        if (valid(p, o)) found = to;
      }
      // In a crowded room a uniform draw seldom lands on a free spot: scan.
      if (!found) found = nearest_free_pose(o, poses, box, valid);
      // No spot is free: take the nearest spot that smaller movable objects
      // hold; they are separated in turn (smaller objects fit more easily).
      if (!found) found = displacing_pose(o, poses, box);
      if (!found) continue;
      place(o, *found);
      poses[i] = *found;
      ++moved;
    }
    // A pass that places nothing leaves the layout as it was: the scans of
    // another pass would answer the same, at about a second per object.
    if (moved == before) break;
  }
  return moved;
}

namespace {

//! The pose of `now`'s object nearest `now` that `ok` accepts: positions
//! `step` apart over `box`, nearest first (ties in scan order, so the answer
//! is one function of the layout), each at `now`'s heading and its three
//! quarter turns.
std::optional<Pose2> nearest_pose(const Pose2& now, const geometry::Box& box, double step,
                                  const std::function<bool(const Pose2&)>& ok) {
  const int nx = static_cast<int>(std::floor((box.xmax - box.xmin) / step)) + 1;
  const int ny = static_cast<int>(std::floor((box.ymax - box.ymin) / step)) + 1;
  std::vector<std::pair<double, Vec2>> spots;
  spots.reserve(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));
  for (int ix = 0; ix < nx; ++ix)
    for (int iy = 0; iy < ny; ++iy) {
      const Vec2 c{box.xmin + ix * step, box.ymin + iy * step};
      spots.emplace_back(std::hypot(c.x - now.x, c.y - now.y), c);
    }
  std::stable_sort(spots.begin(), spots.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [d, c] : spots)
    for (int quarter = 0; quarter < 4; ++quarter) {
      const Pose2 to{c.x, c.y, geometry::wrap_angle(now.theta + quarter * (std::numbers::pi / 2))};
      if (ok(to)) return to;
    }
  return std::nullopt;
}

}  // namespace

std::optional<Pose2> EscapePolicy::nearest_free_pose(int o, const std::vector<Pose2>& poses,
                                                     const geometry::Box& box,
                                                     const ValidFn& valid) {
  std::vector<Pose2> p = poses;
  return nearest_pose(poses[static_cast<std::size_t>(o)], box, 0.1, [&](const Pose2& to) {
    p[static_cast<std::size_t>(o)] = to;
    return valid(p, o);
  });
}

std::optional<Pose2> EscapePolicy::displacing_pose(int o, const std::vector<Pose2>& poses,
                                                   const geometry::Box& box) {
  const auto area = [](const geometry::Object& x) {
    return std::abs(geometry::signed_area(x.footprint));
  };
  geometry::Scene larger = round_.scene();
  larger.objects.clear();
  int at = -1;
  for (std::size_t j = 0; j < poses.size(); ++j) {
    geometry::Object x = round_.scene().objects[j];
    x.pose = poses[j];
    const bool self = static_cast<int>(j) == o;
    if (!self && movable_[j] && area(x) < area(round_.scene().objects[static_cast<std::size_t>(o)]))
      continue;
    if (self) at = static_cast<int>(larger.objects.size());
    larger.objects.push_back(std::move(x));
  }
  return nearest_pose(poses[static_cast<std::size_t>(o)], box, 0.2, [&](const Pose2& to) {
    larger.objects[static_cast<std::size_t>(at)].pose = to;
    return object_fits(larger, at);
  });
}

EscapePolicy::EscapePolicy(const geometry::Scene& scene, TourRound& round,
                           const std::vector<Sequence>& sequences,
                           const std::vector<bool>& movable, const DesignOptions& options,
                           bool plan_every)
    : scene_(scene),
      round_(round),
      sequences_(sequences),
      movable_(movable),
      cspace_options_(options.cspace),
      gate_options_(options.gate),
      escape_(options.planner.escape),
      plan_every_(plan_every) {}

//! The objects that are stops of some sequence, ascending.
std::vector<int> EscapePolicy::stop_objects() const {
  std::vector<int> stops;
  for (const Sequence& s : sequences_)
    for (std::size_t i = 1; i < s.nodes.size(); ++i) {
      const int o = round_.scene().find_object(s.nodes[i]);
      if (o >= 0 && std::find(stops.begin(), stops.end(), o) == stops.end()) stops.push_back(o);
    }
  std::sort(stops.begin(), stops.end());
  return stops;
}

//! The stops the door's reachable region misses (grade > 0); `total` is
//! the summed grade of all `stops`.
std::vector<int> EscapePolicy::walled_off(const std::vector<int>& stops, double& total) {
  std::vector<int> walled;
  total = 0.0;
  for (int s : stops) {
    const double b = round_.gate().blockage(round_.goals_of(s));
    total += b;
    if (b > 0.0) walled.push_back(s);
  }
  return walled;
}

//! The stops with a free goal pose in the current layout (covers_a_stop).
void EscapePolicy::refresh_open_stops() {
  open_stops_.clear();
  if (!escape_ || !plan_every_) return;
  for (int s : stop_objects())
    if (!round_.goals_of(s).empty()) open_stops_.push_back(s);
}

//! With `escape`: true when the layout `poses` leaves a stop that has a
//! free goal pose now without any (docs/optimize.md "Blocked layouts").
//! Such a layout has no tour through that stop whatever the planner does,
//! and once the annealer accepts one (while hot) the move back is seldom
//! drawn. The moved objects are `moved` and every object whose pose in
//! `poses` differs from the C-space's (the partner of a pair move or an
//! exchange of places: two moves can cover a stop together that neither
//! covers alone). Only the stops within reach of a moved object's new
//! footprint are asked, with the objects moved in the C-space and back.
bool EscapePolicy::covers_a_stop(const std::vector<Pose2>& poses, int moved) {
  if (!escape_ || !plan_every_ || open_stops_.empty()) return false;
  // The moved objects' footprints where they go and where the C-space has
  // them (the partner of a pair move is only in `poses`).
  struct Moved {
    int object;
    geometry::Polygon to, from;
  };
  std::vector<Moved> group;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const int k = static_cast<int>(i);
    const Pose2& from = round_.cspace().object_pose(k);
    if (k != moved && from == poses[i]) continue;
    geometry::Object o = round_.scene().objects[i];
    o.pose = poses[i];
    Moved m{k, geometry::world_footprint(o), {}};
    o.pose = from;
    m.from = geometry::world_footprint(o);
    group.push_back(std::move(m));
  }
  // A goal pose's chair lies within gap + its diagonal of the stop, so only
  // an object within that reach of the stop, where it goes or where it
  // was, changes its goal poses.
  const auto reach_of = [&](int s) {
    return round_.scene().objects[s].approach_or_default().gap + 0.01 +
           std::hypot(scene_.wheelchair.length, scene_.wheelchair.width);
  };
  // A moved stop's goal poses are where it goes.
  std::vector<int> near;
  std::vector<geometry::Polygon> near_at;
  for (int s : open_stops_) {
    const auto in_group = std::find_if(group.begin(), group.end(),
                                       [&](const Moved& m) { return m.object == s; });
    const geometry::Polygon at = in_group != group.end()
                                     ? in_group->to
                                     : geometry::world_footprint(round_.scene().objects[s]);
    const double reach = reach_of(s);
    const bool close = in_group != group.end() ||
                       std::any_of(group.begin(), group.end(), [&](const Moved& m) {
                         return geometry::polygon_distance(at, m.to) <= reach;
                       });
    if (!close) continue;
    near.push_back(s);
    near_at.push_back(at);
  }
  if (near.empty()) return false;
  // The moved objects that matter to a near stop enter the C-space, one
  // trial inside the other.
  std::vector<int> trial;
  for (const Moved& m : group) {
    bool matters = m.object == moved;
    for (std::size_t n = 0; n < near.size() && !matters; ++n)
      matters = m.object == near[n] ||
                geometry::polygon_distance(near_at[n], m.to) <= reach_of(near[n]) ||
                geometry::polygon_distance(near_at[n], m.from) <= reach_of(near[n]);
    if (matters) trial.push_back(m.object);
  }
  bool covers = false;
  std::function<void(std::size_t)> ask = [&](std::size_t g) {
    if (g < trial.size()) {
      const int k = trial[g];
      round_.trial(k, poses[static_cast<std::size_t>(k)], [&] { ask(g + 1); });
      return;
    }
    for (int s : near)
      if (round_.goals_of(s).empty()) {
        covers = true;
        break;
      }
  };
  ask(0);
  if (covers) ++covering_moves_;
  return covers;
}

//! One unblocking proposal for object `o`: a jump anywhere in the room's
//! `box` with a quarter turn (1/2), a step of up to 1 m per axis (1/4) or a
//! quarter turn (1/4), redrawn up to 50 times until valid. When no jump is
//! valid and the object is wanted against a wall, up to 50 wall slots
//! (wall_slot, drawn from `slots`) are tried: a bed that seals a corridor
//! seldom fits at a uniform place of a crowded room, but often along a
//! wall. nullopt when no draw was valid.
std::optional<Pose2> EscapePolicy::unblock_move(int o, const std::vector<Pose2>& poses,
                                              const geometry::Box& box, std::mt19937_64& rng,
                                              std::mt19937_64& slots, const ValidFn& valid) {
  constexpr double kQuarter = std::numbers::pi / 2;
  constexpr int kDraws = 50;
  const Pose2 from = round_.scene().objects[o].pose;
  const auto valid_at = [&](const Pose2& to) {
    std::vector<Pose2> p = poses;
    p[o] = to;
    return valid(p, o);
  };
  const double kind = uniform01(rng);
  for (int attempt = 0; attempt < kDraws; ++attempt) {
    Pose2 to = from;
    if (kind < 0.5) {
      to.x = box.xmin + uniform01(rng) * (box.xmax - box.xmin);
      to.y = box.ymin + uniform01(rng) * (box.ymax - box.ymin);
      to.theta = geometry::wrap_angle(from.theta + std::floor(uniform01(rng) * 4.0) * kQuarter);
    } else if (kind < 0.75) {
      to.x += 2.0 * uniform01(rng) - 1.0;
      to.y += 2.0 * uniform01(rng) - 1.0;
    } else {
      to.theta = geometry::wrap_angle(from.theta + (uniform01(rng) < 0.5 ? 1 : -1) * kQuarter);
    }
    if (valid_at(to)) return to;
  }
  const geometry::Object& object = round_.scene().objects[o];
  if (kind >= 0.5 || !object.wall || !object.wall->distance) return std::nullopt;
  for (int attempt = 0; attempt < kDraws; ++attempt) {
    // nullopt: the wall drawn is shorter than the object.
    const std::optional<Pose2> slot = wall_slot(round_.scene(), o, slots);
    if (slot && valid_at(*slot)) return slot;
  }
  return std::nullopt;
}

//! Beyond the paper (docs/optimize.md "Blocked layouts"): when stops are
//! walled off from the door in `poses` (the input layout, or the
//! annealing's best one that misses tours), a greedy search on the free
//! grid alone (no tour is planned, a few milliseconds a proposal) moves the
//! objects that wall them in (focus_for) until no stop of any sequence is
//! walled off, or after kUnblockProposals proposals plus kUnblockPerObject
//! per movable object (a room of 40 objects has more to move out of the
//! way than one of 5). A proposal (unblock_move: a jump with a quarter
//! turn, a step or a quarter turn, each redrawn until valid; wall slots
//! when no jump of a wall object lands) is kept when the summed grade of
//! the stops does not grow. Returns true when the layout changed; the open
//! stops (covers_a_stop) are then the changed layout's.
bool EscapePolicy::unblock(std::vector<Pose2>& poses, std::uint64_t seed,
                         const std::atomic<bool>* stop, const ValidFn& valid,
                         const PlaceFn& place, DesignResult::Unblock& stats) {
  static constexpr int kUnblockProposals = 300, kUnblockPerObject = 15;
  const int budget = kUnblockProposals +
                     kUnblockPerObject * static_cast<int>(std::count(movable_.begin(), movable_.end(), true));
  if (!escape_ || !plan_every_) return false;
  const std::vector<int> stops = stop_objects();
  double score = 0.0;
  std::vector<int> walled = walled_off(stops, score);
  stats.walled_before = static_cast<int>(walled.size());
  stats.walled_after = stats.walled_before;
  if (walled.empty()) return false;
  std::mt19937_64 rng(splitmix64(seed ^ 0x756e'626c'6f63'6bULL));
  // The wall slots' own stream: a layout whose jumps all find a valid
  // place draws what it drew without them.
  std::mt19937_64 slots(splitmix64(seed ^ 0x736c'6f74'73ULL));
  const geometry::Box box = geometry::bounding_box(scene_.room.polygon);
  bool changed = false;
  for (int k = 0; k < budget && !walled.empty(); ++k) {
    if (stop && stop->load()) break;
    const std::vector<int> focus = walled_focus(walled);
    if (focus.empty()) break;
    const int o = focus[uniform_index(rng, focus.size())];
    const std::optional<Pose2> to = unblock_move(o, poses, box, rng, slots, valid);
    ++stats.proposals;
    if (!to) continue;
    const Pose2 from = round_.scene().objects[o].pose;
    place(o, *to);
    double next = 0.0;
    std::vector<int> now = walled_off(stops, next);
    if (next <= score) {
      score = next;
      walled = std::move(now);
      poses[o] = *to;
      changed = true;
      ++stats.accepted;
      refresh_open_stops();
    } else {
      place(o, from);
    }
  }
  stats.walled_after = static_cast<int>(walled.size());
  return changed;
}

//! The movable objects near `stops` (see walling_objects()); `in_grid`:
//! only those bordering the door's reachable region.
std::vector<int> EscapePolicy::focus_for(const std::vector<int>& stops, bool in_grid) {
  // The stops' footprints: a stop whose goal poses are all covered (by
  // what walls it in) has no free goal pose to measure from.
  std::vector<geometry::Polygon> targets;
  for (int s : stops) targets.push_back(geometry::world_footprint(round_.scene().objects[s]));
  return near_targets(targets, stops, in_grid);
}

namespace {

geometry::Scene without_movable(const geometry::Scene& scene) {
  geometry::Scene fixed = scene;
  fixed.objects.clear();
  for (const geometry::Object& o : scene.objects)
    if (o.fixed) fixed.objects.push_back(o);
  return fixed;
}

}  // namespace

EscapePolicy::FixedOnly::FixedOnly(const geometry::Scene& s,
                                   const geometry::CSpaceOptions& cspace_options,
                                   const planning::ReachGateOptions& gate_options)
    : scene(without_movable(s)),
      cspace(scene, cspace_options),
      gate(scene, cspace, gate_options) {}

//! The movable stops of `walled` that only moving themselves can bring
//! within the door's reach: with every movable object taken out of the
//! room, the door still reaches none of their goal poses (certified by the
//! free grid of the walls and the fixed objects alone). What closes their
//! pocket is fixed (a partition's opening narrowed by a fixed wardrobe
//! below the chair's width), so moving the objects around it, which the
//! focus does for every other walled stop, cannot open it. Stops with no
//! free goal pose are left to the covered-stop rule.
std::vector<int> EscapePolicy::sealed_by_fixed(const std::vector<int>& walled) {
  std::vector<int> out;
  for (int s : walled) {
    if (!movable_[static_cast<std::size_t>(s)]) continue;
    const auto goals = round_.goals_of(s);
    if (goals.empty()) continue;
    if (!fixed_only_) fixed_only_ = std::make_unique<FixedOnly>(scene_, cspace_options_, gate_options_);
    if (fixed_only_->gate.walls_off(goals)) out.push_back(s);
  }
  return out;
}

std::vector<int> EscapePolicy::walled_focus(const std::vector<int>& walled) {
  std::vector<int> out = focus_for(walled, true);
  for (int s : sealed_by_fixed(walled))
    if (std::find(out.begin(), out.end(), s) == out.end()) out.push_back(s);
  std::sort(out.begin(), out.end());
  return out;
}

//! The movable objects among `members` or near a polygon of `targets`,
//! index order (members count only when they are candidates: movable and,
//! with `in_grid`, bordering the door's region). Without `in_grid`: every
//! movable object within kFocusReach. With `in_grid`: of the movable
//! objects bordering the door's reachable region, those within
//! max(kFocusReach, n + kNearestBand) of a target, n the distance of the
//! nearest of them to it. What walls a stop off from the door's region is
//! what of that region's border lies nearest the stop, however large the
//! room: a fixed reach alone left the focus empty, or on the wrong
//! objects, wherever the stop's room is more than 2 m across.
std::vector<int> EscapePolicy::near_targets(const std::vector<geometry::Polygon>& targets,
                                            const std::vector<int>& members, bool in_grid) {
  static constexpr double kNearestBand = 0.5;
  std::vector<int> out;
  if (targets.empty()) return out;
  std::vector<int> candidates;
  if (in_grid) {
    for (int i : round_.gate().bordering(0.5 * scene_.wheelchair.length + 0.25))
      if (movable_[i]) candidates.push_back(i);
  } else {
    for (int i = 0; i < static_cast<int>(movable_.size()); ++i)
      if (movable_[i]) candidates.push_back(i);
  }
  std::vector<geometry::Polygon> footprints;
  for (int i : candidates) footprints.push_back(geometry::world_footprint(round_.scene().objects[i]));
  std::vector<char> near(candidates.size(), 0);
  for (std::size_t c = 0; c < candidates.size(); ++c)
    near[c] = std::find(members.begin(), members.end(), candidates[c]) != members.end();
  std::vector<double> d(candidates.size());
  for (const geometry::Polygon& t : targets) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      d[c] = geometry::polygon_distance(footprints[c], t);
      nearest = std::min(nearest, d[c]);
    }
    if (!std::isfinite(nearest)) continue;  // no candidate, or an empty target
    const double reach = in_grid ? std::max(kFocusReach, nearest + kNearestBand) : kFocusReach;
    for (std::size_t c = 0; c < candidates.size(); ++c) near[c] = near[c] || d[c] <= reach;
  }
  for (std::size_t c = 0; c < candidates.size(); ++c)
    if (near[c]) out.push_back(candidates[c]);
  return out;
}

//! The annealer's focus, with `escape`, when tours are unfound: the
//! objects that most likely stand between the door and the stops it
//! misses. When stops are walled off in the free grid (grade > 0): the
//! movable objects that border the door's reachable region (within the
//! chair's half length + 25 cm) and are such a stop or lie near one
//! (near_targets), the walled stops that fixed objects alone seal
//! (sealed_by_fixed), and, for a stop with no free
//! goal pose at all, the stop and the movable objects within kFocusReach
//! of it wherever they are. Otherwise (the grid joins
//! everything, the car still fails: a turn too tight, a gap the grid's
//! margin lets through): the movable stops where unfound tours broke off
//! and the movable objects within kFocusReach of their footprints, and
//! when every unfound tour breaks off leaving the door, the movable objects
//! within kFocusReach of the door's clear zone.
std::vector<int> EscapePolicy::walling_objects() {
  if (!escape_) return {};
  const std::vector<int> walled = round_.walled_stops();
  if (walled.empty()) {
    std::vector<int> out = focus_for(round_.failing_stops(), false);
    // Every unfound tour breaks off leaving the door: the objects near the
    // door's clear zone box the car's first turn in.
    if (round_.fails_leaving_the_door()) {
      for (int i : near_targets({geometry::door_clear_zone(scene_)}, {}, false))
        if (std::find(out.begin(), out.end(), i) == out.end()) out.push_back(i);
      std::sort(out.begin(), out.end());
    }
    return out;
  }
  std::vector<int> out = walled_focus(walled);
  // A stop without a single free goal pose is covered where it stands,
  // however far the door's region reaches: it and its neighbours join
  // (measured: a bookshelf facing the bed, otherwise never moved).
  std::vector<int> covered;
  for (int s : walled)
    if (round_.goals_of(s).empty()) covered.push_back(s);
  for (int i : focus_for(covered, false))
    if (std::find(out.begin(), out.end(), i) == out.end()) out.push_back(i);
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace hrs::optimize
