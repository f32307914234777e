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

#include <array>
#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/cspace.h"
#include "geometry/free_grid.h"
#include "geometry/pose.h"
#include "geometry/scene.h"
#include "planning/leg_measures.h"
#include "planning/motion_validator.h"
#include "planning/rrt.h"
#include "planning/tour.h"
#include "rs/decomposition.h"

namespace hrs::planning {

//! Which §V techniques are on, and their parameters.
struct ReuseOptions {
  bool samples = true;   //!< §V-A: RRT samples from the RS-decomposition
  bool steering = true;  //!< §V-A: RS look-ups through the decomposition (exact fallback)
  bool paths = true;     //!< §V-B: path database, shared within and across iterations
  bool trees = true;     //!< §V-C: RRT trees reused while their root barely moves
  //! Beyond the paper: a leg whose RRT failed fails again, without planning,
  //! while its ends are unchanged and every object moved since stayed out of
  //! reach of every pose that RRT examined (then the same run would make the
  //! same collision queries with the same answers: a proof, not a guess).
  bool failures = true;
  //! Beyond the paper: every path the planner stores (fresh or repaired) is
  //! shortened first (shorten_path), so that reused paths are not the
  //! RRT's detours: without it, reuse trades tour length for time.
  bool shortcuts = true;
  //! Beyond the paper (its Fig. "rrt-it": a path that is found at all is
  //! nearly always found in few RRT iterations): a fresh plan stops after
  //! `budget_iterations` RRT iterations instead of the planner's own cap
  //! (3000). A leg that would have needed more fails and the tour tries its
  //! next pose pair: this trades a few hard legs for the time every failing
  //! leg used to cost, which the final costs must absorb (measured in
  //! docs/BENCHMARKS.md). Repairs keep their own, smaller budget.
  bool budget = true;
  //! Beyond the paper: the clearance metrics and the re-certification of a
  //! found leg are kept (planning/leg_measures.h) and brought up to date
  //! instead of recomputed, by the tours that share the leg and in later
  //! layouts. Exact: the results are the fresh ones to the last bit.
  bool metrics = true;
  //! Beyond the paper: a leg (by key) whose fresh plans failed k times in a
  //! row gets the fresh-plan budget halved k times, down to
  //! `backoff_floor` RRT iterations, and the whole budget again once found.
  //! The failures of a design run repeat by key (goal poses in tight spots
  //! fail layout after layout), and a leg that is found at all is nearly
  //! always found in few iterations (Fig. "rrt-it"). A heuristic: a leg that
  //! needs more than its reduced budget fails (measured in docs/BENCHMARKS.md).
  bool backoff = true;
  //! Beyond the paper; changes the work, never an outcome: a tour that asks
  //! for a leg another tour is planning at that moment (tours of an
  //! iteration share legs, computed once) plans, instead of waiting, the
  //! first leg of its own remaining candidates that nobody has started.
  //! A leg that keeps a tour waiting is usually failing (a found leg stops
  //! early), so that tour's next candidate is usually needed next. Legs
  //! computed this way and never asked for leave no trace: counters and
  //! stores take only the legs the tours asked for. One thread: no effect.
  bool speculate = true;
  int backoff_floor = 120;      //!< RRT iterations a backed-off fresh plan keeps at least
  int budget_iterations = 300;  //!< RRT iterations of a fresh plan with `budget` on
  //! Beyond the paper, opt-in (not in "all"): a fresh plan that has not
  //! found the leg after `proof_after` RRT iterations asks geometry::FreeGrid
  //! whether the leg's ends are in different components of a certified outer
  //! approximation of the free C-space; if so no motion exists and the leg
  //! fails at once, else the RRT goes on with the rest of its budget.
  //! Measured not to pay (docs/planner.md): the legs the RRT cannot find are
  //! nearly always connected in that approximation.
  bool proofs = false;
  int proof_after = 300;                 //!< RRT iterations before a proof is tried
  geometry::FreeGridOptions proof_grid;  //!< cells of the proof's grid
  //! Cells a proof may search: a proof succeeds when one end's component is
  //! small (a pocket), so large searches only cost time.
  std::size_t proof_cells = 20'000;
  //! §V-B: a stored path whose ends moved apart is repaired (valid part kept,
  //! gap re-planned) before a fresh plan is tried.
  bool repair = true;
  int repair_iterations = 30;  //!< RRT iterations allowed to close a repair's gap
  //! §V-B, exact (part of `paths`, no name of its own; off only in tests): a
  //! stored path that path_free() found free in an earlier layout, driven
  //! from the same start, is served without checking it again when every
  //! object that moved since stays clear of it by a proven margin
  //! (ReusePlanner::still_free): the check would pass.
  bool skip_far_checks = true;
  //! §V-C: a tree is kept while its root moved at most this much (metres +
  //! radians); the tree moves rigidly with its root and is then pruned.
  double tree_root_tolerance = 0.1;
  int tree_max_nodes = 30;           //!< §V-C: a tree past this many nodes is rebuilt (paper: 30)
  int decomposition_initial = 1000;  //!< K of the decomposition (paper: 1000)
  int decomposition_stop = 100;      //!< consecutive agreeing samples ending it (paper: 100)

