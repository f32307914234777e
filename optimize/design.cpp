// SPDX-License-Identifier: GPL-3.0-or-later
#include "optimize/design.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <optional>
#include <random>
#include <stdexcept>

#include "geometry/error.h"
#include "geometry/polygon_ops.h"
#include "geometry/random.h"
#include "optimize/escape.h"
#include "optimize/tour_proxy.h"
#include "optimize/tour_round.h"

namespace hrs::optimize {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::vector<bool> movable_of(const geometry::Scene& scene) {
  std::vector<bool> out;
  for (const auto& o : scene.objects) out.push_back(!o.fixed);
  return out;
}

//! With all path weights 0 the cost does not depend on the tours: plan only
//! the initial and the best layout (Fig. 1's "designed without the chair").
bool plans_every_iteration(const geometry::Scene& scene) {
  const auto& wp = scene.weights.path;
  return wp[0] != 0.0 || wp[1] != 0.0 || wp[2] != 0.0;
}

//! One design run (paper §III-E with the tours of §III-C): the annealer's
//! callbacks on one object, each step a named member. run() is design().
class DesignRun {
 public:
  DesignRun(const geometry::Scene& scene, const DesignOptions& options,
            const std::atomic<bool>* stop, const std::function<void(const DesignStep&)>& progress)
      : t0_(Clock::now()),
        scene_(scene),
        options_(options),
        stop_(stop),
        progress_(progress),
        sequences_(scene_sequences(scene, stop)),
        model_(scene, sequences_),
        round_(scene, options, sequences_, stop),
        movable_(movable_of(scene)),
        plan_every_iteration_(plans_every_iteration(scene)),
        escape_(scene, round_, sequences_, movable_, options,
                plan_every_iteration_) {
    result_.sequences = sequences_;
    result_.threads = round_.threads();
    for (const auto& o : scene.objects) poses_.push_back(o.pose);
    poses_initial_ = poses_;
    model_.set_bounded_preferences(options.planner.prefer);
    model_.set_uniform_alpha(options.uniform_alpha);
    result_.planned_every_iteration = plan_every_iteration_;
    valid_ = [this](const std::vector<Pose2>& p, int moved) { return move_valid(p, moved); };
    move_ = [this](int o, const Pose2& to) { round_.move(o, to); };
  }

  DesignResult run() {
    // A stop before the first plan: there is no design yet (design.h).
    throw_if_stopped(stop_, "design setup");
    result_.time_setup_s = seconds_since(t0_);
    const auto anneal0 = Clock::now();
    plan_current();
    current_terms_ = model_.evaluate(poses_, round_.tours(), &round_.blockage());
    result_.initial = current_terms_;
    escape_.refresh_open_stops();
    // Validity comes first: separation may cover a stop (the unblocking
    // and the annealing open it again).
    const EscapePolicy::ValidFn fits = [this](const std::vector<Pose2>& p, int moved) {
      return round_.fits(p, moved);
    };
    result_.unblock.separated = escape_.separate(poses_, options_.seed, fits, move_,
                                                result_.unblock.separation_passes);
    if (result_.unblock.separated > 0) escape_.refresh_open_stops();
    result_.unblock.left_invalid = layout_violation(round_.scene());
    if (escape_.unblock(poses_, options_.seed, stop_, valid_, move_, result_.unblock) ||
        result_.unblock.separated > 0) {
      plan_current();  // the annealing starts from the unblocked layout
      current_terms_ = model_.evaluate(poses_, round_.tours(), &round_.blockage());
    }
    if (options_.planner.prefer && options_.opening) open_arrangement();
    focus_current_ = escape_.walling_objects();
    current_tours_ = round_.tours();
    const AnnealOptions schedule = make_schedule();
    std::mt19937_64 rng(options_.seed);
    const AnnealResult r = anneal(poses_, movable_, schedule, callbacks(), rng, stop_);
    const auto finish0 = Clock::now();
    result_.time_anneal_s = std::chrono::duration<double>(finish0 - anneal0).count();
    finish(r);
    result_.time_finish_s = seconds_since(finish0);
    result_.time_total_s = seconds_since(t0_);
    return std::move(result_);
  }

