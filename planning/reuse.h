// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The proposed planner (paper §V): reuse across the hundreds of similar
// planning problems of one design run, each technique switchable alone.
// §V-A: RRT samples drawn from the RS-decomposition's configurations
// (DecompositionSampler) and RS look-ups through its predicted words
// (DecompositionSteering). §V-B: a path database keyed by LegKey whose paths
// live in the frames of the goal poses they join, so a path between two
// objects that moved rigidly together is transformed exactly, and a path
// with one moved end is repaired (its valid part kept, the gap re-planned).
// §V-C: RRT trees rooted at goal poses, kept while their root barely moves,
// pruned of edges a move invalidated, rebuilt past 30 nodes.
//
// Determinism (docs/design-notes.md: the same seed gives the same bytes for any thread
// count): ReusePlanner serves legs through TourHooks::provider. Between
// begin_iteration() and end_iteration() the database and the tree store are
// read-only snapshots; every leg's outcome is a pure function of (snapshot,
// current layout, iteration seed, LegKey), computed once per key and shared
// by the tours of the iteration (a per-key lock); end_iteration() merges the
// outcomes into the stores in key order. Leg seeds depend on the iteration
// seed and the key, never on the tour.

#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <vector>

#include "geometry/cspace.h"
#include "geometry/pose.h"
#include "geometry/scene.h"
#include "planning/decomposition_hooks.h"
#include "planning/failure_memory.h"
#include "planning/leg_measures.h"
#include "planning/path_database.h"
#include "planning/reach_gate.h"
#include "planning/reuse_counters.h"
#include "planning/reuse_options.h"
#include "planning/rrt.h"
#include "planning/tour.h"
#include "planning/tree_store.h"
#include "rs/decomposition.h"

namespace hrs::planning {

struct ReuseSlot;  // one key's shared outcome in an iteration (reuse_slot.h)

//! The proposed planner's leg service (a LegProvider) for one scene.
class ReusePlanner final : public LegProvider {
 public:
  //! `cspace` is read at every resolve (the caller moves objects between
  //! iterations); `seed` seeds the decomposition.
  ReusePlanner(const geometry::Scene& scene, const geometry::CSpace& cspace,
               const TourOptions& tour, const ReuseOptions& options, std::uint64_t seed);
  ~ReusePlanner() override;

  //! Hooks for the TourPlanners of this run: provider, sampler, steering.
  TourHooks hooks();
  //! Starts an iteration (a new layout): clears the shared legs; leg seeds
  //! derive from `iteration_seed` and the key.
  void begin_iteration(std::uint64_t iteration_seed);
  //! Merges the iteration's outcomes into the database and the tree store in
  //! key order and returns the iteration's counters (also added to totals()).
  //! Only legs asked for by tours with index < `kept_tours` count: a caller
  //! that stopped some tours early (a rejected layout) keeps the stores
  //! independent of how far the stopped tours got.
  ReuseCounters end_iteration(int kept_tours = kAllTours);
  static constexpr int kAllTours = 1 << 30;

  LegOutcome resolve(const LegKey& key, const Pose2& from, const Pose2& to, std::uint64_t tour_seed,
                     bool may_plan, LegPlanner& planner, std::span<const LegRequest> next = {},
                     int tour = 0) override;
  //! Stops a fresh plan still unfound after kRefuseAfter RRT iterations
  //! when `gate` proves its leg impossible (null: never). Such legs count as
  //! failed fresh plans and as legs_proven.
  void set_gate(const ReachGate* gate) { gate_ = gate; }

  //! Legs planned by `speculate` and how many of them a tour then asked for
  //! in the same iteration (depends on thread timing: not for reports).
  struct Speculation {
    std::uint64_t planned = 0;
    std::uint64_t used = 0;
  };
  Speculation speculation() const;

  const ReuseOptions& options() const { return options_; }
  const ReuseCounters& totals() const { return totals_; }
  const PathDatabase& database() const { return database_; }
  const TreeStore& trees() const { return trees_; }
  //! Null when neither samples nor steering is on.
  const rs::Decomposition* decomposition() const { return decomposition_.get(); }
  //! Null unless `metrics` is on.
  LegMeasures* measures() { return measures_.get(); }

 private:
  //! Stage A: the stored path, transformed and validated (no RRT);
  //! `skipped`: served without a check, by PathDatabase::still_free().
  LegOutcome from_database(const LegKey& key, const Pose2& from, const Pose2& to,
                           bool& skipped) const;
  //! Stage B: repair, else a fresh plan (with a kept tree when on).
  LegOutcome plan_leg(const LegKey& key, const Pose2& from, const Pose2& to, std::uint64_t seed,
                      LegPlanner& planner, ReuseSlot& slot) const;
  //! The fresh RRT of stage B on `tree` (budget, backoff, the gate).
  LegResult fresh_plan(const LegKey& key, const Pose2& from, const Pose2& to, std::uint64_t seed,
                       LegPlanner& planner, RrtTree& tree, LegStats& stats, ReuseSlot& slot) const;
  //! Every technique off: the baseline's own plan, counted per tour.
  LegOutcome plan_alone(const LegKey& key, const Pose2& from, const Pose2& to,
                        std::uint64_t tour_seed, bool may_plan, LegPlanner& planner, int tour);

  //! The iteration's slot of `r.key`, made on first use; `request`: a tour
  //! asks for it (counted, and kept by end_iteration()), `may_plan`: with
  //! planning allowed (then stage B's outcome counts too).
  ReuseSlot* slot_for(const LegRequest& r, bool request, bool may_plan = false, int tour = 0);
  //! Stage A, then (when `may_plan`) stage B, each once per slot; the caller
  //! holds slot.mutex. The outcome a tour gets.
  LegOutcome settle(const LegKey& key, ReuseSlot& slot, bool may_plan, LegPlanner& planner) const;
  //! `speculate`: settles the first request of `next` that nobody has
  //! started, with planning allowed; false when there was none.
  bool speculate_one(std::span<const LegRequest> next, LegPlanner& planner);
  //! shorten_path() of a found path, its checks counted into `stats`.
  rs::Path shortened(const Pose2& from, const rs::Path& path, LegStats& stats) const;
  std::optional<LegOutcome> repair(const LegKey& key, const Pose2& from, const Pose2& to,
                                   std::uint64_t seed, LegPlanner& planner) const;

  const geometry::CSpace* cspace_;
  TourOptions tour_;
  ReuseOptions options_;
  double radius_;
  std::unique_ptr<rs::Decomposition> decomposition_;
  std::unique_ptr<DecompositionSampler> sampler_;
  std::unique_ptr<DecompositionSteering> steering_;
  std::unique_ptr<LegMeasures> measures_;
  PathDatabase database_;
  TreeStore trees_;
  geometry::Scene scene_;           //!< footprints for still_free() and the failures
  FailureMemory failures_;          //!< `failures` and `backoff`
  double still_free_margin_ = 0.0;  //!< see still_free()
  std::uint64_t iteration_seed_ = 0;
  std::mutex mutex_;  //!< guards slots_, leg_requests_ and the slots' `requested`
  std::atomic<std::uint64_t> speculated_{0}, speculated_used_{0};
  std::map<LegKey, std::unique_ptr<ReuseSlot>> slots_;
  std::map<int, std::uint64_t> leg_requests_;  //!< per tour
  std::map<int, ReuseCounters> unshared_;      //!< all techniques off: per request, per tour
  const ReachGate* gate_ = nullptr;
  ReuseCounters totals_;
};

}  // namespace hrs::planning