  //! A technique's --reuse name and its switch.
  struct Technique {
    const char* name;
    bool ReuseOptions::*on;
  };
  //! Every technique, in the order names() lists them: the one list that
  //! parse(), names(), any() and none() go through.
  static const std::array<Technique, 11>& techniques();
  //! A technique's numeric parameter, set by NAME=N (budget=500, backoff=10).
  struct Parameter {
    const char* technique;
    bool ReuseOptions::*on;  //!< the technique NAME=N turns on
    int ReuseOptions::*value;
    const char* unit;
  };
  static const std::array<Parameter, 2>& parameters();

  //! True when at least one technique is on; all off is the baseline exactly.
  bool any() const;
  //! Every technique off.
  static ReuseOptions none();
  //! Parses "none" or a comma list of samples, steering, paths, trees,
  //! failures, shortcuts, budget, metrics, backoff, proofs and "all" (every technique on by
  //! default, i.e. all but proofs), applied left to right: a name turns its
  //! technique on, -name turns it off ("all,-budget"), NAME=N turns it on
  //! with parameter N (budget=500, backoff=10). hrs::InputError for any
  //! other item.
  static ReuseOptions parse(std::string_view list);
  //! The comma list of the techniques on ("none" when none).
  std::string names() const;
};

//! §V-A: RRT targets drawn uniformly from the decomposition's samples, mapped
//! from its doubled room (centred on the start) onto the room's bounding box.
class DecompositionSampler final : public SampleSource {
 public:
  DecompositionSampler(const rs::Decomposition& decomposition, const geometry::Scene& scene);
  Pose2 sample(std::mt19937_64& rng) override;

 private:
  const rs::Decomposition* decomposition_;
  double cx_, cy_, sx_, sy_;  //!< room centre and scale from the doubled room
};

//! §V-A: RS paths by the decomposition's predicted word; the exact shortest
//! path when the predicted word cannot connect the poses. Thread-safe.
class DecompositionSteering final : public Steering {
 public:
  explicit DecompositionSteering(const rs::Decomposition& decomposition)
      : decomposition_(&decomposition) {}
  double distance(const Pose2& from, const Pose2& to, double radius) override;
  rs::Path path(const Pose2& from, const Pose2& to, double radius) override;

 private:
  const rs::Decomposition* decomposition_;
};

//! A path from `start` to the same end that is at most as long as `path`:
//! greedy shortcuts between poses along it (every `step` metres and at
//! segment borders), each replacement the exact shortest RS path between
//! the two poses, kept only when shorter by more than 1 mm and free by the
//! continuous checks of `validator`. From each pose the farthest pose is
//! tried first, then halfway closer, down to the next pose. Deterministic.
rs::Path shorten_path(const Pose2& start, const rs::Path& path, MotionValidator& validator,
                      double step);

//! `b` in the frame of `a` (a's position at the origin, heading +x).
Pose2 relative_pose(const Pose2& a, const Pose2& b);
//! Distance (metres) plus absolute heading difference (radians).
double pose_gap(const Pose2& a, const Pose2& b);

//! §V-B: paths keyed by LegKey. A path is a list of RS segments driven from
//! its start, so it lives in the frame of its from-pose; its to-pose is kept
//! relative to that frame. When the current ends have the same relative pose
//! (both objects moved rigidly together, or neither moved), the stored path
//! driven from the new from-pose ends exactly at the new to-pose.
class PathDatabase final : public LegCache {
 public:
  struct Entry {
    rs::Path path;
    Pose2 from, to;  //!< world poses of the ends when stored
    //! Object poses of a layout in which MotionValidator::path_free(from,
    //! path) held; empty when the path was never checked that way (a fresh
    //! or repaired path was checked in pieces, which is not the same query).
    std::vector<Pose2> checked;
    //! With `checked`: the chair's reference positions along the path from
    //! `from`, at most kTraceStep metres apart, both ends included.
    std::vector<geometry::Vec2> trace;
  };
  //! Ends whose relative poses differ by at most this are "the same" (m + rad).
  static constexpr double kRigidTolerance = 1e-9;
  //! Spacing (metres of path) of Entry::trace.
  static constexpr double kTraceStep = 0.1;