 private:
  //! Plans the M tours of the current layout (round `iteration_`); with a
  //! bound, stops once the bound is rejected (outcome_.rejected).
  void plan_current(const TourRound::Bound* bound = nullptr) {
    const auto p0 = Clock::now();
    if (options_.layouts_out) {
      options_.layouts_out->emplace_back();
      for (int i = 0; i < round_.cspace().object_count(); ++i)
        options_.layouts_out->back().push_back(round_.cspace().object_pose(i));
    }
    outcome_ = round_.plan(iteration_, iteration_legs_, bound);
    result_.tours_invalidated += outcome_.dropped;
    result_.tours_planned += outcome_.kept;
    for (int k = 0; k < outcome_.kept; ++k) result_.legs_refused += round_.tours()[k].stats.legs_refused;
    if (outcome_.rejected) skipped_from(outcome_.kept);
    const double ms = 1e3 * seconds_since(p0);
    planning_ms_ += ms;
    result_.time_planning_s += ms / 1e3;
  }

  //! Temperatures from the initial cost (docs/optimize.md), jumps inside
  //! the room's bounding box unless the options bound them.
  AnnealOptions make_schedule() {
    AnnealOptions schedule = moves();
    schedule.iterations = options_.iterations;
    schedule.t_start = std::max(1e-6, options_.t_start_fraction * current_terms_.total());
    schedule.t_end = schedule.t_start * options_.t_end_ratio;
    result_.t_start = schedule.t_start;
    result_.t_end = schedule.t_end;
    return schedule;
  }

  //! The annealer's moves; jumps inside the room's bounding box unless bounded.
  AnnealOptions moves() const {
    AnnealOptions m = options_.anneal;
    const geometry::Box b = geometry::bounding_box(scene_.room.polygon);
    if (!m.bounds) m.bounds = std::array<double, 4>{b.xmin, b.ymin, b.xmax, b.ymax};
    return m;
  }

  AnnealCallbacks callbacks() {
    AnnealCallbacks cb;
    cb.move_valid = valid_;
    cb.cost = [this](const std::vector<Pose2>& p, const Move& move, const Acceptance& a) {
      return cost(p, move, a);
    };
    cb.rejected = [this](const Move& move) { undo(move); };
    cb.layout_valid = [this](const std::vector<Pose2>&) {
      return layout_violation(round_.scene()).empty();
    };
    cb.new_best = [this] { new_best(); };
    cb.progress = [this](const TraceEntry& e) { step_done(e); };
    cb.focus = [this] { return focus_current_; };
    if (options_.planner.prefer)
      cb.preferred = [this](const std::vector<Pose2>& p, int o, std::mt19937_64& rng) {
        return preferred_move(p, o, rng);
      };
    return cb;
  }

  //! A preference move (AnnealCallbacks::preferred): one of the object's
  //! preferred poses or a wall slot, uniformly.
  std::optional<Pose2> preferred_move(const std::vector<Pose2>& p, int o, std::mt19937_64& rng) {
    std::vector<Pose2> c = preferred_poses(round_.scene(), model_, p, o);
    if (const auto slot = wall_slot(round_.scene(), o, rng)) c.push_back(*slot);
    if (c.empty()) return std::nullopt;
    return c[uniform_index(rng, c.size())];
  }

  //! The exact checks of one moved object, before any planning.
  //! Every object is taken at `p` (a pair move of the polish checks the
  //! partner against the object's new pose, and the covered-stop rule
  //! moves both in the C-space).
  bool move_valid(const std::vector<Pose2>& p, int moved) {
    return round_.fits(p, moved) && !escape_.covers_a_stop(p, moved);
  }

