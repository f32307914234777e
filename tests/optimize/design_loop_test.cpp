// SPDX-License-Identifier: GPL-3.0-or-later
// The design loop's additions beyond the paper (optimize/design.h,
// docs/optimize.md), each against the run without it:
// - early rejection (DesignOptions::early_reject) makes the same accept
//   decisions, the same final layout and cost; a proposal rejected early is
//   never accepted, its bound is below the full cost, and the result's
//   counter equals the rejected-early steps of the trace;
// - refusing impossible legs (refuse_impossible) leaves the baseline's
//   designs and tours unchanged (it only skips RRTs that would fail);
// - the proposed planner with early rejection gives the same design with
//   one and two threads;
// - escape: scenes/l_studio.json, whose door pocket is sealed (0/10 tours),
//   is opened up by a 700-iteration baseline design, and a stop whose
//   every goal pose is covered (the narrow passage's bookshelf behind the
//   bed) is moved out, and no object that can be approached loses its
//   last free goal pose; a crowded generated room whose door boxes the
//   car's first turn in (every tour fails leaving the door while the free
//   grid joins everything) is opened by focusing on the door's neighbours;
//   generated rooms whose walled stops lie more than 2 m from every object
//   bordering the door's region are opened by focusing on the nearest;
// - the clearance weight: a large weight on the path clearance term widens
//   the tours' corridors (printed for docs/optimize.md);
// - the rescue: with an RRT cut to 3 iterations (it finds only legs whose
//   direct RS curve is free), the same design with `rescue` finds exactly
//   the tours the rescue reports more, loses none, and stays valid.

#include "optimize/design.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "geometry/cspace.h"
#include "geometry/scene.h"
#include "planning/goals.h"
#include "rs/reeds_shepp.h"