  const Entry* find(const LegKey& key) const;
  //! The stored path transformed to the ends `from`, `to` when they are
  //! rigidly the same as the stored ones, else nullopt.
  std::optional<rs::Path> transformed(const LegKey& key, const Pose2& from, const Pose2& to) const;
  //! Stores the path; `checked`: the object poses of a layout in which
  //! path_free(from, path) held (empty: not known), then the trace is kept.
  void put(const LegKey& key, const Pose2& from, const Pose2& to, const rs::Path& path,
           std::vector<Pose2> checked = {});
  void erase(const LegKey& key) { entries_.erase(key); }
  std::size_t size() const { return entries_.size(); }

  // LegCache, for single-threaded use with a TourPlanner.
  bool lookup(const LegKey& key, const Pose2& from, const Pose2& to, rs::Path& out) override;
  void store(const LegKey& key, const Pose2& from, const Pose2& to, const rs::Path& path) override;
  void reject(const LegKey& key) override { erase(key); }

 private:
  std::map<LegKey, Entry> entries_;
};

//! Where an RRT tree is rooted: a goal pose of an object (−1: the door).
struct RootKey {
  int object = -1;
  int slot = 0;
  friend auto operator<=>(const RootKey&, const RootKey&) = default;
};

//! §V-C: RRT trees by root. A tree is handed out only while its root moved
//! at most `tree_root_tolerance`; it is moved rigidly onto the new root (its
//! edges are RS segments, so node poses are re-driven from the root), every
//! edge is re-checked continuously and invalid subtrees are dropped.
class TreeStore final : public TreeCache {
 public:
  TreeStore(const geometry::CSpace& cspace, double radius, const ReuseOptions& options)
      : cspace_(&cspace), radius_(radius), options_(options) {}

  //! A pruned copy of the tree of `root` moved onto `from`, or nullopt when
  //! there is none, its root moved too far, or it is too large. Counts the
  //! edge checks into `checks`. Const: safe from parallel tours.
  std::optional<RrtTree> usable(const RootKey& root, const Pose2& from,
                                std::uint64_t* checks = nullptr) const;
  //! Keeps `tree` for `root`, or forgets the root's tree when `tree` has
  //! more than tree_max_nodes nodes (rebuilt next time).
  void put(const RootKey& root, RrtTree tree);
  std::size_t size() const { return trees_.size(); }

  // TreeCache, for single-threaded use with a TourPlanner.
  RrtTree* tree_for(const LegKey& key, const Pose2& from) override;

 private:
  const geometry::CSpace* cspace_;
  double radius_;
  ReuseOptions options_;
  std::map<RootKey, RrtTree> trees_;
};

//! Counts over a design run (or one iteration). Deterministic: legs are
//! counted once per key and iteration, from the pure outcomes.
struct ReuseCounters {
  std::uint64_t legs_database = 0;  //!< served from the database, transformed and validated
  std::uint64_t legs_repaired = 0;  //!< stored path repaired (valid part kept, gap planned)
  std::uint64_t legs_planned = 0;   //!< planned fresh and found
  std::uint64_t legs_failed = 0;    //!< planned fresh, nothing found
  std::uint64_t legs_rejected = 0;  //!< stored paths not valid as they were
  //! Of legs_database: no check run, every object moved since the last
  //! check stood out of reach (ReuseOptions::skip_far_checks).
  std::uint64_t checks_skipped = 0;
  std::uint64_t trees_reused = 0;     //!< fresh plans that grew a kept tree
  std::uint64_t failures_reused = 0;  //!< failed legs known to fail again (in legs_failed)
  std::uint64_t legs_proven = 0;      //!< failed legs proven impossible (in legs_failed)
  std::uint64_t leg_requests = 0;     //!< leg look-ups by tours (shared legs counted per tour)
  //! RRT iterations of the successful fresh plans: iterations → count (Fig. "rrt-it").
  std::map<int, std::uint64_t> rrt_iterations;
  //! Work behind the outcomes (wall time, not reproducible): database
  //! validations, repairs, fresh plans found, fresh plans failed.
  double database_ms = 0.0, repaired_ms = 0.0, planned_ms = 0.0, failed_ms = 0.0;
  double proof_ms = 0.0;  //!< of which proofs (grid updates and searches)
  ReuseCounters& operator+=(const ReuseCounters& other);
};

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
  ReuseCounters end_iteration();