  //! Applies a proposal to the C-space, tours it and returns its cost, or
  //! a lower bound of it that `acceptance` rejects (early rejection).
  double cost(const std::vector<Pose2>& p, const Move& move, const Acceptance& acceptance) {
    if (move.object < 0) return current_terms_.total();
    proposed_ = true;
    ++iteration_;
    round_.move(move.object, move.to);
    planning_ms_ = 0.0;
    rejected_early_ = false;
    outcome_ = {};
    if (!plan_every_iteration_) {
      proposed_terms_ = model_.evaluate(p, round_.tours());
      return proposed_terms_.total();
    }
    const InteriorCosts in = model_.interior(p);
    if (!options_.planner.early) {
      plan_current();
      proposed_terms_ = model_.evaluate(in, round_.tours(), &round_.blockage());
      return proposed_terms_.total();
    }
    // Rejected on the interior alone, or on the grid's floors: no tour is
    // planned.
    const double base = model_.interior_terms(in).total();
    if (acceptance.rejects(base)) return rejected_unplanned(in, base);
    const std::vector<double> floors = pre_planning_floors();
    double pre = base;
    for (double f : floors) pre += f;
    if (!floors.empty() && acceptance.rejects(pre)) return rejected_unplanned(in, pre);
    const TourRound::Bound bound{&model_, base, &acceptance, floors.empty() ? nullptr : &floors};
    plan_current(&bound);
    if (outcome_.rejected) {
      rejected_early_ = true;
      proposed_terms_ = model_.evaluate(in, round_.tours(), &round_.blockage(), outcome_.kept);
      return outcome_.bound;
    }
    proposed_terms_ = model_.evaluate(in, round_.tours(), &round_.blockage());
    return proposed_terms_.total();
  }

  //! A proposal rejected before any tour was planned, on the lower bound `bound`.
  double rejected_unplanned(const InteriorCosts& in, double bound) {
    rejected_early_ = true;
    proposed_terms_ = model_.evaluate(in, round_.tours(), &round_.blockage(), 0);
    skipped_from(0);
    return bound;
  }

  //! The grid's lower bounds of the tours' costs before anything is planned
  //! (TourRound::certain_floors), or none: asked by the baseline (or the
  //! proposed planner with every technique off) while the current layout
  //! misses tours, where a fill costs less than the legs it can spare.
  //! Floors only bound: the decisions are the same with or without them.
  std::vector<double> pre_planning_floors() {
    const bool baseline_like = !options_.planner.proposed || !options_.planner.reuse.any();
    if (!baseline_like || !options_.planner.refuse) return {};
    if (current_terms_.tours_found == current_terms_.tours_total) return {};
    const auto f0 = Clock::now();
    std::vector<double> floors = round_.certain_floors(model_);
    planning_ms_ = 1e3 * seconds_since(f0);  // planning work: counted as such
    result_.time_planning_s += planning_ms_ / 1e3;
    return floors;
  }


  //! Counts an early rejection that left tours `first`… unplanned.
  void skipped_from(int first) {
    ++result_.early.proposals;
    for (std::size_t k = static_cast<std::size_t>(first); k < sequences_.size(); ++k) {
      ++result_.early.tours_skipped;
      result_.early.legs_skipped += static_cast<long>(sequences_[k].nodes.size()) - 1;
    }
  }

  void undo(const Move& move) { round_.move(move.object, move.from); }

  //! Called for the initial layout (before any proposal) or right after an
  //! accepted proposal: the round's tours and the terms belong to the current layout.
  void new_best() {
    if (!proposed_) {
      result_.final = current_terms_;
      result_.tours = current_tours_;
    } else {
      result_.final = proposed_terms_;
      result_.tours = round_.tours();
    }
  }

  //! The trace entry of one iteration; an accepted proposal becomes current.
  void step_done(const TraceEntry& e) {
    DesignStep step;
    step.anneal = e;
    if (e.valid) {
      step.proposed = proposed_terms_;
      step.planning_ms = planning_ms_;
      step.planned = plan_every_iteration_;
      step.rejected_early = rejected_early_;
      if (plan_every_iteration_) step.legs = iteration_legs_;
    }
    if (e.accepted) {
      current_terms_ = proposed_terms_;
      current_tours_ = round_.tours();
      // Right after the decision the round's tours and grades are still the
      // accepted layout's: the focus is computed for accepted layouts only.
      focus_current_ = plan_every_iteration_ ? escape_.walling_objects() : std::vector<int>{};
      escape_.refresh_open_stops();
    }
    result_.trace.push_back(step);
    if (progress_) progress_(step);
  }

