// SPDX-License-Identifier: GPL-3.0-or-later
// The proposed planner (paper §V); see reuse.h.

#include "planning/reuse.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <set>
#include <stdexcept>

#include "geometry/error.h"
#include "geometry/polygon_ops.h"
#include "geometry/random.h"
#include "planning/motion_validator.h"
#include "planning/moved_objects.h"
#include "planning/path_ops.h"
#include "planning/path_shortening.h"
#include "planning/reuse_slot.h"

namespace hrs::planning {

namespace {

//! FailureMemory's margin: a collision query of the RRT starts at a node
//! (or is the goal pose) and drives at most step_length, so its reference
//! point stays within that of a recorded point (moved_objects.h).
double failure_margin(const geometry::CSpace& cspace, const TourOptions& tour) {
  return tour.planner.step_length + cspace.swept_reach() + kOffsetSlack;
}

}  // namespace

ReusePlanner::ReusePlanner(const geometry::Scene& scene, const geometry::CSpace& cspace,
                           const TourOptions& tour, const ReuseOptions& options, std::uint64_t seed)
    : cspace_(&cspace),
      tour_(tour),
      options_(options),
      radius_(scene.wheelchair.turning_radius),
      trees_(cspace, scene.wheelchair.turning_radius, options),
      scene_(scene),
      failures_(scene_, failure_margin(cspace, tour)) {
  if (options_.samples || options_.steering) {
    const geometry::Box b = geometry::bounding_box(scene.room.polygon);
    rs::DecompositionOptions d;
    d.radius = radius_;
    d.room_width = b.xmax - b.xmin;
    d.room_depth = b.ymax - b.ymin;
    d.initial_samples = options_.decomposition_initial;
    d.stop_after = options_.decomposition_stop;
    std::mt19937_64 rng(splitmix64(seed ^ 0x5eed'dec0'0000'0000ULL));
    decomposition_ = std::make_unique<rs::Decomposition>(d, rng);
    if (options_.samples) sampler_ = std::make_unique<DecompositionSampler>(*decomposition_, scene);
    if (options_.steering) steering_ = std::make_unique<DecompositionSteering>(*decomposition_);
  }
  if (options_.metrics)
    measures_ =
        std::make_unique<LegMeasures>(scene_, cspace, radius_, scene.weights.clearance_width);
  // PathDatabase::still_free(): a point of a stored path lies within half a trace step of
  // the trace; straight motions are tested as the segment itself and each
  // arc, cut at slice borders, as triangles within one slice's arc length
  // (radius · 2π/K) of a point on the arc (cspace.h); then swept_reach() and
  // the slack (moved_objects.h).
  still_free_margin_ = 0.5 * PathDatabase::kTraceStep +
                       radius_ * 2.0 * std::numbers::pi / cspace.slices() + cspace.swept_reach() +
                       kOffsetSlack;
}

ReusePlanner::~ReusePlanner() = default;

TourHooks ReusePlanner::hooks() {
  TourHooks h;
  h.provider = this;
  h.planner.sampler = sampler_.get();
  h.planner.steering = steering_.get();
  h.measures = measures_.get();
  return h;
}

void ReusePlanner::begin_iteration(std::uint64_t iteration_seed) {
  iteration_seed_ = iteration_seed;
  slots_.clear();
  leg_requests_.clear();
  unshared_.clear();
}

LegOutcome ReusePlanner::from_database(const LegKey& key, const Pose2& from, const Pose2& to,
                                       bool& skipped) const {
  LegOutcome out;
  out.source = LegSource::kReused;
  skipped = false;
  const PathDatabase::Entry* e = database_.find(key);
  if (!e) return out;
  out.rejected = true;
  std::optional<rs::Path> path = database_.transformed(key, from, to);
  if (!path) return out;  // the ends moved apart: repair or plan
  const auto t0 = std::chrono::steady_clock::now();
  MotionValidator validator(*cspace_, radius_);
  // Driven from the same start, the path is the same motion as when checked.
  skipped = options_.skip_far_checks && e->from == from &&
            PathDatabase::still_free(*e, *cspace_, scene_, still_free_margin_);
  const bool valid = std::abs(path->radius - radius_) <= 1e-12 &&
                     pose_gap(rs::end_pose(from, *path), to) <= tour_.planner.goal_tolerance &&
                     (skipped || validator.path_free(from, *path));
  skipped = skipped && valid;
  out.stats.collision_checks = validator.checks();
  out.stats.time_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (!valid) return out;
  out.rejected = false;
  out.found = true;
  out.path = *std::move(path);
  return out;
}

std::optional<LegOutcome> ReusePlanner::repair(const LegKey& key, const Pose2& from,
                                               const Pose2& to, std::uint64_t seed,
                                               LegPlanner& planner) const {
  const PathDatabase::Entry* e = database_.find(key);
  if (!e) return std::nullopt;
  // Keep the part of the path attached to the end that did not move: driven
  // from `from` when the from-pose is where it was (or both moved), else the
  // reversed path driven from `to`. Then grow an RRT from that chain.
  const bool from_moved = pose_gap(from, e->from) > PathDatabase::kRigidTolerance;
  const bool to_moved = pose_gap(to, e->to) > PathDatabase::kRigidTolerance;
  const bool reverse = from_moved && !to_moved;
  const Pose2 start = reverse ? to : from;
  const Pose2 goal = reverse ? from : to;
  const rs::Path base = reverse ? rs::reversed(e->path) : e->path;

  MotionValidator validator(*cspace_, radius_);
  RrtTree chain;
  chain.nodes.push_back({start, -1, rs::Path{{}, radius_}, 0.0});
  double cost = 0.0;
  for_each_piece(start, base, tour_.planner.step_length, radius_, [&](const PathPiece& q) {
    if (!validator.segment_free(q.start, q.part)) return false;
    cost += q.part.length;
    chain.nodes.push_back({q.end, static_cast<std::int32_t>(chain.nodes.size() - 1),
                           rs::Path{{q.part}, radius_}, cost});
    return true;
  });
  LegOutcome out;
  out.planned = true;
  out.source = LegSource::kRepaired;
  out.stats.collision_checks = validator.checks();
  if (chain.nodes.size() < 2) return std::nullopt;
  LegResult r =
      planner.plan(start, goal, seed, chain, Termination{}.iterations(options_.repair_iterations));
  add_stats(out.stats, r.stats);
  if (!r.found) {
    out.found = false;
    return out;  // counted, and the caller plans fresh
  }
  rs::Path path = reverse ? rs::reversed(r.path) : std::move(r.path);
  if (reverse) {
    // The same curve driven the other way: confirm its end and its freedom.
    MotionValidator again(*cspace_, radius_);
    const bool ok = pose_gap(rs::end_pose(from, path), to) <= tour_.planner.goal_tolerance &&
                    again.path_free(from, path);
    out.stats.collision_checks += again.checks();
    if (!ok) return out;
  }
  out.found = true;
  out.path = std::move(path);
  return out;
}

LegResult ReusePlanner::fresh_plan(const LegKey& key, const Pose2& from, const Pose2& to,
                                   std::uint64_t seed, LegPlanner& planner, RrtTree& tree,
                                   LegStats& stats, ReuseSlot& slot) const {
  const int cap = planner.options().max_iterations;
  int budget = options_.budget ? std::min(options_.budget_iterations, cap) : cap;
  if (options_.backoff) {
    if (const int failed = failures_.failed_in_a_row(key); failed > 0) {
      const int halvings = std::min(failed, 30);
      budget = std::max(std::min(options_.backoff_floor, budget), budget >> halvings);
    }
  }
  // The gate is asked, as for the baseline (TourHooks::gate), only once the
  // RRT has run kRefuseAfter iterations in vain: most legs are found or
  // served sooner, and their layouts need no grid fill.
  Termination stop;
  stop.iterations(budget);
  if (gate_) stop.ask_after(kRefuseAfter, [&] { return gate_->refuses(from, to); });
  LegResult r = planner.plan(from, to, seed, tree, stop);
  if (r.gave_up()) slot.proven = true;
  add_stats(stats, r.stats);
  slot.fresh_iterations = r.stats.iterations;
  return r;
}

LegOutcome ReusePlanner::plan_leg(const LegKey& key, const Pose2& from, const Pose2& to,
                                  std::uint64_t seed, LegPlanner& planner, ReuseSlot& slot) const {
  LegOutcome out;
  out.planned = true;
  out.source = LegSource::kPlanned;
  if (options_.failures && failures_.repeats(key, from, to, *cspace_)) {
    slot.failure_reused = true;
    return out;  // the recorded RRT run would repeat query for query
  }
  if (options_.paths && options_.repair) {
    if (std::optional<LegOutcome> r = repair(key, from, to, seed, planner)) {
      if (r->found) {
        if (options_.shortcuts) r->path = shortened(from, r->path, r->stats);
        return *std::move(r);
      }
      add_stats(out.stats, r->stats);
    }
  }
  RrtTree tree;
  if (options_.trees) {
    std::uint64_t checks = 0;
    if (std::optional<RrtTree> kept =
            trees_.usable({key.from_object, key.from_slot}, from, &checks)) {
      tree = *std::move(kept);
      slot.tree_reused = true;
    }
    out.stats.collision_checks += checks;
  }
  LegResult r = fresh_plan(key, from, to, seed, planner, tree, out.stats, slot);
  // A failure the gate proved is not recorded for `failures`: the gate's grid
  // looked at the whole layout, not only near the RRT's nodes, so
  // FailureMemory::repeats() could not vouch for it after a move.
  if (!r.found && options_.failures && !slot.proven) {
    slot.failed_points.reserve(tree.nodes.size() + 1);
    for (const RrtTree::Node& node : tree.nodes) slot.failed_points.push_back(node.pose.position());
    slot.failed_points.push_back(to.position());
  }
  if (options_.trees) slot.grown = std::move(tree);
  out.found = r.found;
  if (r.found)
    out.path = options_.shortcuts ? shortened(from, r.path, out.stats) : std::move(r.path);
  return out;
}

ReuseSlot* ReusePlanner::slot_for(const LegRequest& r, bool request, bool may_plan, int tour) {
  std::lock_guard lock(mutex_);
  auto& owned = slots_[r.key];
  if (!owned) {
    owned = std::make_unique<ReuseSlot>();
    owned->from = r.from;
    owned->to = r.to;
  }
  if (request) {
    ++leg_requests_[tour];
    owned->first_request = std::min(owned->first_request, tour);
    if (may_plan) owned->first_plan_request = std::min(owned->first_plan_request, tour);
  }
  return owned.get();
}

LegOutcome ReusePlanner::settle(const LegKey& key, ReuseSlot& slot, bool may_plan,
                                LegPlanner& planner) const {
  slot.working = true;
  if (!slot.database_done) {
    slot.database = from_database(key, slot.from, slot.to, slot.check_skipped);
    slot.database_done = true;
  }
  if (slot.database.found || !may_plan) {
    slot.working = false;
    if (slot.database.found) return slot.database;
    LegOutcome out;
    out.planned = true;
    out.rejected = slot.database.rejected;
    return out;
  }
  if (!slot.planned_done) {
    slot.planned = plan_leg(key, slot.from, slot.to, leg_seed(iteration_seed_, key), planner, slot);
    slot.planned.rejected = slot.database.rejected;
    slot.planned.stats.collision_checks += slot.database.stats.collision_checks;
    slot.planned_done = true;
  }
  slot.working = false;
  return slot.planned;
}

bool ReusePlanner::speculate_one(std::span<const LegRequest> next, LegPlanner& planner) {
  for (const LegRequest& r : next) {
    ReuseSlot* slot = slot_for(r, false);
    std::unique_lock lock(slot->mutex, std::try_to_lock);
    if (!lock.owns_lock()) continue;  // being computed
    if (slot->planned_done || (slot->database_done && slot->database.found)) continue;
    settle(r.key, *slot, true, planner);
    if (!slot->planned_done) continue;  // served by the database: cheap, go on
    slot->speculative = true;
    ++speculated_;
    return true;
  }
  return false;
}

ReusePlanner::Speculation ReusePlanner::speculation() const {
  return {speculated_.load(), speculated_used_.load()};
}

rs::Path ReusePlanner::shortened(const Pose2& from, const rs::Path& path, LegStats& stats) const {
  MotionValidator validator(*cspace_, radius_);
  rs::Path out = shorten_path(from, path, validator, tour_.planner.step_length);
  stats.collision_checks += validator.checks();
  return out;
}

LegOutcome ReusePlanner::plan_alone(const LegKey& key, const Pose2& from, const Pose2& to,
                                    std::uint64_t tour_seed, bool may_plan, LegPlanner& planner,
                                    int tour) {
  LegOutcome out;
  out.planned = true;
  if (!may_plan) return out;
  LegResult r = planner.plan(from, to, leg_seed(tour_seed, key));
  out.found = r.found;
  out.path = std::move(r.path);
  out.stats = r.stats;
  // Every tour plans its own legs here: counted per request (the sums
  // do not depend on the order).
  std::lock_guard lock(mutex_);
  ReuseCounters& mine = unshared_[tour];
  ++mine.leg_requests;
  if (r.found) {
    ++mine.legs_planned;
    ++mine.rrt_iterations[r.stats.iterations];
  } else {
    ++mine.legs_failed;
  }
  return out;
}

LegOutcome ReusePlanner::resolve(const LegKey& key, const Pose2& from, const Pose2& to,
                                 std::uint64_t tour_seed, bool may_plan, LegPlanner& planner,
                                 std::span<const LegRequest> next, int tour) {
  // The baseline exactly: a fresh tree and the tour's own leg seed.
  if (!options_.any()) return plan_alone(key, from, to, tour_seed, may_plan, planner, tour);
  ReuseSlot* slot = slot_for({key, from, to}, true, may_plan, tour);
  if (options_.paths) {
    // Compute once per key and iteration; tours needing the same leg wait,
    // or with `speculate` first plan their next candidate.
    std::unique_lock lock(slot->mutex, std::try_to_lock);
    if (!lock.owns_lock()) {
      if (options_.speculate && slot->working.load()) speculate_one(next, planner);
      lock.lock();
    }
    if (slot->speculative) {
      slot->speculative = false;
      ++speculated_used_;
    }
    return settle(key, *slot, may_plan, planner);
  }
  const std::uint64_t seed = leg_seed(iteration_seed_, key);
  // No sharing (path reuse off): every tour plans; the outcome is the same
  // pure function, so the first copy recorded is as good as any.
  LegOutcome out;
  out.planned = true;
  if (!may_plan) return out;
  ReuseSlot local;
  out = plan_leg(key, from, to, seed, planner, local);
  std::lock_guard lock(slot->mutex);
  if (!slot->planned_done) {
    slot->planned = out;
    slot->planned_done = true;
    slot->fresh_iterations = local.fresh_iterations;
    slot->tree_reused = local.tree_reused;
    slot->failure_reused = local.failure_reused;
    slot->proven = local.proven;
    slot->failed_points = std::move(local.failed_points);
    slot->grown = std::move(local.grown);
  }
  return out;
}

ReuseCounters ReusePlanner::end_iteration(int kept_tours) {
  ReuseCounters c;
  for (const auto& [tour, counts] : unshared_)
    if (tour < kept_tours) c += counts;
  for (const auto& [tour, n] : leg_requests_)
    if (tour < kept_tours) c.leg_requests += n;
  std::set<RootKey> roots;
  const std::vector<Pose2> layout = layout_of(*cspace_);  // the iteration's, for the stores
  for (auto& [key, slot] : slots_) {                      // key order: the merge is deterministic
    // Computed by `speculate` only, or only for tours the caller dropped: no trace.
    if (slot->first_request >= kept_tours) continue;
    // Stage B counts only when a tour asked for the leg with planning
    // allowed: a tour capped by max_leg_plans gets "not found" whether or
    // not `speculate` planned the leg meanwhile, so the stores must not
    // depend on it either.
    const bool planned = slot->planned_done && slot->first_plan_request < kept_tours;
    const LegOutcome* outcome = count_slot(*slot, planned, c);
    if (options_.failures && planned) {
      if (!slot->failed_points.empty()) {
        failures_.record(key, slot->from, slot->to, layout, std::move(slot->failed_points));
      } else if (slot->planned.found) {
        failures_.forget(key);
      }
    }
    if (options_.backoff && outcome == &slot->planned)
      failures_.count_fresh_plan(key, outcome->found);
    if (options_.paths && outcome) {
      if (outcome == &slot->database) {
        // path_free() held now (checked, or implied by PathDatabase::still_free()).
        database_.put(key, slot->from, slot->to, outcome->path, layout);
      } else if (outcome->found) {
        database_.put(key, slot->from, slot->to, outcome->path);
      } else {
        database_.erase(key);  // not valid here and not repairable
      }
    }
    if (planned && slot->grown) {
      const RootKey root{key.from_object, key.from_slot};
      if (roots.insert(root).second) trees_.put(root, *std::move(slot->grown));
    }
  }
  slots_.clear();
  leg_requests_.clear();
  unshared_.clear();
  totals_ += c;
  return c;
}

}  // namespace hrs::planning
