// SPDX-License-Identifier: GPL-3.0-or-later
// Top-M sequences against brute-force enumeration, α against a hand-computed
// example (paper §III-A, §III-D).
#include "optimize/sequences.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>

namespace hrs::optimize {
namespace {

using geometry::Activity;

// Brute force, written independently of AoGraph: every sequence of `visits`
// moves from "door", no node twice in a row, probability renormalized over
// the non-self entries of each raw row.
std::map<std::vector<std::string>, double> brute_force(const Activity& act, int visits) {
  std::map<std::vector<std::string>, double> out;
  std::vector<std::vector<std::string>> frontier{{"door"}};
  std::vector<double> lik{1.0};
  for (int step = 0; step < visits; ++step) {
    std::vector<std::vector<std::string>> next;
    std::vector<double> next_lik;
    for (std::size_t i = 0; i < frontier.size(); ++i) {
      const std::string& last = frontier[i].back();
      auto row = act.transitions.find(last);
      if (row == act.transitions.end()) continue;
      double self = row->second.count(last) ? row->second.at(last) : 0.0;
      for (const auto& [to, p] : row->second) {
        if (to == last || p <= 0.0 || self >= 1.0) continue;
        auto seq = frontier[i];
        seq.push_back(to);
        next.push_back(seq);
        next_lik.push_back(lik[i] * p / (1.0 - self));
      }
    }
    frontier = std::move(next);
    lik = std::move(next_lik);
  }
  for (std::size_t i = 0; i < frontier.size(); ++i) out[frontier[i]] = lik[i];
  return out;
}

Activity random_activity(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> nodes_d(1, 5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n = nodes_d(rng);
  std::vector<std::string> ids{"door"};
  // (std::string("o") += ...: GCC 12 warns falsely (-Wrestrict) on "o" + std::string.)
  for (int i = 0; i < n; ++i) ids.push_back(std::string("o").append(std::to_string(i)));
  const bool quantized = u(rng) < 0.5;  // many exact ties
  Activity act;
  for (const auto& from : ids) {
    if (from != "door" && u(rng) < 0.1) continue;  // no row: a dead end
    std::map<std::string, double> row;
    double sum = 0.0;
    for (const auto& to : ids) {
      if (u(rng) < 0.35) continue;
      double w = quantized ? std::floor(u(rng) * 4.0) + 1.0 : u(rng) + 1e-3;
      row[to] = w;
      sum += w;
    }
    if (row.empty()) row[from] = sum = 1.0;  // absorbing
    for (auto& [to, p] : row) p /= sum;
    act.transitions[from] = row;
  }
  return act;
}

TEST(Sequences, TopMEqualsBruteForceOnRandomGraphs) {
  std::mt19937_64 rng(20240505);
  std::uniform_int_distribution<int> visits_d(1, 4), count_d(1, 15);
  int compared = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const Activity act = random_activity(rng);
    const int visits = visits_d(rng), count = count_d(rng);
    const auto all = brute_force(act, visits);
    std::vector<double> expected;
    for (const auto& [seq, l] : all) expected.push_back(l);
    std::sort(expected.rbegin(), expected.rend());
    if (static_cast<int>(expected.size()) > count) expected.resize(count);

    const auto got = top_sequences(AoGraph(act), "door", visits, count);
    ASSERT_EQ(got.size(), expected.size()) << "trial " << trial;
    std::set<std::vector<std::string>> seen;
    for (std::size_t i = 0; i < got.size(); ++i) {
      ASSERT_EQ(got[i].nodes.size(), static_cast<std::size_t>(visits + 1));
      ASSERT_TRUE(seen.insert(got[i].nodes).second) << "duplicate sequence, trial " << trial;
      auto it = all.find(got[i].nodes);
      ASSERT_NE(it, all.end()) << "not a valid sequence, trial " << trial;
      EXPECT_NEAR(got[i].likelihood, it->second, 1e-12);
      // Same likelihood profile as the brute-force ranking (ties may reorder).
      EXPECT_NEAR(got[i].likelihood, expected[i], 1e-12) << "trial " << trial << " rank " << i;
      ++compared;
    }
  }
  EXPECT_GT(compared, 10000);
}

TEST(Sequences, LikelihoodsOfAllSequencesSumToOneWhenNoDeadEnds) {
  Activity act;
  act.transitions["door"] = {{"a", 0.5}, {"b", 0.5}};
  act.transitions["a"] = {{"a", 0.5}, {"b", 0.25}, {"c", 0.25}};
  act.transitions["b"] = {{"a", 1.0}};
  act.transitions["c"] = {{"a", 0.1}, {"b", 0.2}, {"c", 0.7}};
  const auto all = top_sequences(AoGraph(act), "door", 4, 1000);
  double sum = 0.0;
  for (const auto& s : all) sum += s.likelihood;
  EXPECT_NEAR(sum, 1.0, 1e-12);
  for (std::size_t i = 1; i < all.size(); ++i) EXPECT_LE(all[i].likelihood, all[i - 1].likelihood);
}

TEST(Sequences, HandComputedSceneFormatExample) {
  // The AO graph of scene-format.md. bed's self-transition 0.2 is skipped, so
  // bed's row becomes tv .375, lamp .375, dresser .25.
  Activity act;
  act.transitions["door"] = {{"bed", 0.4}, {"tv", 0.2}, {"dresser", 0.3}, {"lamp", 0.1}};
  act.transitions["bed"] = {{"bed", 0.2}, {"tv", 0.3}, {"lamp", 0.3}, {"dresser", 0.2}};
  act.transitions["tv"] = {{"bed", 0.6}, {"dresser", 0.2}, {"lamp", 0.2}};
  act.transitions["dresser"] = {{"bed", 0.5}, {"tv", 0.3}, {"lamp", 0.2}};
  act.transitions["lamp"] = {{"bed", 0.7}, {"tv", 0.3}};
  const auto top = top_sequences(AoGraph(act), "door", 3, 3);
  ASSERT_EQ(top.size(), 3u);
  EXPECT_EQ(top[0].nodes, (std::vector<std::string>{"door", "bed", "lamp", "bed"}));
  EXPECT_NEAR(top[0].likelihood, 0.4 * 0.375 * 0.7, 1e-15);
  EXPECT_EQ(top[1].nodes, (std::vector<std::string>{"door", "bed", "tv", "bed"}));
  EXPECT_NEAR(top[1].likelihood, 0.4 * 0.375 * 0.6, 1e-15);
  // Tied with door-dresser-bed-tv; ties go to the smaller ids ("lamp" < "tv").
  EXPECT_EQ(top[2].nodes, (std::vector<std::string>{"door", "dresser", "bed", "lamp"}));
  EXPECT_NEAR(top[2].likelihood, 0.3 * 0.5 * 0.375, 1e-15);
}

TEST(Sequences, AlphaMatchesHandComputedExample) {
  // s1 = door a b c (L .4): counts door 1, a 2, b 2, c 1 of 6.
  // s2 = door b a b (L .3): counts door 1, b 2+1, a 2 of 6.
  const std::vector<Sequence> seqs{{{"door", "a", "b", "c"}, 0.4}, {{"door", "b", "a", "b"}, 0.3}};
  const auto alpha = object_scales(seqs);
  ASSERT_EQ(alpha.size(), 4u);
  EXPECT_NEAR(alpha.at("a"), 0.4 * 2 / 6 + 0.3 * 2 / 6, 1e-15);
  EXPECT_NEAR(alpha.at("b"), 0.4 * 2 / 6 + 0.3 * 3 / 6, 1e-15);
  EXPECT_NEAR(alpha.at("c"), 0.4 * 1 / 6, 1e-15);
  EXPECT_NEAR(alpha.at("door"), 0.4 / 6 + 0.3 / 6, 1e-15);
}

TEST(Sequences, UnknownStartOrZeroCountGivesNothing) {
  Activity act;
  act.transitions["door"] = {{"a", 1.0}};
  EXPECT_TRUE(top_sequences(AoGraph(act), "nope", 2, 5).empty());
  EXPECT_TRUE(top_sequences(AoGraph(act), "door", 2, 0).empty());
  // "a" has no row: sequences of 2 moves do not exist, of 1 move one does.
  EXPECT_TRUE(top_sequences(AoGraph(act), "door", 2, 5).empty());
  EXPECT_EQ(top_sequences(AoGraph(act), "door", 1, 5).size(), 1u);
}

}  // namespace
}  // namespace hrs::optimize