  //! The hooks of an untoured arrangement: the design's validity, moves
  //! that the C-space follows (so the covered-stop rule sees the
  //! arrangement) and the annealer's preference moves.
  ArrangeHooks arrange_hooks() {
    ArrangeHooks hooks;
    hooks.valid = valid_;
    hooks.set = move_;
    hooks.preferred = [this](const std::vector<Pose2>& p, int o, std::mt19937_64& rng) {
      return preferred_move(p, o, rng);
    };
    return hooks;
  }

  //! The opening arrangement (docs/optimize.md "Preferences", with
  //! PlannerConfig::prefer): before the tour annealing, the input layout is
  //! re-packed on the interior cost alone (arrange(), nothing planned), the
  //! objects without a wall distance preference drawn to the walls
  //! (opening_pull()). The arranged layout is toured once, and the
  //! annealing starts from it when it finds at least the input's tours at a
  //! lower total cost; else the input is placed and toured again.
  void open_arrangement() {
    auto& o = result_.opening;
    const int per_object = opening_proposals_per_object(scene_);
    if (per_object == 0) return;  // beyond the work bound: no opening
    o.ran = true;
    o.tours_found_before = o.tours_found_after = current_terms_.tours_found;
    o.cost_before = o.cost_after = current_terms_.total();
    const auto t0 = Clock::now();
    const ArrangeHooks hooks = arrange_hooks();
    ArrangeOptions options;
    options.iterations_per_object = per_object;
    options.extra = opening_pull(scene_, model_, movable_);
    // A seed apart from the final arrangement's (seed + round).
    const ArrangeResult a = arrange(model_, movable_, poses_, moves(), options, hooks,
                                    options_.seed + 7919, stop_);
    o.proposals = a.proposals;
    o.ms = 1e3 * seconds_since(t0);
    if (a.poses == poses_ || (stop_ && stop_->load())) return;
    const std::vector<Pose2> input = poses_;
    const auto place = [&](const std::vector<Pose2>& from, const std::vector<Pose2>& to) {
      for (std::size_t i = 0; i < to.size(); ++i)
        if (to[i] != from[i]) move_(static_cast<int>(i), to[i]);
    };
    place(input, a.poses);
    const CostTerms t = replan(a.poses);
    o.tours_found_after = t.tours_found;
    o.cost_after = t.total();
    if (t.tours_found >= current_terms_.tours_found && t.total() < current_terms_.total()) {
      o.kept = true;
      poses_ = a.poses;
      current_terms_ = t;
      escape_.refresh_open_stops();
      return;
    }
    place(a.poses, input);
    current_terms_ = replan(poses_);
  }

  //! Tours the placed layout `p` in a round of its own.
  CostTerms replan(const std::vector<Pose2>& p) {
    ++iteration_;
    plan_current();
    return model_.evaluate(p, round_.tours(), &round_.blockage());
  }

  //! The preference arrangement (optimize/arrange.h) of the best layout
  //! `poses` (placed; toured: `terms` and result_.tours).
  void arrange_best(std::vector<Pose2>& poses, CostTerms& terms) {
    const ArrangeHooks hooks = arrange_hooks();
    ToursHooks toured;
    toured.place = move_;
    toured.plan = [this](const std::vector<Pose2>& p) { return replan(p); };
    for (int k = 0; k < kArrangeRounds; ++k) {
      // The best layout's tours: the round's may hold the last proposal's, whose
      // tail an early rejection left to the threads' timing.
      const ArrangeReport a = arrange_toured(scene_, model_, movable_, result_.tours, poses,
                                             terms, moves(), hooks, toured, options_.seed + k,
                                             stop_);
      result_.arrange.add(a, k == 0);
      if (!a.kept) break;
      result_.tours = round_.tours();
    }
  }