namespace hrs::optimize {
namespace {

using geometry::Scene;

Scene shipped(const std::string& file) {
  return geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/scenes/" + file);
}

//! Baseline design options with `seed`, `iterations` and two threads.
DesignOptions options(std::uint64_t seed, int iterations) {
  DesignOptions o;
  o.planner = hrs::optimize::PlannerConfig::from_preset("baseline");
  o.seed = seed;
  o.iterations = iterations;
  o.threads = 2;
  return o;
}

//! The final layout poses, costs and tours of two designs are the same;
//! with `trace`, also every iteration's validity and decision.
void expect_same_design(const DesignResult& a, const DesignResult& b, const std::string& what,
                        bool trace = true) {
  ASSERT_EQ(a.layout.objects.size(), b.layout.objects.size()) << what;
  for (std::size_t i = 0; i < a.layout.objects.size(); ++i)
    EXPECT_EQ(a.layout.objects[i].pose, b.layout.objects[i].pose)
        << what << ": " << a.layout.objects[i].id;
  EXPECT_EQ(a.valid, b.valid) << what;
  EXPECT_EQ(a.initial.total(), b.initial.total()) << what;
  EXPECT_EQ(a.final.total(), b.final.total()) << what;
  EXPECT_EQ(a.final.tours_found, b.final.tours_found) << what;
  EXPECT_EQ(a.accepted, b.accepted) << what;
  EXPECT_EQ(a.valid_proposals, b.valid_proposals) << what;
  ASSERT_EQ(a.tours.size(), b.tours.size()) << what;
  for (std::size_t k = 0; k < a.tours.size(); ++k) {
    EXPECT_EQ(a.tours[k].found, b.tours[k].found) << what << ": tour " << k;
    EXPECT_EQ(a.tours[k].metrics.length, b.tours[k].metrics.length) << what << ": tour " << k;
  }
  if (!trace) return;
  ASSERT_EQ(a.trace.size(), b.trace.size()) << what;
  for (std::size_t i = 0; i < a.trace.size(); ++i) {
    ASSERT_EQ(a.trace[i].anneal.valid, b.trace[i].anneal.valid) << what << ": step " << i;
    ASSERT_EQ(a.trace[i].anneal.accepted, b.trace[i].anneal.accepted) << what << ": step " << i;
  }
}

//! The counters of early rejection agree with the trace.
int expect_early_counters(const DesignResult& r, const std::string& what) {
  int early = 0;
  for (std::size_t i = 0; i < r.trace.size(); ++i) {
    const DesignStep& s = r.trace[i];
    if (!s.rejected_early) continue;
    ++early;
    EXPECT_TRUE(s.anneal.valid) << what << ": step " << i;
    EXPECT_FALSE(s.anneal.accepted) << what << ": step " << i << " accepted, yet rejected early";
    EXPECT_LE(s.proposed.tours_total, static_cast<int>(r.sequences.size())) << what;
  }
  EXPECT_EQ(r.early.proposals, early) << what;
  EXPECT_LE(r.early.proposals, r.valid_proposals) << what;
  if (early == 0) {
    EXPECT_EQ(r.early.tours_skipped, 0) << what;
  }
  return early;
}

TEST(DesignLoop, EarlyRejectionMakesTheSameDecisionsAsFullEvaluation) {
  int early_total = 0;
  for (const std::string file : {"bedroom.json", "office.json"}) {
    const Scene scene = shipped(file);
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      DesignResult r[2];
      for (int early = 0; early < 2; ++early) {
        DesignOptions o = options(seed, 40);
        o.planner.early = early == 1;
        r[early] = design(scene, o);
      }
      const std::string what = file + " seed " + std::to_string(seed);
      expect_same_design(r[0], r[1], what);
      // Without early rejection nothing is rejected early.
      EXPECT_EQ(expect_early_counters(r[0], what + " (full)"), 0);
      EXPECT_EQ(r[0].early.tours_skipped, 0) << what;
      const int early = expect_early_counters(r[1], what + " (early)");
      early_total += early;
      // A step rejected early reports a lower bound of the full cost.
      for (std::size_t i = 0; i < r[1].trace.size(); ++i) {
        const TraceEntry& e = r[1].trace[i].anneal;
        const TraceEntry& full = r[0].trace[i].anneal;
        if (!r[1].trace[i].rejected_early) {
          if (e.valid) {
            EXPECT_EQ(e.proposed_cost, full.proposed_cost) << what << " step " << i;
          }
          continue;
        }
        EXPECT_LE(e.proposed_cost, full.proposed_cost + 1e-9 * std::max(1.0, full.proposed_cost))
            << what << " step " << i << ": the bound exceeds the cost";
      }
      std::printf("%s: %d of %d valid proposals rejected early, %d tours skipped\n", what.c_str(),
                  early, r[1].valid_proposals, r[1].early.tours_skipped);
    }
  }
  EXPECT_GT(early_total, 20) << "early rejection was hardly exercised";
}

TEST(DesignLoop, RefusingImpossibleLegsLeavesTheBaselinesDesignUnchanged) {
  long refused = 0;
  for (const std::string file : {"l_studio.json", "crowded_living.json"}) {
    const Scene scene = shipped(file);
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
      DesignResult r[2];
      for (int refuse = 0; refuse < 2; ++refuse) {
        DesignOptions o = options(seed, 40);
        o.planner.refuse = refuse == 1;
        r[refuse] = design(scene, o);
      }
      const std::string what = file + " seed " + std::to_string(seed);
      expect_same_design(r[0], r[1], what);
      for (std::size_t k = 0; k < r[0].tours.size(); ++k) {
        ASSERT_EQ(r[0].tours[k].legs.size(), r[1].tours[k].legs.size()) << what;
        for (std::size_t i = 0; i < r[0].tours[k].legs.size(); ++i) {
          EXPECT_EQ(r[0].tours[k].legs[i].from, r[1].tours[k].legs[i].from) << what;
          EXPECT_EQ(r[0].tours[k].legs[i].to, r[1].tours[k].legs[i].to) << what;
        }
      }
      EXPECT_EQ(r[0].legs_refused, 0) << what;
      refused += r[1].legs_refused;
      std::printf("%s: %ld legs refused, tours found %d\n", what.c_str(), r[1].legs_refused,
                  r[1].final.tours_found);
    }
  }
  EXPECT_GT(refused, 50) << "no leg was refused: the comparison says nothing";
}

