// SPDX-License-Identifier: GPL-3.0-or-later
// The final polish of a design; see polish.h.

#include "optimize/polish.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "geometry/polygon_ops.h"
#include "optimize/arrange.h"
#include "optimize/preferences.h"
#include "optimize/rearrange.h"
#include "optimize/squaring.h"

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

//! The objects at the other end of `id`'s grossly missed angle preferences.
std::vector<std::string> gross_others(const PreferenceReport& r, const std::string& id) {
  std::vector<std::string> out;
  for (const PreferenceCheck& c : r.checks) {
    if (!c.angular() || c.residual <= kGrossAngle || c.other.empty()) continue;
    if (c.object == id) out.push_back(c.other);
    if (c.other == id) out.push_back(c.object);
  }
  return out;
}

//! Whether an angle preference of object `id` is grossly missed.
bool grossly_off(const PreferenceReport& r, const std::string& id) {
  return std::any_of(r.checks.begin(), r.checks.end(), [&](const PreferenceCheck& c) {
    return c.angular() && c.residual > kGrossAngle && (c.object == id || c.other == id);
  });
}

//! How many of the best places along the walls are planned per object.
constexpr std::size_t kSlideTries = 3;

//! How many of the best exchanges of places are planned per object.
constexpr std::size_t kSwapTries = 2;

//! Held places looked at per object whose heading is grossly off, and how
//! many of the best evictions of their holders are planned.
constexpr int kEvictPlaces = 16;
constexpr std::size_t kEvictTries = 4;

//! Places along the walls tried per wall object of a group turn, and how
//! many of a turn's best placements are planned.
constexpr int kPlaces = 6;
constexpr std::size_t kTurnTries = 2;

//! Rounds of the shorter-tour rearrangement: each kept layout starts one
//! more (each with its own allowance).
constexpr int kShorterRounds = 2;

//! A group member that no longer fits once turned is shifted by up to this
//! much (metres), in rings this far apart.
constexpr double kNudge = 0.3;
constexpr double kNudgeStep = 0.1;

}  // namespace