  //! The final polish (optimize/polish.h) of the best layout, written into
  //! result_.layout, result_.final and result_.tours.
  void polish_best(const AnnealResult& r) {
    std::vector<Pose2> poses = r.best;
    round_.place(poses);
    escape_.refresh_open_stops();  // the covered-stop rule asks the best layout's stops
    poses_ = poses;
    CostTerms terms = result_.final;
    if (!plan_every_iteration_) {
      iteration_ = r.proposals + 1;
      plan_current();
      terms = model_.evaluate(poses, round_.tours(), &round_.blockage());
      result_.tours = round_.tours();
      result_.final = terms;
    }
    // Feasibility first: stops the annealing left walled off are unblocked
    // before the preference stages, which then keep the tours this finds.
    if (options_.planner.rescue && result_.valid && terms.tours_found < terms.tours_total) {
      result_.rescue.tours_unfound = terms.tours_total - terms.tours_found;
      result_.rescue.unblocked += unblock_unfound(poses, terms);
      result_.final = terms;
      unblocked_layout_ = poses;
    }
    arrange_best(poses, terms);
    result_.polish.tours_found_before = terms.tours_found;
    result_.polish.met_before = check_preferences(scene_, model_, poses).met;
    PolishHooks hooks;
    hooks.valid = valid_;
    hooks.fits = [this](const std::vector<Pose2>& p, int moved) { return round_.fits(p, moved); };
    hooks.place = move_;
    hooks.plan = [this](const std::vector<Pose2>& p) { return replan(p); };
    hooks.kept = [this] { result_.tours = round_.tours(); };
    hooks.tours = [this]() -> const std::vector<planning::Tour>& { return result_.tours; };
    hooks.seed = splitmix64(options_.seed ^ 0x706f6c697368ULL);
    std::optional<TourProxy> proxy;
    if (options_.planner.shorten) {
      proxy.emplace(scene_, model_, round_.local_goals());
      hooks.tour_proxy = [&proxy](const std::vector<Pose2>& p) { return proxy->value(p); };
    }
    const int max_tries = std::max(20, 4 * static_cast<int>(poses.size()));
    const PolishResult pr = polish(scene_, model_, movable_, poses, terms, hooks, max_tries, stop_);
    static_cast<PolishResult&>(result_.polish) = pr;
    if (!result_.arrange.kept && pr.kept == 0 && pr.squared == 0 && pr.turned == 0) return;
    for (std::size_t i = 0; i < poses.size(); ++i) result_.layout.objects[i].pose = poses[i];
    result_.final = terms;
    result_.valid = layout_violation(result_.layout).empty();
  }

  //! Stops still walled off in layout `p` (placed and toured: `terms`,
  //! result_.tours) are unblocked once more (EscapePolicy::unblock); the
  //! unblocked layout is kept, in `p`, `terms`, result_.tours and
  //! result_.layout, when it finds more tours. Returns the tours gained.
  int unblock_unfound(std::vector<Pose2>& p, CostTerms& terms) {
    escape_.refresh_open_stops();
    std::vector<Pose2> q = p;
    DesignResult::Unblock stats;
    if (!escape_.unblock(q, options_.seed + 1, stop_, valid_, move_, stats)) return 0;
    const CostTerms t = replan(q);
    if (t.tours_found <= terms.tours_found) {
      round_.place(p);
      escape_.refresh_open_stops();  // the unblocking left them at `q`'s
      return 0;
    }
    const int gained = t.tours_found - terms.tours_found;
    p = q, terms = t, result_.tours = round_.tours();
    for (std::size_t i = 0; i < p.size(); ++i) result_.layout.objects[i].pose = p[i];
    return gained;
  }

  //! The rescue of the final layout's unfound tours (PlannerConfig::rescue):
  //! stops still walled off are unblocked once more when the layout changed
  //! since the polish's unblocking (unblock_unfound), then the lattice plans
  //! the legs the RRT misses (TourRound::rescue).
  void rescue_tours() {
    auto& r = result_.rescue;
    const int unfound = result_.final.tours_total - result_.final.tours_found;
    if (unfound == 0) return;
    if (unblocked_layout_.empty()) r.tours_unfound = unfound;  // else the first unblocking's
    const auto t = Clock::now();
    std::vector<Pose2> p;  // the final layout
    for (const auto& o : result_.layout.objects) p.push_back(o.pose);
    round_.place(p);
    if (p != unblocked_layout_) r.unblocked += unblock_unfound(p, result_.final);
    r.ran = true, r.tours_found = round_.rescue(p, result_.tours, ++iteration_);
    if (r.tours_found > 0) {
      result_.tours = round_.tours();
      result_.final = model_.evaluate(p, round_.tours(), &round_.blockage());
    }
    r.ms = 1e3 * seconds_since(t);
  }

