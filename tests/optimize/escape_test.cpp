// SPDX-License-Identifier: GPL-3.0-or-later
// The covered-stop rule (optimize/escape.h, covers_a_stop) against brute
// force: for random moves of one or two objects near a stop of a shipped
// room (and of a partner beside where the first goes), the rule says "covers" exactly when some stop with a free goal pose
// in the current layout has none in a C-space built afresh from the moved
// layout (planning::goal_poses). Pairs are the polish's exchanges and pair
// moves: two moves can cover a stop together that neither covers alone,
// and the rule must see both objects at their new places.

#include "optimize/escape.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "geometry/cspace.h"
#include "geometry/scene.h"
#include "optimize/sequences.h"
#include "optimize/tour_round.h"
#include "planning/goals.h"

namespace hrs::optimize {
namespace {

using geometry::Pose2;
using geometry::Scene;

//! The stops of `sequences` (every node after the door), ascending.
std::vector<int> stops_of(const Scene& scene, const std::vector<Sequence>& sequences) {
  std::vector<int> out;
  for (const Sequence& q : sequences)
    for (std::size_t i = 1; i < q.nodes.size(); ++i)
      if (const int k = scene.find_object(q.nodes[i]); k >= 0) out.push_back(k);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

//! The stops of `stops` with a free goal pose in `scene` (a C-space of its
//! own).
std::vector<int> open_stops(const Scene& scene, const std::vector<int>& stops) {
  const geometry::CSpace cspace(scene);
  std::vector<int> out;
  for (int s : stops) {
    const geometry::Object& o = scene.objects[static_cast<std::size_t>(s)];
    if (!planning::goal_poses(scene, o, o.pose, cspace).empty()) out.push_back(s);
  }
  return out;
}

//! Brute force: some stop of `open` has no free goal pose with every object
//! at `poses` (a C-space of the moved layout alone).
bool covers_brute(const Scene& scene, const std::vector<int>& open,
                  const std::vector<Pose2>& poses) {
  Scene moved = scene;
  for (std::size_t i = 0; i < poses.size(); ++i) moved.objects[i].pose = poses[i];
  const geometry::CSpace after(moved);
  for (int s : open) {
    const geometry::Object& o = moved.objects[static_cast<std::size_t>(s)];
    if (planning::goal_poses(moved, o, o.pose, after).empty()) return true;
  }
  return false;
}

TEST(Escape, CoveredStopRuleAgreesWithBruteForceForSingleAndPairMoves) {
  int cases = 0, covered = 0, pair_only = 0;
  for (const std::string file : {"bedroom.json", "office.json", "narrow_passage.json"}) {
    const Scene scene =
        geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/scenes/" + file);
    DesignOptions options;
    options.threads = 1;
    const std::vector<Sequence> sequences = scene_sequences(scene);
    TourRound round(scene, options, sequences);
    std::vector<bool> movable;
    for (const geometry::Object& o : scene.objects) movable.push_back(!o.fixed);
    EscapePolicy escape(scene, round, sequences, movable, options, true);
    escape.refresh_open_stops();
    const std::vector<int> stops = stops_of(scene, sequences);
    const std::vector<int> open = open_stops(scene, stops);
    std::vector<int> movers;
    for (std::size_t i = 0; i < movable.size(); ++i)
      if (movable[i]) movers.push_back(static_cast<int>(i));
    ASSERT_GE(movers.size(), 2u) << file;
    std::vector<Pose2> poses;
    for (const geometry::Object& o : scene.objects) poses.push_back(o.pose);
    std::mt19937_64 rng(20261128);
    std::uniform_real_distribution<double> off(-2.0, 2.0), turn(-3.14159, 3.14159);
    std::uniform_int_distribution<std::size_t> pick(0, movers.size() - 1);
    std::uniform_int_distribution<std::size_t> pick_stop(0, stops.size() - 1);
    // Each object lands within 2 m per axis of a random stop, where it
    // most likely takes goal poses away.
    const auto near_a_stop = [&] {
      const Pose2& s = scene.objects[static_cast<std::size_t>(stops[pick_stop(rng)])].pose;
      return Pose2{s.x + off(rng), s.y + off(rng), turn(rng)};
    };
    std::uniform_real_distribution<double> beside(-1.0, 1.0);
    for (int n = 0; n < 400; ++n) {
      const int a = movers[pick(rng)];
      int b = movers[pick(rng)];
      while (b == a) b = movers[pick(rng)];
      const auto ia = static_cast<std::size_t>(a), ib = static_cast<std::size_t>(b);
      // `a` alone, `b` alone, both near stops, and `b` within 1 m of where
      // `a` goes (a moved stop whose new goal poses its partner takes).
      std::vector<Pose2> one = poses, other = poses, two = poses, follow = poses;
      one[ia] = two[ia] = follow[ia] = near_a_stop();
      other[ib] = two[ib] = near_a_stop();
      follow[ib] = Pose2{one[ia].x + beside(rng), one[ia].y + beside(rng), turn(rng)};
      const bool rule_one = escape.covers_a_stop(one, a);
      const bool rule_other = escape.covers_a_stop(other, b);
      const bool rule_two = escape.covers_a_stop(two, a);
      const bool rule_follow = escape.covers_a_stop(follow, a);
      EXPECT_EQ(rule_one, covers_brute(scene, open, one)) << file << " case " << n << " a alone";
      EXPECT_EQ(rule_other, covers_brute(scene, open, other)) << file << " case " << n << " b alone";
      EXPECT_EQ(rule_two, covers_brute(scene, open, two)) << file << " case " << n << " pair";
      EXPECT_EQ(rule_follow, covers_brute(scene, open, follow))
          << file << " case " << n << " b beside a";
      // The rule leaves the C-space as it was.
      for (std::size_t i = 0; i < poses.size(); ++i)
        ASSERT_EQ(round.cspace().object_pose(static_cast<int>(i)), poses[i]) << file;
      cases += 4;
      covered += rule_one + rule_other + rule_two + rule_follow;
      pair_only += rule_two && !rule_one && !rule_other;
    }
  }
  std::printf("cases %d, covering %d, covering only as a pair %d\n", cases, covered, pair_only);
  EXPECT_GT(covered, 20);
  EXPECT_GT(pair_only, 0);
}

}  // namespace
}  // namespace hrs::optimize
