// SPDX-License-Identifier: GPL-3.0-or-later
#include "optimize/annealer.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>

#include "geometry/random.h"

namespace hrs::optimize {

double acceptance_probability(double delta, double t) {
  if (delta <= 0.0) return 1.0;
  if (!(t > 0.0)) return 0.0;
  return std::exp(-delta / t);
}

bool metropolis_accept(double delta, double t, double u) {
  return u < acceptance_probability(delta, t);
}

bool Acceptance::rejects(double lower_bound) const {
  if (!active) return false;
  const double margin = 1e-9 * std::max(1.0, std::abs(lower_bound));
  return !metropolis_accept(lower_bound - margin - current, temperature, u);
}

namespace {

//! a·(b/a)^(k/(n−1)): geometric interpolation over the iterations.
double geometric(double a, double b, int k, int n) {
  if (n <= 1 || a <= 0.0 || b <= 0.0) return a;
  return a * std::pow(b / a, static_cast<double>(k) / (n - 1));
}

}  // namespace

double temperature_at(const AnnealOptions& options, int k) {
  return geometric(options.t_start, options.t_end, k, options.iterations);
}

namespace {

//! Sets `move` to a jump to the bounds' point (rx, ry) (in [0, 1)²), turned
//! by a multiple of π/2 picked by `rt` in [0, 1).
void jump_to(const AnnealOptions& options, double rx, double ry, double rt, Move& move) {
  const auto& b = *options.bounds;
  move.to.x = b[0] + rx * (b[2] - b[0]);
  move.to.y = b[1] + ry * (b[3] - b[1]);
  const int quarter = std::min(3, static_cast<int>(rt * 4.0));
  move.to.theta = geometry::wrap_angle(move.from.theta + quarter * (std::numbers::pi / 2));
  move.jump = true;
}

//! One proposal for `object` at iteration k. Draws in a fixed order: the
//! kind of move, then its parameters (the object was drawn before).
Move propose_move(const AnnealOptions& options, const Pose2& from, int object, int k,
                  std::mt19937_64& rng) {
  constexpr double kPi = std::numbers::pi;
  const double step = geometric(options.step_start, options.step_end, k, options.iterations);
  const double shrink = options.step_start > 0.0 ? step / options.step_start : 1.0;
  Move move;
  move.object = object;
  move.from = from;
  move.to = from;
  move.rotation = uniform01(rng) < options.rotate_probability;
  if (move.rotation) {
    const double kind = uniform01(rng);
    const double r = uniform01(rng);
    double turn;
    if (kind < options.quarter_turn_probability) {
      turn = r < 1.0 / 3.0 ? kPi / 2 : (r < 2.0 / 3.0 ? -kPi / 2 : kPi);
    } else {
      turn = (2.0 * r - 1.0) * kPi * shrink;
    }
    move.to.theta = geometry::wrap_angle(from.theta + turn);
    return move;
  }
  const double jump = uniform01(rng), rx = uniform01(rng), ry = uniform01(rng);
  if (options.bounds && jump < options.jump_probability * shrink) {
    // A jump anywhere in the bounds (a symmetric proposal): escapes places
    // that small steps cannot leave while the chain is hot.
    jump_to(options, rx, ry, uniform01(rng), move);
  } else {
    move.to.x += (2.0 * rx - 1.0) * step;
    move.to.y += (2.0 * ry - 1.0) * step;
  }
  return move;
}

//! The chain's state between iterations.
struct Chain {
  std::vector<Pose2> poses;
  double current = 0.0;
};

//! Checks, costs and decides one proposal with the uniform `u` drawn before
//! it was costed; fills the entry's validity, cost and decision.
void decide(const Move& move, double u, Chain& chain, TraceEntry& e, AnnealResult& result,
            const AnnealCallbacks& callbacks) {
  auto layout_valid = [&](const std::vector<Pose2>& p) {
    return !callbacks.layout_valid || callbacks.layout_valid(p);
  };
  chain.poses[move.object] = move.to;
  e.valid = callbacks.move_valid(chain.poses, move.object);
  if (!e.valid) {
    chain.poses[move.object] = move.from;
    e.proposed_cost = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  ++result.valid_proposals;
  const Acceptance acceptance{true, chain.current, e.temperature, u};
  const double proposed = callbacks.cost(chain.poses, move, acceptance);
  e.proposed_cost = proposed;
  e.accepted = metropolis_accept(proposed - chain.current, e.temperature, u);
  if (!e.accepted) {
    chain.poses[move.object] = move.from;
    if (callbacks.rejected) callbacks.rejected(move);
    return;
  }
  ++result.accepted;
  chain.current = proposed;
  if (chain.current < result.best_cost && layout_valid(chain.poses)) {
    result.best_cost = chain.current;
    result.best = chain.poses;
    result.best_valid = true;
    if (callbacks.new_best) callbacks.new_best();
  }
}

//! The object to move at this iteration: a movable one, or with
//! focus_probability one of the focus objects (callbacks.focus) when there
//! are any. `focused` says which.
int pick_object(const AnnealOptions& options, const AnnealCallbacks& callbacks,
                const std::vector<int>& candidates, std::mt19937_64& rng, bool& focused) {
  int object = candidates[uniform_index(rng, candidates.size())];
  focused = false;
  if (callbacks.focus) {
    const std::vector<int> focus = callbacks.focus();
    if (!focus.empty() && uniform01(rng) < options.focus_probability) {
      object = focus[uniform_index(rng, focus.size())];
      focused = true;
    }
  }
  return object;
}

//! The proposal for `object`: propose_move(), and for a focus object a jump
//! with probability 1/2 when the move is a step.
Move draw_move(const AnnealOptions& options, const Pose2& from, int object, bool focused, int k,
               std::mt19937_64& rng) {
  Move move = propose_move(options, from, object, k, rng);
  if (focused && options.bounds && !move.jump && uniform01(rng) < 0.5) {
    const double rx = uniform01(rng), ry = uniform01(rng);
    move = Move{object, from, from};
    jump_to(options, rx, ry, uniform01(rng), move);
  }
  return move;
}

//! A jump is redrawn until valid: at most `attempts` draws in all; decide()
//! checks the last draw again.
void redraw_jump(const AnnealOptions& options, const AnnealCallbacks& callbacks, int attempts,
                 Chain& chain, Move& move, std::mt19937_64& rng) {
  for (int a = 1; move.jump && a < attempts; ++a) {
    chain.poses[move.object] = move.to;
    const bool ok = callbacks.move_valid(chain.poses, move.object);
    chain.poses[move.object] = move.from;
    if (ok) return;
    const double rx = uniform01(rng), ry = uniform01(rng);
    jump_to(options, rx, ry, uniform01(rng), move);
  }
}

//! A preference move of `object` (callbacks.preferred), redrawn until valid;
//! nullopt when no draw was valid.
std::optional<Move> preference_move(const AnnealOptions& options, const AnnealCallbacks& callbacks,
                                    Chain& chain, int object, std::mt19937_64& rng) {
  const Pose2 from = chain.poses[object];
  for (int a = 0; a < options.preference_attempts; ++a) {
    const std::optional<Pose2> to = callbacks.preferred(chain.poses, object, rng);
    if (!to) return std::nullopt;
    chain.poses[object] = *to;
    const bool ok = callbacks.move_valid(chain.poses, object);
    chain.poses[object] = from;
    if (!ok) continue;
    Move move{object, from, *to};
    move.rotation = to->x == from.x && to->y == from.y;
    move.preference = true;
    return move;
  }
  return std::nullopt;
}

//! The initial layout's cost, and the best so far when it is valid.
Chain start_chain(std::vector<Pose2> poses, const AnnealCallbacks& callbacks,
                  AnnealResult& result) {
  Chain chain{std::move(poses), 0.0};
  chain.current = callbacks.cost(chain.poses, Move{}, Acceptance{});
  result.initial_cost = chain.current;
  result.best = chain.poses;
  result.best_cost = std::numeric_limits<double>::infinity();
  if (!callbacks.layout_valid || callbacks.layout_valid(chain.poses)) {
    result.best_cost = chain.current;
    result.best_valid = true;
    if (callbacks.new_best) callbacks.new_best();
  }
  return chain;
}

}  // namespace

AnnealResult anneal(std::vector<Pose2> poses, const std::vector<bool>& movable,
                    const AnnealOptions& options, const AnnealCallbacks& callbacks,
                    std::mt19937_64& rng, const std::atomic<bool>* stop) {
  assert(callbacks.move_valid && callbacks.cost);
  assert(movable.size() == poses.size());
  std::vector<int> candidates;
  for (std::size_t i = 0; i < movable.size(); ++i)
    if (movable[i]) candidates.push_back(static_cast<int>(i));

  AnnealResult result;
  Chain chain = start_chain(std::move(poses), callbacks, result);
  for (int k = 0; k < options.iterations && !candidates.empty(); ++k) {
    if (stop && stop->load()) {
      result.stopped = true;
      break;
    }
    TraceEntry e;
    e.iteration = k;
    e.temperature = temperature_at(options, k);
    // Draws in a fixed order: object, move, the Metropolis uniform (before
    // the proposal is costed), then any redraws of an invalid jump.
    // With callbacks.preferred one more draw decides a preference move first.
    bool focused = false;
    const int object = pick_object(options, callbacks, candidates, rng, focused);
    std::optional<Move> preferred;
    if (callbacks.preferred && uniform01(rng) < options.preference_probability)
      preferred = preference_move(options, callbacks, chain, object, rng);
    Move move = preferred ? *preferred : draw_move(options, chain.poses[object], object, focused, k, rng);
    const double u = uniform01(rng);
    redraw_jump(options, callbacks, focused ? options.focus_jump_attempts : options.jump_attempts,
                chain, move, rng);
    e.object = object;
    e.rotation = move.rotation;
    e.jump = move.jump;
    e.preference = move.preference;
    decide(move, u, chain, e, result, callbacks);
    e.current_cost = chain.current;
    e.best_cost = result.best_cost;
    ++result.proposals;
    result.trace.push_back(e);
    if (callbacks.progress) callbacks.progress(e);
  }
  result.final_poses = chain.poses;
  result.final_cost = chain.current;
  return result;
}

}  // namespace hrs::optimize
