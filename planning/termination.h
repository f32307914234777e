// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// When a leg's search stops. One value, `Termination`, composes every reason
// a caller may have: an iteration cap (the planner's own, a repair's smaller
// one, the `budget` and `backoff` techniques' reduced ones), a tree-size cap,
// a give-up question (the refusal gate: does the certified free grid separate
// the leg's ends?) and a cancellation flag (a layout already rejected by the
// annealer's bound). The search asks one `StopRule` before every iteration
// instead of checking its own counters, in the spirit of OMPL's
// PlannerTerminationCondition (Şucan, Moll and Kavraki 2012), where
// conditions are predicates combined with "or".
//
// The give-up question is expensive (a grid fill), so it is asked at most
// once per search: when `after` iterations have run without the goal, or
// when the search stops earlier for another reason (a smaller cap, a full
// tree). A cap below `after` therefore never hides the question.

#include <atomic>
#include <cstdint>
#include <functional>
#include <utility>

namespace hrs::planning {

//! Why a search stopped without the goal (kNone: it has not stopped).
enum class StopReason : std::uint8_t {
  kNone,        //!< still running, or stopped at the goal
  kIterations,  //!< the iteration cap
  kTreeFull,    //!< the tree-size cap
  kGaveUp,      //!< the give-up question answered yes: no path can exist
  kCancelled,   //!< the cancellation flag was raised
};

//! The stop conditions of one leg search. Every field is optional; the
//! default stops only at the planner's own caps.
struct Termination {
  int max_iterations = -1;  //!< >= 0: overrides the planner's iteration cap
  int max_nodes = -1;       //!< >= 0: overrides the planner's tree-size cap
  //! Asked once: after `give_up_after` iterations without the goal, or at an
  //! earlier stop. True stops the search (kGaveUp).
  int give_up_after = 0;
  std::function<bool()> give_up;
  //! Read before every iteration; true stops the search (kCancelled). Only
  //! for searches whose result is discarded when cancelled.
  const std::atomic<bool>* cancel = nullptr;

  Termination& iterations(int cap) {
    max_iterations = cap;
    return *this;
  }
  Termination& nodes(int cap) {
    max_nodes = cap;
    return *this;
  }
  Termination& ask_after(int after, std::function<bool()> question) {
    give_up_after = after;
    give_up = std::move(question);
    return *this;
  }
  Termination& cancelled_by(const std::atomic<bool>* flag) {
    cancel = flag;
    return *this;
  }
};

//! The running evaluation of a Termination for one search.
class StopRule {
 public:
  //! `iteration_cap` and `node_cap` are the planner's own, used where the
  //! Termination sets none.
  StopRule(const Termination& t, int iteration_cap, int node_cap)
      : t_(t),
        iteration_cap_(t.max_iterations >= 0 ? t.max_iterations : iteration_cap),
        node_cap_(t.max_nodes >= 0 ? t.max_nodes : node_cap) {}

  //! Asked before iteration `done` + 1, with `nodes` in the tree: the reason
  //! to stop, or kNone to run it.
  StopReason before_iteration(int done, int nodes) {
    if (t_.cancel && t_.cancel->load(std::memory_order_relaxed)) return StopReason::kCancelled;
    if (done == t_.give_up_after && ask()) return StopReason::kGaveUp;
    if (done >= iteration_cap_) return StopReason::kIterations;
    if (nodes >= node_cap_) return StopReason::kTreeFull;
    return StopReason::kNone;
  }
  //! The search stopped without the goal for `why` (a cap): the question,
  //! if not asked yet, is asked now and may turn the reason into kGaveUp.
  StopReason unfound(StopReason why) {
    if (why == StopReason::kIterations || why == StopReason::kTreeFull)
      if (ask()) return StopReason::kGaveUp;
    return why;
  }
  int iteration_cap() const { return iteration_cap_; }

 private:
  bool ask() {
    if (asked_ || !t_.give_up) return false;
    asked_ = true;
    return t_.give_up();
  }
  const Termination& t_;
  int iteration_cap_;
  int node_cap_;
  bool asked_ = false;
};

}  // namespace hrs::planning