  //! The best layout, its tours (toured now when the tours were not planned
  //! every iteration) and the run's counts.
  void finish(const AnnealResult& r) {
    result_.layout = scene_;
    for (std::size_t i = 0; i < scene_.objects.size(); ++i)
      result_.layout.objects[i].pose = r.best[i];
    result_.valid = r.best_valid && layout_violation(result_.layout).empty();
    if (!r.best_valid) {
      // No valid layout was ever seen: report the chain's last state.
      for (std::size_t i = 0; i < scene_.objects.size(); ++i)
        result_.layout.objects[i].pose = r.final_poses[i];
      result_.final = current_terms_;
      result_.tours = current_tours_;
    }
    const bool polished = options_.planner.prefer && r.best_valid && !(stop_ && stop_->load());
    if (polished) polish_best(r);
    if (!plan_every_iteration_ && r.best_valid && !polished) {
      round_.place(r.best);
      iteration_ = r.proposals + 1;
      plan_current();
      result_.tours = round_.tours();
      result_.final = model_.evaluate(r.best, round_.tours(), &round_.blockage());
    }
    if (options_.planner.rescue && result_.valid) rescue_tours();
    result_.proposals = r.proposals;
    result_.valid_proposals = r.valid_proposals;
    result_.accepted = r.accepted;
    result_.stopped = r.stopped;
    result_.proposed = options_.planner.proposed;
    result_.planner = options_.planner.name();
    result_.preferences_initial = check_preferences(scene_, model_, poses_initial_);
    std::vector<Pose2> best;
    for (const auto& o : result_.layout.objects) best.push_back(o.pose);
    result_.preferences = check_preferences(scene_, model_, best);
    result_.covering_moves = escape_.covering_moves();
    result_.gate_fills = round_.gate().fills();
    result_.gate_ms = round_.gate().fill_ms();
    if (result_.tours_planned > 0)
      result_.early.saved_s_estimate =
          result_.early.tours_skipped * result_.time_planning_s / result_.tours_planned;
    if (planning::ReusePlanner* reuse = round_.reuse()) {
      result_.legs_refused = static_cast<long>(reuse->totals().legs_proven);
      result_.reuse = options_.planner.reuse.names();
      result_.counters = reuse->totals();
    }
  }

  Clock::time_point t0_;
  const geometry::Scene& scene_;
  DesignOptions options_;
  const std::atomic<bool>* stop_;
  const std::function<void(const DesignStep&)>& progress_;
  std::vector<Sequence> sequences_;
  CostModel model_;
  TourRound round_;
  std::vector<Pose2> poses_;
  std::vector<Pose2> poses_initial_;  //!< the input layout's
  std::vector<Pose2> unblocked_layout_;  //!< the layout the polish's unblocking left
  std::vector<bool> movable_;
  bool plan_every_iteration_ = true;
  EscapePolicy escape_;
  //! The exact checks of a move (move_valid) and a move of the working
  //! layout, as the escape policy, the arrangement and the polish take them.
  EscapePolicy::ValidFn valid_;
  EscapePolicy::PlaceFn move_;
  std::vector<int> focus_current_;  //!< walling_objects() of the current layout
  //! The round of the last plan: 0 the input layout, then the opening
  //! arrangement's (one or two), then one per proposal.
  int iteration_ = 0;
  bool proposed_ = false;  //!< the annealer has made a proposal (new_best: not the start)
  double planning_ms_ = 0.0;
  TourRound::Outcome outcome_;
  bool rejected_early_ = false;
  std::optional<planning::ReuseCounters> iteration_legs_;
  CostTerms current_terms_, proposed_terms_;
  std::vector<planning::Tour> current_tours_;
  DesignResult result_;
};

}  // namespace

std::uint64_t tour_seed(std::uint64_t seed, int iteration, int tour) {
  std::uint64_t h = splitmix64(seed);
  h = splitmix64(h ^ static_cast<std::uint64_t>(iteration));
  return splitmix64(h ^ (static_cast<std::uint64_t>(tour) << 32));
}

DesignResult design(const geometry::Scene& scene, const DesignOptions& options,
                    const std::atomic<bool>* stop,
                    const std::function<void(const DesignStep&)>& progress) {
  return DesignRun(scene, options, stop, progress).run();
}

}  // namespace hrs::optimize