TEST(DesignLoop, ProposedPlannerWithEarlyRejectionIsTheSameWithOneAndTwoThreads) {
  int early_total = 0;
  for (const std::string file : {"bedroom.json", "l_studio.json"}) {
    const Scene scene = shipped(file);
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
      DesignResult r[2];
      for (int t = 0; t < 2; ++t) {
        DesignOptions o;
        o.planner = hrs::optimize::PlannerConfig::from_preset("baseline");
        o.seed = seed;
        o.iterations = 40;
        o.threads = t + 1;
        o.planner = hrs::optimize::PlannerConfig::from_preset("default");
        r[t] = design(scene, o);
        EXPECT_EQ(r[t].threads, t + 1);
      }
      const std::string what = file + " seed " + std::to_string(seed);
      expect_same_design(r[0], r[1], what);
      for (std::size_t i = 0; i < r[0].trace.size(); ++i) {
        const DesignStep &a = r[0].trace[i], &b = r[1].trace[i];
        EXPECT_EQ(a.rejected_early, b.rejected_early) << what << " step " << i;
        if (a.anneal.valid) {
          EXPECT_EQ(a.anneal.proposed_cost, b.anneal.proposed_cost) << what << " step " << i;
          EXPECT_EQ(a.proposed.tours_total, b.proposed.tours_total) << what << " step " << i;
        }
      }
      EXPECT_EQ(r[0].early.proposals, r[1].early.proposals) << what;
      EXPECT_EQ(r[0].early.tours_skipped, r[1].early.tours_skipped) << what;
      early_total += expect_early_counters(r[0], what + " (1 thread)");
      expect_early_counters(r[1], what + " (2 threads)");
    }
  }
  EXPECT_GT(early_total, 10);
}

TEST(DesignLoop, EscapeOpensTheSealedLStudio) {
  // The door's pocket is walled off by the sofa and the dining table: no
  // tour is found in the initial layout. Escape (unfound tours graded by how
  // walled off their stops are, focus moves on the walling objects) lets
  // the annealer relocate the sofa. Seed 3 ends with 10/10 (`hrspace design
  // scenes/l_studio.json --iterations 700 --seed 3 --threads 2`).
  const Scene scene = shipped("l_studio.json");
  const DesignResult r = design(scene, options(3, 700));
  std::printf("l_studio seed 3: tours %d/%d -> %d/%d, cost %.4f -> %.4f, %ld legs refused\n",
              r.initial.tours_found, r.initial.tours_total, r.final.tours_found,
              r.final.tours_total, r.initial.total(), r.final.total(), r.legs_refused);
  EXPECT_EQ(r.initial.tours_found, 0);
  EXPECT_TRUE(r.valid);
  EXPECT_GE(r.final.tours_found, 8);
  EXPECT_EQ(r.final.tours_found,
            static_cast<int>(std::count_if(r.tours.begin(), r.tours.end(),
                                           [](const planning::Tour& t) { return t.found; })));
  EXPECT_TRUE(layout_violation(r.layout).empty()) << layout_violation(r.layout);
}

TEST(DesignLoop, AStopWithNoFreeGoalPoseIsMovedOut) {
  // In the narrow passage, the proposed planner's seed 5 let the bed settle
  // in front of the bookshelf's only approach side: no goal pose of the
  // bookshelf was free, 3 of 10 tours were lost, and since the bookshelf
  // does not border the door's region it never joined the focus. Now a
  // stop without a free goal pose and its neighbours do (`hrspace design
  // scenes/narrow_passage.json --planner proposed --seed 5 --threads 2`).
  const Scene scene = shipped("narrow_passage.json");
  DesignOptions o = options(5, 700);
  o.planner = hrs::optimize::PlannerConfig::from_preset("default");
  const DesignResult r = design(scene, o);
  std::printf("narrow_passage proposed seed 5: tours %d/%d, cost %.4f\n", r.final.tours_found,
              r.final.tours_total, r.final.total());
  EXPECT_TRUE(r.valid);
  EXPECT_EQ(r.final.tours_found, r.final.tours_total);
  EXPECT_TRUE(layout_violation(r.layout).empty()) << layout_violation(r.layout);
}

TEST(DesignLoop, ACrowdedDoorIsCleared) {
  // A generated room (`hrspace generate --seed 7`, room 1: an L of 33
  // objects, scrambled into an overlapping layout). Once separated, the free
  // grid joins every stop to the door (no stop walled off), yet the car
  // finds no tour: the objects by the door box its first turn in, and the
  // focus on the stops where tours broke off never moved them. When every
  // unfound tour breaks off on the leg that leaves the door, the objects
  // within 2 m of the door's clear zone join the focus (`hrspace design
  // tests/optimize/zoo_7_1.json --seed 1 --threads 2`: 0/10 before).
  const Scene scene =
      geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/tests/optimize/zoo_7_1.json");
  DesignOptions o = options(1, 700);
  o.planner = hrs::optimize::PlannerConfig::from_preset("default");
  const DesignResult r = design(scene, o);
  std::printf("zoo_7_1 seed 1: tours %d/%d -> %d/%d, separated %d\n", r.initial.tours_found,
              r.initial.tours_total, r.final.tours_found, r.final.tours_total,
              r.unblock.separated);
  // The situation: no tour in the input, an invalid input made valid, then
  // no stop walled off in the grid.
  EXPECT_EQ(r.initial.tours_found, 0);
  EXPECT_GT(r.unblock.separated, 0);
  EXPECT_EQ(r.unblock.left_invalid, "");
  EXPECT_EQ(r.unblock.walled_after, 0);
  EXPECT_TRUE(r.valid);
  EXPECT_GE(r.final.tours_found, 9);
  EXPECT_TRUE(layout_violation(r.layout).empty()) << layout_violation(r.layout);
}