PolishResult polish(const geometry::Scene& scene, const CostModel& model,
                    const std::vector<bool>& movable, std::vector<geometry::Pose2>& poses,
                    CostTerms& terms, const PolishHooks& hooks, int max_tries,
                    const std::atomic<bool>* stop) {
  PolishResult out;
  PreferenceReport report = check_preferences(scene, model, poses);
  // The kept layout's tour corridor (optimize/arrange.h), rebuilt on a keep.
  std::optional<TourCorridor> corridor;
  if (hooks.tours) corridor.emplace(scene.wheelchair, hooks.tours());
  // Object `object`'s footprint at `to`.
  const auto footprint_at = [&](int object, const geometry::Pose2& to) {
    geometry::Object o = scene.objects[static_cast<std::size_t>(object)];
    o.pose = to;
    return geometry::world_footprint(o);
  };
  const auto clear = [&](int object, const geometry::Pose2& to) {
    return !corridor || corridor->clear(footprint_at(object, to));
  };
  // Keeps the placed and planned layout `q` (terms `t`, preference report
  // `met`).
  const auto keep_planned = [&](std::vector<geometry::Pose2> q, const CostTerms& t,
                                PreferenceReport& met) {
    poses = std::move(q);
    terms = t;
    report = std::move(met);
    hooks.kept();
    if (corridor) corridor.emplace(scene.wheelchair, hooks.tours());
  };
  // Places `moves`, plans, and keeps them when every tour found before is
  // still found, and with `no_costlier` the total cost is not higher (with
  // `lower` too: lower) (`met` is the preference report of the moved
  // layout); else puts the objects back.
  auto try_moves = [&](const std::vector<std::pair<int, geometry::Pose2>>& moves,
                       PreferenceReport& met, bool no_costlier = false, bool lower = false) {
    std::vector<geometry::Pose2> q = poses;
    for (const auto& [k, pose] : moves) {
      q[static_cast<std::size_t>(k)] = pose;
      hooks.place(k, pose);
    }
    const CostTerms t = hooks.plan(q);
    if (t.tours_found >= terms.tours_found &&
        (!no_costlier || (lower ? t.total() < terms.total() : t.total() <= terms.total()))) {
      keep_planned(std::move(q), t, met);
      return true;
    }
    for (auto it = moves.rbegin(); it != moves.rend(); ++it)
      hooks.place(it->first, poses[static_cast<std::size_t>(it->first)]);
    return false;
  };
  // A wall object of `move` (applied to `q`) whose pose there is invalid
  // (its spot is taken, or it overhangs the wall's end) slides along the
  // walls that give it the same heading, nearest first, to the first valid
  // place; `move` and `q` follow it.
  const auto settle = [&](std::vector<geometry::Pose2>& q, GroupMove& move) {
    for (auto& [k, pose] : move) {
      const geometry::Object& o = scene.objects[static_cast<std::size_t>(k)];
      if (!o.wall || !o.wall->distance || hooks.valid(q, k)) continue;
      for (const geometry::Pose2& at : wall_slides(scene, model, q, k, kWallSlideStep)) {
        if (std::abs(geometry::wrap_angle(at.theta - pose.theta)) > 1e-9) continue;
        q[static_cast<std::size_t>(k)] = at;
        if (hooks.valid(q, k)) {
          pose = at;
          break;
        }
        q[static_cast<std::size_t>(k)] = pose;
      }
    }
  };
  // Object `k`, invalid at `pose` in `q`, shifted by up to kNudge metres
  // (rings of kNudgeStep, eight directions each, the heading kept) to the
  // first valid place; `q` and `pose` follow it. False when none is valid.
  const auto nudge = [&](std::vector<geometry::Pose2>& q, int k, geometry::Pose2& pose) {
    for (double r = kNudgeStep; r <= kNudge + 1e-9; r += kNudgeStep)
      for (int d = 0; d < 8; ++d) {
        const double a = d * std::numbers::pi / 4;
        const geometry::Pose2 at{pose.x + r * std::cos(a), pose.y + r * std::sin(a), pose.theta};
        q[static_cast<std::size_t>(k)] = at;
        if (hooks.valid(q, k)) {
          pose = at;
          return true;
        }
      }
    q[static_cast<std::size_t>(k)] = pose;
    return false;
  };
  // Valid placements of a group turn `move` (from `poses`): the move
  // settled (settle()), then, for each wall object of the move in turn, the
  // move with that object at each valid place along the walls that give it
  // the same heading (nearest first, at most kPlaces), the others settled:
  // the nearest place can cost a tour that another keeps. A member that
  // turns in place and no longer fits is nudged (nudge()). Each placement
  // differs from the others; all are valid.
  const auto placements = [&](const std::vector<geometry::Pose2>& from, const GroupMove& move) {
    std::vector<GroupMove> out_moves;
    const auto add = [&](GroupMove m) {
      std::vector<geometry::Pose2> q = from;
      for (const auto& [k, pose] : m) q[static_cast<std::size_t>(k)] = pose;
      settle(q, m);
      for (auto& [k, pose] : m)
        if (!hooks.valid(q, k) && !nudge(q, k, pose)) return;
      if (std::find(out_moves.begin(), out_moves.end(), m) == out_moves.end())
        out_moves.push_back(std::move(m));
    };
    add(move);
    for (std::size_t w = 0; w < move.size(); ++w) {
      const int k = move[w].first;
      const geometry::Object& o = scene.objects[static_cast<std::size_t>(k)];
      if (!o.wall || !o.wall->distance) continue;
      std::vector<geometry::Pose2> q = from;
      for (const auto& [j, pose] : move) q[static_cast<std::size_t>(j)] = pose;
      int places = 0;
      for (const geometry::Pose2& at : wall_slides(scene, model, q, k, kWallSlideStep)) {
        if (places >= kPlaces) break;
        if (std::abs(geometry::wrap_angle(at.theta - move[w].second.theta)) > 1e-9) continue;
        q[static_cast<std::size_t>(k)] = at;
        if (!hooks.valid(q, k)) continue;
        ++places;
        GroupMove m = move;
        m[w].second = at;
        add(std::move(m));
      }
    }
    return out_moves;
  };
  // The valid candidates that score higher (wall slides, exchanges of
  // places): those clear of the tours' corridor first (they seldom cost a
  // tour), then the highest score, then the order found (the nearest
  // slide, the lower partner index). The best `tries` are planned in turn
  // until one is kept (try_moves); true when one was. With `no_costlier`
  // a candidate is kept only at no higher total cost, unless it mends a
  // gross angle miss: a wrong heading is seen at a glance, a longer tour
  // is not.
  struct Candidate {
    bool clear;
    PreferenceReport report;
    GroupMove move;
    //! Chair footprints of the kept tours its moved objects come near
    //! (TourCorridor::blocked; set by try_best, when it ranks by it, for
    //! candidates not clear).
    std::size_t blocked = 0;
  };
  // Plannings with an allowance of their own: the rearrangement's, and the
  // second round of a gross miss's eviction (evict()).
  int own_tries = 0;
  // With `by_blocked`, candidates of equal score are taken by how few of
  // the kept tours' chair footprints they come near (TourCorridor::blocked)
  // rather than in the order found.
  // With `own`, the plannings are counted in `own_tries`, beyond
  // `max_tries`. `planned` is how many the last call planned.
  std::size_t planned = 0;
  const auto try_best = [&](std::vector<Candidate>& candidates, std::size_t tries,
                            bool no_costlier, bool by_blocked = false, bool own = false) {
    for (Candidate& c : candidates) {
      c.blocked = 0;
      if (!by_blocked || c.clear || !corridor) continue;
      for (const auto& [k, pose] : c.move) c.blocked += corridor->blocked(footprint_at(k, pose));
    }
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const Candidate& a, const Candidate& b) {
                       if (a.clear != b.clear) return a.clear;
                       const int sa = polish_score(a.report), sb = polish_score(b.report);
                       if (sa != sb) return sa > sb;
                       return a.blocked < b.blocked;
                     });
    planned = 0;
    for (std::size_t k = 0; k < candidates.size() && k < tries; ++k) {
      if ((!own && out.tried - own_tries >= max_tries) || (stop && stop->load())) break;
      ++out.tried, ++planned;
      if (own) ++own_tries;
      const bool capped = no_costlier && gross_misses(candidates[k].report) >= gross_misses(report);
      if (try_moves(candidates[k].move, candidates[k].report, capped)) return true;
    }
    return false;
  };
  // Frees a place that would mend object i's preferences (an eviction).
  // The places: its preferred poses, then its places along the walls,
  // nearest first, the object alone or with a partner (below). A free one
  // is a candidate as it is (the slides planned only the three
  // best-scoring); one held by one or two movable objects (at most
  // kEvictPlaces such) is a candidate with the holders moved away: to their
  // own wall places or preferred poses, or to the place the object leaves
  // (a second holder to the first of those that fits). A move of three
  // that no exchange makes. For an object whose heading is grossly off
  // (> 20°), a candidate mends a gross miss at a score no lower (a
  // preference of a holder may be traded for the heading, as the score
  // counts a gross miss twice), and is kept at any cost; for any other (the
  // last pass, below), it raises the score and adds no gross miss, and is
  // kept only at no higher total cost, as an exchange. The best four are
  // planned, and the first kept ends it.
  const auto evict = [&](std::size_t i) {
    const int object = static_cast<int>(i);
    const std::string& id = scene.objects[i].id;
    const bool gross = grossly_off(report, id);
    const auto mends = [&](const PreferenceReport& next) {
      return gross ? gross_misses(next) < gross_misses(report)
                   : polish_score(next) > polish_score(report) &&
                         gross_misses(next) <= gross_misses(report);
    };
    const auto accept = [&](const PreferenceReport& next) {
      return mends(next) && polish_score(next) >= polish_score(report);
    };
    std::vector<Candidate> evictions;
    int places = 0;
    std::vector<geometry::Pose2> targets = preferred_poses(scene, model, poses, object);
    for (const geometry::Pose2& at : wall_slides(scene, model, poses, object, kWallSlideStep))
      targets.push_back(at);
    // A free object's places around its partners (a lamp whose front has
    // no room where it stands goes round the bed to where it has).
    if (gross)
      for (const geometry::Pose2& at : relation_slides(scene, poses, object, kWallSlideStep))
        targets.push_back(at);
    for (const geometry::Pose2& to : targets) {
      if (places >= kEvictPlaces || (stop && stop->load())) break;
      std::vector<geometry::Pose2> p = poses;
      p[i] = to;
      // The object alone, or with the first relation partner (ascending)
      // at the first of its preferred poses that mends the miss with it
      // (a desk moved to another wall with the chair that faces it).
      GroupMove base{{object, to}};
      if (!mends(check_preferences(scene, model, p))) {
        for (const int f : partners(scene, object)) {
          if (!movable[static_cast<std::size_t>(f)] || base.size() > 1) continue;
          for (const geometry::Pose2& at : preferred_poses(scene, model, p, f)) {
            std::vector<geometry::Pose2> pf = p;
            pf[static_cast<std::size_t>(f)] = at;
            if (mends(check_preferences(scene, model, pf))) {
              base.push_back({f, at});
              break;
            }
          }
        }
        if (base.size() == 1) {
          // Or with its side of the relations: the movable partners other
          // than those its gross misses are with, moved rigidly with it
          // (a desk taken to the wardrobe's wall with the chair before
          // it), so the relations between them still hold.
          const std::vector<std::string> across = gross_others(report, id);
          const double turn = geometry::wrap_angle(to.theta - poses[i].theta);
          const double c = std::cos(turn), s = std::sin(turn);
          std::vector<geometry::Pose2> ps = p;
          GroupMove side{{object, to}};
          for (const int f : partners(scene, object)) {
            const geometry::Object& of = scene.objects[static_cast<std::size_t>(f)];
            if (!movable[static_cast<std::size_t>(f)] ||
                std::find(across.begin(), across.end(), of.id) != across.end())
              continue;
            const geometry::Pose2& was = poses[static_cast<std::size_t>(f)];
            const double dx = was.x - poses[i].x, dy = was.y - poses[i].y;
            const geometry::Pose2 at{to.x + c * dx - s * dy, to.y + s * dx + c * dy,
                                     geometry::wrap_angle(was.theta + turn)};
            ps[static_cast<std::size_t>(f)] = at;
            side.push_back({f, at});
          }
          if (side.size() == 1 || !mends(check_preferences(scene, model, ps))) continue;
          base = std::move(side);
          p = std::move(ps);
        } else {
          p[static_cast<std::size_t>(base[1].first)] = base[1].second;
        }
      }
      const auto fits = [&](const std::vector<geometry::Pose2>& q) {
        return std::all_of(base.begin(), base.end(),
                           [&](const auto& m) { return hooks.valid(q, m.first); });
      };
      const auto clear_all = [&](const GroupMove& m) {
        return std::all_of(m.begin(), m.end(),
                           [&](const auto& e) { return clear(e.first, e.second); });
      };
      if (hooks.valid(p, object)) {
        if (!fits(p)) continue;
        PreferenceReport next = check_preferences(scene, model, p);
        if (accept(next)) evictions.push_back({clear_all(base), std::move(next), base});
        continue;
      }
      const std::vector<int> held = holders(scene, p, object);
      if (held.empty() || held.size() > 2 || std::any_of(held.begin(), held.end(), [&](int j) {
            return !movable[static_cast<std::size_t>(j)] ||
                   std::any_of(base.begin(), base.end(),
                               [&](const auto& m) { return m.first == j; });
          }))
        continue;
      ++places;
      // Where holder j may go in layout q: its wall places, its preferred
      // poses, and the object's old place (its own heading, or the
      // object's).
      const auto away = [&](const std::vector<geometry::Pose2>& q, int j) {
        std::vector<geometry::Pose2> out_places = wall_slides(scene, model, q, j, kWallSlideStep);
        for (const geometry::Pose2& at : preferred_poses(scene, model, q, j))
          out_places.push_back(at);
        const geometry::Pose2& was = poses[i];
        out_places.push_back({was.x, was.y, q[static_cast<std::size_t>(j)].theta});
        out_places.push_back(was);
        return out_places;
      };
      const int j = held[0];
      for (const geometry::Pose2& at : away(p, j)) {
        std::vector<geometry::Pose2> q = p;
        q[static_cast<std::size_t>(j)] = at;
        if (!hooks.valid(q, j)) continue;
        GroupMove move = base;
        move.push_back({j, at});
        if (held.size() == 2) {
          // The second holder at its first place that fits.
          const int k = held[1];
          bool placed = false;
          for (const geometry::Pose2& at_k : away(q, k)) {
            q[static_cast<std::size_t>(k)] = at_k;
            if (hooks.valid(q, k) && hooks.valid(q, j)) {
              move.push_back({k, at_k});
              placed = true;
              break;
            }
          }
          if (!placed) continue;
        }
        if (!fits(q)) continue;
        PreferenceReport next = check_preferences(scene, model, q);
        if (!accept(next)) continue;
        evictions.push_back({clear_all(move), std::move(next), std::move(move)});
      }
    }
    if (!try_best(evictions, kEvictTries, true)) {
      // For a gross miss, four of those not yet planned, among equal scores
      // fewest blocked footprints first: the places found first (preferred
      // poses, the nearest slides) can all stand in the tours' way, where a
      // place farther round (a lamp at the bed's far corner) leaves them
      // be. An allowance of its own: the moves before may have spent the
      // budget.
      if (!gross || evictions.size() <= planned) return false;
      evictions.erase(evictions.begin(), evictions.begin() + static_cast<std::ptrdiff_t>(planned));
      if (!try_best(evictions, kEvictTries, true, true, true)) return false;
    }
    ++out.kept, ++out.evicted;
    return true;
  };
  // Two passes: a pose kept in the first can make a partner's pose meet its
  // relation in the second.
  for (int pass = 0; pass < 2 && report.met < report.total; ++pass) {
    for (std::size_t i = 0; i < poses.size(); ++i) {
      if (!movable[i] || out.tried - own_tries >= max_tries || (stop && stop->load())) continue;
      const std::string& id = scene.objects[i].id;
      const bool unmet = std::any_of(
          report.checks.begin(), report.checks.end(),
          [&](const PreferenceCheck& c) { return !c.met && (c.object == id || c.other == id); });
      if (!unmet) continue;
      const int object = static_cast<int>(i);
      bool kept = false;
      // Its preferred poses, then turned in place to the heading its
      // nearest wall asks for: that meets the angle where no spot at the
      // wanted distance is free (a bed left in the room's middle, side on
      // to its wall). A pose that does not fit is nudged (nudge()).
      std::vector<geometry::Pose2> wanted = preferred_poses(scene, model, poses, object);
      const geometry::Object& o = scene.objects[i];
      if (o.wall && o.wall->distance && o.wall->angle) {
        const double normal = model.wall_normal_angle(model.nearest_wall(object, poses[i]));
        wanted.push_back({poses[i].x, poses[i].y, geometry::wrap_angle(normal + *o.wall->angle)});
      }
      for (geometry::Pose2 to : wanted) {
        if (out.tried - own_tries >= max_tries || (stop && stop->load())) break;
        std::vector<geometry::Pose2> p = poses;
        p[i] = to;
        if (!hooks.valid(p, object) && !nudge(p, object, to)) continue;
        const PreferenceReport next = check_preferences(scene, model, p);
        // Alone, or with one relation partner moved to one of its own
        // preferred poses (a bed turned round with the TV that faces it).
        std::vector<std::pair<int, geometry::Pose2>> moves{{object, to}};
        PreferenceReport best = next;
        if (polish_score(next) <= polish_score(report)) {
          for (const int j : partners(scene, object)) {
            if (!movable[static_cast<std::size_t>(j)]) continue;
            for (const geometry::Pose2& to_j : preferred_poses(scene, model, p, j)) {
              std::vector<geometry::Pose2> q = p;
              q[static_cast<std::size_t>(j)] = to_j;
              if (!hooks.valid(q, j)) continue;
              PreferenceReport both = check_preferences(scene, model, q);
              if (polish_score(both) > polish_score(best)) {
                best = std::move(both);
                moves = {{object, to}, {j, to_j}};
              }
            }
          }
        }
        if (polish_score(best) <= polish_score(report)) continue;
        ++out.tried;
        if (try_moves(moves, best)) {
          ++out.kept;
          kept = true;
          break;
        }
      }
      if (kept || out.tried - own_tries >= max_tries || (stop && stop->load())) continue;
      // The spots straight across are taken: slide along the walls.
      std::vector<Candidate> slides;
      for (const geometry::Pose2& to : wall_slides(scene, model, poses, object, kWallSlideStep)) {
        std::vector<geometry::Pose2> p = poses;
        p[i] = to;
        if (!hooks.valid(p, object)) continue;
        PreferenceReport next = check_preferences(scene, model, p);
        if (polish_score(next) > polish_score(report))
          slides.push_back({clear(object, to), std::move(next), {{object, to}}});
      }
      if (try_best(slides, kSlideTries, false)) {
        ++out.kept, ++out.slid;
        continue;
      }
      if (out.tried - own_tries >= max_tries || (stop && stop->load())) continue;
      // Every place it could take is held: exchange places with another
      // movable object (swaps()). Kept only when the total cost is not
      // higher, or when it mends a gross angle miss: two objects moved at
      // once can lengthen every tour through them. A later pass can then
      // bring a partner near.
      std::vector<Candidate> exchanges;
      for (std::size_t j = 0; j < poses.size() && !(stop && stop->load()); ++j) {
        if (j == i || !movable[j]) continue;
        for (GroupMove& move : swaps(scene, poses, object, static_cast<int>(j))) {
          std::vector<geometry::Pose2> q = poses;
          for (const auto& [k, pose] : move) q[static_cast<std::size_t>(k)] = pose;
          settle(q, move);
          if (!hooks.valid(q, object) || !hooks.valid(q, static_cast<int>(j))) continue;
          PreferenceReport next = check_preferences(scene, model, q);
          if (polish_score(next) <= polish_score(report)) continue;
          const bool c = clear(object, move[0].second) && clear(move[1].first, move[1].second);
          exchanges.push_back({c, std::move(next), std::move(move)});
        }
      }
      if (try_best(exchanges, kSwapTries, true)) {
        ++out.kept, ++out.swapped;
        continue;
      }
      // A heading still grossly off (> 20°): free a place that mends it.
      if (out.tried - own_tries >= max_tries || (stop && stop->load()) || !grossly_off(report, id)) continue;
      evict(i);
    }
  }
  // Groups linked by relation angles turn as one body (a bed, the TV that
  // faces it and the chair beside it): one object at a time cannot meet a
  // relation without breaking another of the group, nor a member's wall
  // angle without breaking the relations it keeps (a TV askew to its wall
  // with the table and the plant turned to it).
  for (const std::vector<int>& group : heading_groups(scene)) {
    const auto unmet = [&] {
      return std::any_of(report.checks.begin(), report.checks.end(), [&](const PreferenceCheck& c) {
        if (c.met || (c.kind != "relation_angle" && c.kind != "wall_angle")) return false;
        const int a = scene.find_object(c.object);
        return std::find(group.begin(), group.end(), a) != group.end();
      });
    };
    for (GroupMove move : group_turns(scene, model, poses, movable, group)) {
      if (!unmet() || out.tried - own_tries >= max_tries || (stop && stop->load())) break;
      std::vector<Candidate> turns;
      for (GroupMove& placed : placements(poses, move)) {
        std::vector<geometry::Pose2> q = poses;
        for (const auto& [k, pose] : placed) q[static_cast<std::size_t>(k)] = pose;
        PreferenceReport next = check_preferences(scene, model, q);
        if (polish_score(next) <= polish_score(report)) continue;
        const bool c = std::all_of(placed.begin(), placed.end(),
                                   [&](const auto& m) { return clear(m.first, m.second); });
        turns.push_back({c, std::move(next), std::move(placed)});
      }
      if (try_best(turns, kTurnTries, false)) ++out.turned;
    }
  }
  // Angles still grossly off after the local moves above: whole
  // rearrangements, found by a search over the preferences alone (no
  // planning), then planned. A bed that holds the only wall a desk can
  // share with its wardrobe moves to another wall, and the dresser that
  // stands by the bed follows it: moves that raise the score only together.
  // Each chain (a fixed seed per chain, so one output whatever the thread
  // count) is a Metropolis walk over valid layouts; a step takes one object
  // with an unmet preference (or, one step in four, any movable object) to
  // one of its preferred poses or wall places, moving the one or two
  // movable objects that hold the place to places of their own. Its energy
  // is the score's negative, once more per gross miss, plus what the moved
  // objects travel and how many stand in the kept tours' corridor: the
  // tours are likelier kept near the layout that found them. Each chain's
  // best layout with fewer gross misses and a score no lower is planned,
  // best first, and kept at any cost when every tour is still found.
  RearrangeHooks rh;
  rh.fits = hooks.fits ? hooks.fits : hooks.valid;
  rh.valid = hooks.valid;
  rh.clear = clear;
  rh.seed = hooks.seed;
  rh.tour_proxy = hooks.tour_proxy;
  // The chains' layouts for `goal`, planned best first with an allowance of
  // their own (one per chain), beyond `max_tries`: the moves before them
  // may have spent theirs. The first kept (at no higher total cost with
  // `no_costlier`, unless it has fewer gross misses) ends it.
  const auto rearrange = [&](RearrangeGoal goal, bool no_costlier) {
    const bool shorter = goal == RearrangeGoal::kShorterTours;
    for (Rearrangement& f : rearrangements(scene, model, movable, poses, report, rh, stop, goal)) {
      if (stop && stop->load()) break;
      ++out.tried, ++own_tries;
      // One that also mends a gross miss is kept at any cost, as the
      // fewer gross misses' are; a shorter-tour layout only at a lower cost.
      if (try_moves(f.move, f.report,
                    shorter || (no_costlier && gross_misses(f.report) >= gross_misses(report)),
                    shorter)) {
        ++out.kept;
        ++(shorter ? out.shortened : out.rearranged);
        break;
      }
    }
  };
  if (gross_misses(report) > 0 && !(stop && stop->load()))
    rearrange(RearrangeGoal::kFewerGross, false);
  // Then the misses that need more objects moved than an eviction moves (a
  // sofa wanted by a TV whose wall a bed and a cabinet hold): the chains
  // again, for a higher score, each layout kept only when every tour is
  // still found at no higher total cost, or at any cost when it also has
  // fewer gross misses: the rule of the exchanges.
  if (report.met < report.total && !(stop && stop->load()))
    rearrange(RearrangeGoal::kHigherScore, true);
  // Square to the room: an object whose heading no preference fixes is
  // turned parallel or perpendicular to its nearest wall (a lamp at 10°
  // looks wrong to a designer), when the layout stays valid, no preference
  // is lost and the tours found stay found, whatever the cost
  // (docs/BENCHMARKS.md, 2026-11-29: kept only at no higher cost, it left a
  // side table at 7° in a shipped living room). Each heading is tried
  // turned in place, then, where that is not valid or loses a preference
  // (turned about its centre, the object's reach towards the wall changes:
  // a lamp 5 cm from its wall, as wanted, ends 11 cm from it), slid along the
  // wall's normal to keep the object's gap to the wall. The square headings
  // are planned nearest first, and the first that costs no more is kept;
  // when each costs more, the cheapest is (a quarter or half turn moves the
  // object's front, where the wheelchair stops: in the shipped bedroom the
  // three cost 17.5 to 18.8 against 14.9 tilted, and three squarings to
  // the nearest heading took zoo room 202's design from 8.0 to 31.4;
  // docs/BENCHMARKS.md, 2026-11-30).
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const int object = static_cast<int>(i);
    if (!movable[i] || heading_fixed(scene, object) || out.tried - own_tries >= max_tries ||
        (stop && stop->load()))
      continue;
    // Whether `n` more plannings fit in the budget.
    const auto budget_left = [&](int n = 1) {
      return out.tried - own_tries + n <= max_tries && !(stop && stop->load());
    };
    if (!budget_left(2)) continue;
    // The square headings, each turned in place or slid to keep its gap to
    // the wall, valid and losing no preference (optimize/squaring.h).
    std::vector<SquarePlace> squares = square_places(scene, model, poses, object, report, hooks.valid);
    // The square headings, nearest first, each planned while two plannings
    // are left (one to evaluate, one to keep): the first whose tours are all
    // found at no higher total cost is kept as planned. When every one costs
    // more, the cheapest whose tours are all found is planned again and kept
    // (a lamp's quarter turn moves its front, where the wheelchair stops: the
    // nearest heading can cost several times the others); when that second
    // plan loses a tour, the next cheapest is tried.
    std::vector<std::pair<double, SquarePlace>> found;
    bool kept = false;
    for (std::size_t k = 0; k < squares.size() && budget_left(2); ++k) {
      SquarePlace& c = squares[k];
      ++out.tried;
      std::vector<geometry::Pose2> q = poses;
      q[i] = c.pose;
      hooks.place(object, c.pose);
      const CostTerms t = hooks.plan(q);
      if (t.tours_found >= terms.tours_found && t.total() <= terms.total()) {
        keep_planned(std::move(q), t, c.report);
        kept = true;
        ++out.squared;
        break;
      }
      hooks.place(object, poses[i]);
      if (t.tours_found >= terms.tours_found) found.emplace_back(t.total(), std::move(c));
    }
    if (kept) continue;
    // Cheapest first; equal costs keep the order planned.
    std::stable_sort(found.begin(), found.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    for (auto& [cost, c] : found) {
      if (!budget_left()) break;
      ++out.tried;
      if (try_moves({{object, c.pose}}, c.report)) {
        ++out.squared;
        break;
      }
    }
  }
  // Last, with the plannings left: each object with a preference still
  // unmet and no angle grossly off has a place that would meet more freed
  // (evict(): a sofa moved to the wall where it stands at its distance from
  // the TV, the cabinet that holds that wall moved to the place the sofa
  // leaves), kept when every tour is still found at no higher total cost.
  // It runs after every other step, so that those find the layout and the
  // budget they had without it.
  for (std::size_t i = 0; i < poses.size(); ++i) {
    if (!movable[i] || out.tried - own_tries >= max_tries || (stop && stop->load())) continue;
    const std::string& id = scene.objects[i].id;
    const bool unmet = std::any_of(report.checks.begin(), report.checks.end(), [&](const PreferenceCheck& c) {
      return !c.met && (c.object == id || c.other == id);
    });
    if (unmet && !grossly_off(report, id)) evict(i);
  }
  // Last of all, shorter tours at a score no lower: chains that keep the
  // score and lower the tour proxy (optimize/tour_proxy.h), each
  // best layout planned (an allowance of its own, one per chain), the first
  // at a lower total cost kept. Run last, it leaves every stage before it
  // as it was.
  // Only when every tour is found: an unfound tour's penalty outweighs
  // what shorter tours save, and its stops are not where the proxy drives.
  // A kept layout starts another round, up to kShorterRounds.
  for (int round = 0; round < kShorterRounds && rh.tour_proxy &&
                      terms.tours_found == terms.tours_total && !(stop && stop->load());
       ++round) {
    const int before = out.shortened;
    rearrange(RearrangeGoal::kShorterTours, true);
    if (out.shortened == before) break;
  }
  return out;
}

}  // namespace hrs::optimize
