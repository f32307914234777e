// SPDX-License-Identifier: GPL-3.0-or-later
// api::design_restarts(): the design kept is the lowest-cost one of the
// single chains run on their own at the chains' seeds (an independent run
// of each), whatever the thread count; one chain is optimize::design().
#include <gtest/gtest.h>

#include <atomic>
#include <set>
#include <string>

#include "api/operations.h"
#include "geometry/error.h"
#include "geometry/scene.h"

namespace {

using hrs::api::design_restarts;
using hrs::api::restart_seed;

hrs::geometry::Scene small_bedroom() {
  return hrs::geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/scenes/small_bedroom.json");
}

hrs::optimize::DesignOptions short_run(std::uint64_t seed, int threads) {
  hrs::optimize::DesignOptions o;
  o.seed = seed;
  o.iterations = 20;
  o.threads = threads;
  return o;
}

std::vector<hrs::geometry::Pose2> poses(const hrs::optimize::DesignResult& r) {
  std::vector<hrs::geometry::Pose2> out;
  for (const auto& o : r.layout.objects) out.push_back(o.pose);
  return out;
}

bool same_poses(const std::vector<hrs::geometry::Pose2>& a, const std::vector<hrs::geometry::Pose2>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].x != b[i].x || a[i].y != b[i].y || a[i].theta != b[i].theta) return false;
  return true;
}

TEST(RestartSeed, ChainZeroKeepsTheSeedAndTheOthersAreDistinctValidSeeds) {
  for (std::uint64_t seed : {0ull, 1ull, 2ull, 12345ull, (1ull << 53)}) {
    EXPECT_EQ(restart_seed(seed, 0), seed);
    std::set<std::uint64_t> seen{seed};
    for (int r = 1; r <= 2000; ++r) {
      const std::uint64_t s = restart_seed(seed, r);
      EXPECT_LE(s, 1ull << 53) << seed << " " << r;  // a seed --seed accepts
      EXPECT_TRUE(seen.insert(s).second) << "seed " << seed << " chain " << r << " repeats";
    }
  }
}

TEST(DesignRestarts, OneChainIsThePlainDesign) {
  const auto scene = small_bedroom();
  const auto plain = hrs::optimize::design(scene, short_run(3, 1));
  const auto one = design_restarts(scene, short_run(3, 1), 1, nullptr, {});
  EXPECT_TRUE(one.chains.empty());
  EXPECT_EQ(one.seed, 3u);
  EXPECT_EQ(one.result.final.total(), plain.final.total());
  EXPECT_TRUE(same_poses(poses(one.result), poses(plain)));
}

TEST(DesignRestarts, KeepsTheCheapestOfTheChainsRunAloneWhateverTheThreads) {
  const auto scene = small_bedroom();
  for (std::uint64_t seed : {1ull, 4ull}) {
    const int chains = 3;
    // Each chain on its own, as `--seed S --restarts 1` runs it.
    std::vector<hrs::optimize::DesignResult> alone;
    int cheapest = 0;
    for (int r = 0; r < chains; ++r) {
      alone.push_back(hrs::optimize::design(scene, short_run(restart_seed(seed, r), 1)));
      const auto& a = alone.back();
      const auto& c = alone[static_cast<std::size_t>(cheapest)];
      if (std::pair(!a.valid, a.final.total()) < std::pair(!c.valid, c.final.total())) cheapest = r;
    }
    for (int threads : {1, 2}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + ", threads " + std::to_string(threads));
      const auto kept = design_restarts(scene, short_run(seed, threads), chains, nullptr, {});
      ASSERT_EQ(kept.chains.size(), static_cast<std::size_t>(chains));
      for (int r = 0; r < chains; ++r) {
        EXPECT_EQ(kept.chains[static_cast<std::size_t>(r)].seed, restart_seed(seed, r));
        EXPECT_EQ(kept.chains[static_cast<std::size_t>(r)].cost,
                  alone[static_cast<std::size_t>(r)].final.total());
        EXPECT_EQ(kept.chains[static_cast<std::size_t>(r)].tours_found,
                  alone[static_cast<std::size_t>(r)].final.tours_found);
      }
      EXPECT_EQ(kept.seed, restart_seed(seed, cheapest));
      EXPECT_EQ(kept.result.final.total(), alone[static_cast<std::size_t>(cheapest)].final.total());
      EXPECT_TRUE(same_poses(poses(kept.result), poses(alone[static_cast<std::size_t>(cheapest)])));
    }
  }
}

TEST(DesignRestarts, ProgressHearsChainZeroOnly) {
  const auto scene = small_bedroom();
  int steps = 0;
  (void)design_restarts(scene, short_run(1, 2), 3, nullptr,
                        [&](const hrs::optimize::DesignStep&) { ++steps; });
  EXPECT_EQ(steps, 20);  // one per iteration of chain 0, none from the others
}

TEST(DesignRestarts, AStopBeforeTheFirstIterationOfEveryChainThrows) {
  const auto scene = small_bedroom();
  std::atomic<bool> stop{true};
  EXPECT_THROW((void)design_restarts(scene, short_run(1, 2), 2, &stop, {}), hrs::Interrupted);
}

}  // namespace