TEST(DesignLoop, TheNearestWallsOfTheDoorsRegionAreFocused) {
  // Two generated rooms (the generalization study's zoo seed 1: room 320,
  // 18 objects, and room 408, an L of 34 objects whose door stands in an
  // alcove). During the annealing, stops are walled off in the free grid
  // while no movable object bordering the door's region lies within 2 m of
  // them (a bed across the alcove's mouth, a bed and a single bed closing a
  // wing 2.1 m from the desk inside it): with a fixed 2 m reach the focus
  // was empty or missed them, and the designs ended at 2/10 and 0/10
  // tours. Now the bordering objects nearest each walled stop are the
  // focus (`hrspace design tests/optimize/zoo_1_408.json --seed 1`).
  // In room 408 the unblocking must also move the bed that seals the door's
  // wing: no uniform jump of it is valid in the crowded room, and without
  // the wall slots it falls back on, 3 stops stay walled off after the
  // unblocking and the design ends at 0/10 tours (1 stays walled now).
  for (const char* room : {"zoo_1_320.json", "zoo_1_408.json"}) {
    const Scene scene =
        geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/tests/optimize/" + room);
    DesignOptions o = options(1, 700);
    o.planner = hrs::optimize::PlannerConfig::from_preset("default");
    const DesignResult r = design(scene, o);
    std::printf("%s seed 1: tours %d/%d -> %d/%d\n", room, r.initial.tours_found,
                r.initial.tours_total, r.final.tours_found, r.final.tours_total);
    EXPECT_EQ(r.initial.tours_found, 0) << room;
    if (std::string(room) == "zoo_1_408.json") {
      EXPECT_LE(r.unblock.walled_after, 1);
    }
    EXPECT_TRUE(r.valid) << room;
    EXPECT_GE(r.final.tours_found, 9) << room;
    EXPECT_TRUE(layout_violation(r.layout).empty()) << room << ": " << layout_violation(r.layout);
  }
}

TEST(DesignLoop, AStopSealedOffByFixedObjectsIsMovedItself) {
  // Room 414 of the generalization study's zoo seed 1: a 42.4 × 3.3 m strip
  // of three rooms. A fixed wardrobe leaves 0.58 m at the first partition's
  // opening, less than the chair's 0.65 m, so the stops beyond it are
  // walled off by fixed objects alone: moving the objects around them (the
  // focus of every other walled stop) cannot open their pocket, and the
  // design ended at 1/10 tours. Such stops now join the focus themselves
  // (the free grid of the walls and fixed objects alone certifies that the
  // door reaches none of their free goal poses), and the design finds 6/10
  // (`hrspace design tests/optimize/zoo_1_414.json --seed 1`; the same with
  // any thread count). The bound leaves one tour of margin for another
  // compiler's rounding; 1/10 is what the rule's absence gives.
  const Scene scene =
      geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/tests/optimize/zoo_1_414.json");
  DesignOptions o = options(1, 700);
  o.planner = hrs::optimize::PlannerConfig::from_preset("default");
  const DesignResult r = design(scene, o);
  std::printf("zoo_1_414 seed 1: tours %d/%d -> %d/%d\n", r.initial.tours_found,
              r.initial.tours_total, r.final.tours_found, r.final.tours_total);
  EXPECT_TRUE(r.valid);
  EXPECT_GE(r.final.tours_found, 5);
  EXPECT_TRUE(layout_violation(r.layout).empty()) << layout_violation(r.layout);
}