  LegOutcome resolve(const LegKey& key, const Pose2& from, const Pose2& to, std::uint64_t tour_seed,
                     bool may_plan, LegPlanner& planner,
                     std::span<const LegRequest> next = {}) override;

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
  struct Slot;
  //! A failed RRT run: its ends, the layout it ran in, and every position
  //! its collision queries were centred near (nodes and the goal).
  struct Failure {
    Pose2 from, to;
    std::vector<Pose2> layout;
    std::vector<geometry::Vec2> points;
  };
  //! True when the recorded failure of `key` provably repeats now.
  bool failure_repeats(const LegKey& key, const Pose2& from, const Pose2& to) const;
  //! True when path_free(e.from, e.path), which held in the layout
  //! e.checked, provably holds now: the walls never move and the footprint
  //! of every object that moved since lies (now) farther than
  //! still_free_margin_ from each point of e.trace. Its old pose blocked
  //! nothing then and is gone, so no query of the check can change to
  //! "blocked" (cspace.h; the margin's terms are in the constructor).
  bool still_free(const PathDatabase::Entry& e) const;
  //! Stage A: the stored path, transformed and validated (no RRT);
  //! `skipped`: served without a check, by still_free().
  LegOutcome from_database(const LegKey& key, const Pose2& from, const Pose2& to,
                           bool& skipped) const;
  //! Stage B: repair, else a fresh plan (with a kept tree when on).
  LegOutcome plan_leg(const LegKey& key, const Pose2& from, const Pose2& to, std::uint64_t seed,
                      LegPlanner& planner, Slot& slot) const;
  //! The iteration's slot of `r.key`, made on first use; `request`: a tour
  //! asks for it (counted, and kept by end_iteration()), `may_plan`: with
  //! planning allowed (then stage B's outcome counts too).
  Slot* slot_for(const LegRequest& r, bool request, bool may_plan = false);
  //! Stage A, then (when `may_plan`) stage B, each once per slot; the caller
  //! holds slot.mutex. The outcome a tour gets.
  LegOutcome settle(const LegKey& key, Slot& slot, bool may_plan, LegPlanner& planner) const;
  //! `speculate`: settles the first request of `next` that nobody has
  //! started, with planning allowed; false when there was none.
  bool speculate_one(std::span<const LegRequest> next, LegPlanner& planner);
  //! shorten_path() of a found path, its checks counted into `stats`.
  rs::Path shortened(const Pose2& from, const rs::Path& path, LegStats& stats) const;
  //! True when FreeGrid proves that no motion joins `from` and `to` in the
  //! current layout (the grid is brought up to date once per iteration).
  bool proven_impossible(const Pose2& from, const Pose2& to) const;
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
  std::map<LegKey, Failure> failures_;
  //! `backoff`: fresh plans of the key that failed in a row since last found.
  std::map<LegKey, int> failed_in_a_row_;
  geometry::Scene scene_;  //!< footprints for failure_repeats(), the proof grid
  //! The proof grid and its per-thread searches; built on the first proof,
  //! moved to the current layout at the first proof of each iteration.
  mutable std::mutex proof_mutex_;
  mutable std::unique_ptr<geometry::FreeGrid> grid_;
  mutable bool grid_current_ = false;
  mutable bool grid_unavailable_ = false;
  mutable std::vector<std::unique_ptr<geometry::ReachabilityQuery>> idle_queries_;
  double reach_ = 0.0;              //!< how far from a node a collision query can look
  double still_free_margin_ = 0.0;  //!< see still_free()
  std::uint64_t iteration_seed_ = 0;
  std::mutex mutex_;  //!< guards slots_, leg_requests_ and the slots' `requested`
  std::atomic<std::uint64_t> speculated_{0}, speculated_used_{0};
  std::map<LegKey, std::unique_ptr<Slot>> slots_;
  std::uint64_t leg_requests_ = 0;
  ReuseCounters unshared_;  //!< all techniques off: legs counted per request
  ReuseCounters totals_;
};

}  // namespace hrs::planning