TEST(DesignLoop, StopsThatCanBeApproachedStaySo) {
  // Every object of a sequence with a free goal pose in the input layout
  // still has one in the designed layout (escape refuses moves that cover
  // one), checked with goal_poses on a C-space built from the output alone;
  // and the rule did refuse moves in these runs.
  int refused = 0, checked = 0;
  for (const std::string file : {"bedroom.json", "l_studio.json", "crowded_living.json"}) {
    const Scene scene = shipped(file);
    const geometry::CSpace before(scene);
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
      const DesignResult r = design(scene, options(seed, 150));
      refused += r.covering_moves;
      const geometry::CSpace after(r.layout);
      std::vector<std::string> stops;
      for (const Sequence& q : r.sequences)
        for (std::size_t i = 1; i < q.nodes.size(); ++i)
          if (std::find(stops.begin(), stops.end(), q.nodes[i]) == stops.end())
            stops.push_back(q.nodes[i]);
      for (const std::string& id : stops) {
        const int i = scene.find_object(id);
        if (i < 0) continue;
        const auto& in = scene.objects[i];
        if (planning::goal_poses(scene, in, in.pose, before).empty()) continue;
        ++checked;
        const auto& out = r.layout.objects[i];
        EXPECT_FALSE(planning::goal_poses(r.layout, out, out.pose, after).empty())
            << file << " seed " << seed << ": " << id << " has no free goal pose left";
      }
    }
  }
  std::printf("stops checked %d, covering moves refused %d\n", checked, refused);
  EXPECT_GT(checked, 20);
  EXPECT_GT(refused, 0);
}

TEST(DesignLoop, LargeClearanceWeightWidensTheToursCorridors) {
  // The office (5 x 4 m) designed with the path clearance weight 10 and 0,
  // seeds 1..4, 150 iterations of the baseline: over the seeds, the mean
  // deficit (max(0, clearance_width − corridor width), averaged along the
  // tours) is smaller and the mean narrowest corridor of the tours wider
  // with the large weight. The annealing alone responds to the weight:
  // without `prefer`, so without the opening arrangement, which starts both
  // runs from a layout whose objects it took to the walls whatever the path
  // weights (with it, the corridors are as wide at weight 0, and 4 seeds
  // tell nothing), and without the final arrangement and polish, which move
  // objects for the preferences after the annealing (the preference terms
  // are then the paper's squared ones).
  const Scene office = shipped("office.json");
  double narrowest[2] = {0, 0}, deficit[2] = {0, 0};
  int found[2] = {0, 0};
  const double weights[2] = {10.0, 0.0};
  for (int w = 0; w < 2; ++w) {
    Scene scene = office;
    scene.weights.path = {1.0, 1.0, weights[w]};
    double seeds_narrowest = 0.0, seeds_deficit = 0.0;
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      DesignOptions o = options(seed, 150);
      o.opening = false;
      o.planner.prefer = false;
      const DesignResult r = design(scene, o);
      ASSERT_TRUE(r.valid);
      double n = 0.0, d = 0.0;
      int k = 0;
      for (const planning::Tour& t : r.tours) {
        if (!t.found) continue;
        n += t.metrics.min_clearance;
        d += t.metrics.clearance_deficit;
        ++k;
      }
      ASSERT_GT(k, 0) << "weight " << weights[w] << " seed " << seed << ": no tour found";
      std::printf("clearance weight %g seed %d: tours %d, mean narrowest corridor %.4f m, mean "
                  "deficit %.4f m\n",
                  weights[w], static_cast<int>(seed), k, n / k, d / k);
      seeds_narrowest += n / k;
      seeds_deficit += d / k;
      found[w] += k;
    }
    narrowest[w] = seeds_narrowest / 4;
    deficit[w] = seeds_deficit / 4;
  }
  std::printf("office, clearance_width %.3f m, over seeds 1-4: mean narrowest corridor %.4f m "
              "(weight 10) vs %.4f m (weight 0); mean deficit %.4f m vs %.4f m; tours %d vs %d\n",
              office.weights.clearance_width, narrowest[0], narrowest[1], deficit[0], deficit[1],
              found[0], found[1]);
  EXPECT_LT(deficit[0], deficit[1]);
  EXPECT_GT(narrowest[0], narrowest[1]);
}

}  // namespace
}  // namespace hrs::optimize

namespace hrs::optimize {
namespace {

// The score the polish raises is checked by Polish.KeepsOnlyHigherScoring-
// LayoutsThatLoseNoTour (arrange_test.cpp); here, in whole designs: no tour
// lost, a valid layout, and the counts consistent.
TEST(DesignLoop, PolishNeverLosesAFoundTour) {
  int kept = 0, squared = 0, runs = 0;
  for (const std::string file : {"bedroom.json", "office.json", "living_room.json"}) {
    const geometry::Scene scene =
        geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/scenes/" + file);
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      DesignOptions o;
      o.seed = seed;
      o.iterations = 60;  // a short anneal leaves work for the polish
      o.threads = 2;
      const DesignResult r = design(scene, o);
      const std::string what = file + " seed " + std::to_string(seed);
      ++runs;
      kept += r.polish.kept;
      EXPECT_GE(r.final.tours_found, r.polish.tours_found_before) << what;
      EXPECT_LE(r.polish.kept + r.polish.squared, r.polish.tried) << what;
      squared += r.polish.squared;
      EXPECT_TRUE(r.valid) << what;
      EXPECT_EQ(layout_violation(r.layout), "") << what;
      int found = 0;
      for (const auto& t : r.tours) found += t.found ? 1 : 0;
      EXPECT_EQ(found, r.final.tours_found) << what;
    }
  }
  // The situation the test is about occurred.
  EXPECT_GT(kept, 0) << "the polish kept nothing in " << runs << " designs";
  EXPECT_GT(squared, 0) << "the polish squared nothing in " << runs << " designs";
}

TEST(DesignLoop, RescueFindsToursACrippledRrtMissesAndLosesNone) {
  int rescued = 0, runs = 0;
  for (const std::string file : {"bedroom.json", "office.json", "narrow_passage.json"}) {
    const Scene scene = shipped(file);
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
      DesignOptions o = options(seed, 20);
      o.tour.planner.max_iterations = 3;
      ASSERT_TRUE(o.planner.prefer);  // else the first unblocking runs on the final layout
      o.planner.rescue = false;
      const DesignResult without = design(scene, o);
      o.planner.rescue = true;
      const DesignResult with = design(scene, o);
      const std::string what = file + " seed " + std::to_string(seed);
      ++runs;
      EXPECT_FALSE(without.rescue.ran) << what;
      // The lattice runs when the final layout still misses tours, and only then.
      if (!with.rescue.ran) {
        EXPECT_EQ(with.final.tours_found, with.final.tours_total) << what;
      }
      if (with.rescue.ran) {
        EXPECT_GT(with.rescue.tours_unfound, 0) << what;
      }
      // The annealing is the same in both runs; the first unblocking runs on
      // its best layout, before the arrangement (which saw it in `without`).
      const int best_found = without.arrange.tours_found_before;
      EXPECT_EQ(with.rescue.tours_unfound, without.final.tours_total - best_found) << what;
      // Nothing is lost: the unblockings' and the lattice's tours add to the
      // best layout's, and the preference stages between them lose none.
      EXPECT_GE(with.final.tours_found,
                best_found + with.rescue.unblocked + with.rescue.tours_found)
          << what;
      EXPECT_TRUE(with.valid) << what;
      EXPECT_EQ(layout_violation(with.layout), "") << what;
      int found = 0;
      for (const auto& t : with.tours) found += t.found ? 1 : 0;
      EXPECT_EQ(found, with.final.tours_found) << what;
      // Every found tour's legs join up (each path driven from its start
      // ends at its goal, the next leg starts there) and are free in the
      // final layout by the C-space's pose checks every 2 cm.
      const geometry::CSpace cspace(with.layout);
      for (const auto& t : with.tours) {
        if (!t.found) continue;
        for (std::size_t i = 0; i < t.legs.size(); ++i) {
          const auto& leg = t.legs[i];
          EXPECT_LE(geometry::pose_gap(rs::end_pose(leg.from, leg.path), leg.to), 1e-6)
              << what << ": leg " << i << " does not end at its goal";
          if (i + 1 < t.legs.size()) {
            EXPECT_LE(geometry::pose_gap(leg.to, t.legs[i + 1].from), 1e-9)
                << what << ": legs " << i << " and " << i + 1 << " do not join";
          }
          for (const geometry::Pose2& q : rs::sample(leg.from, leg.path, 0.02))
            ASSERT_TRUE(cspace.is_free(q)) << what << ": a rescued tour collides";
        }
      }
      rescued += with.rescue.unblocked + with.rescue.tours_found;
    }
  }
  // The situation the test is about occurred.
  EXPECT_GT(rescued, 0) << "the rescue found nothing in " << runs << " designs";
}

}  // namespace
}  // namespace hrs::optimize
