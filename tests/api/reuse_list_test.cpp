// SPDX-License-Identifier: GPL-3.0-or-later
// The --reuse list syntax (api/reuse_list.h): the parser against the options
// it must produce, and against ReuseOptions::names() on random switch sets.

#include "api/reuse_list.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>

#include "geometry/error.h"

namespace hrs::api {
namespace {

using planning::ReuseOptions;

TEST(ReuseList, ParsesTechniqueLists) {
  EXPECT_TRUE(api::parse_reuse("all").any());
  EXPECT_FALSE(api::parse_reuse("none").any());
  const ReuseOptions o = api::parse_reuse("paths,trees");
  EXPECT_TRUE(o.paths && o.trees);
  EXPECT_FALSE(o.samples || o.steering || o.failures || o.shortcuts);
  EXPECT_TRUE(api::parse_reuse("shortcuts").shortcuts);
  EXPECT_EQ(o.names(), "paths,trees");
  EXPECT_EQ(ReuseOptions::none().names(), "none");
  EXPECT_THROW(api::parse_reuse("paths,bogus"), InputError);
  // "all" is every default technique (budget and backoff are opt-in);
  // -name turns one off, left to right.
  EXPECT_EQ(api::parse_reuse("all").names(),
            "samples,steering,paths,trees,failures,shortcuts,metrics,speculate");
  EXPECT_EQ(api::parse_reuse("all,-trees").names(),
            "samples,steering,paths,failures,shortcuts,metrics,speculate");
  EXPECT_EQ(api::parse_reuse("all,budget").names(),
            "samples,steering,paths,trees,failures,shortcuts,budget,metrics,speculate");
  EXPECT_EQ(api::parse_reuse("metrics").names(), "metrics");
  EXPECT_EQ(api::parse_reuse("all,-trees,trees").names(), api::parse_reuse("all").names());
  EXPECT_EQ(api::parse_reuse("budget").names(), "budget");
  EXPECT_TRUE(api::parse_reuse("budget").any());
  EXPECT_FALSE(api::parse_reuse("budget,-budget").any());
  EXPECT_THROW(api::parse_reuse("all,-bogus"), InputError);
  EXPECT_THROW(api::parse_reuse("-all"), InputError);
  const ReuseOptions b = api::parse_reuse("all,budget=800");
  EXPECT_TRUE(b.budget);
  EXPECT_EQ(b.budget_iterations, 800);
  EXPECT_EQ(api::parse_reuse(b.names()).budget_iterations, 800);  // names() round-trips
  const ReuseOptions f = api::parse_reuse("all,-backoff,backoff=25");
  EXPECT_TRUE(f.backoff);
  EXPECT_EQ(f.backoff_floor, 25);
  EXPECT_EQ(api::parse_reuse(f.names()).backoff_floor, 25);
  for (const char* bad : {"budget=", "budget=0", "budget=-5", "budget=12x", "budget=2000000",
                          "backoff=", "backoff=0", "samples=3", "-budget=5"})
    EXPECT_THROW(api::parse_reuse(bad), InputError) << bad;
}

// names() and parse_reuse() are inverses on every switch set, with random
// parameters; a list naming the same techniques in another order, or with
// an item turned off and on again, parses to the same options.
TEST(ReuseList, NamesRoundTripOnRandomSwitchSets) {
  std::mt19937_64 rng(2026);
  const auto& techniques = ReuseOptions::techniques();
  for (int c = 0; c < 4000; ++c) {
    ReuseOptions o = ReuseOptions::none();
    for (const auto& t : techniques) o.*t.on = (rng() & 1) != 0;
    if (o.budget) o.budget_iterations = 1 + static_cast<int>(rng() % 1'000'000);
    if (o.backoff) o.backoff_floor = 1 + static_cast<int>(rng() % 1'000'000);
    const ReuseOptions back = parse_reuse(o.names());
    for (const auto& t : techniques) ASSERT_EQ(back.*t.on, o.*t.on) << o.names();
    if (o.budget) {
      ASSERT_EQ(back.budget_iterations, o.budget_iterations) << o.names();
    }
    if (o.backoff) {
      ASSERT_EQ(back.backoff_floor, o.backoff_floor) << o.names();
    }
    // Reversed order, each name preceded by its own -name: the same switches.
    std::string reversed;
    for (auto t = techniques.rbegin(); t != techniques.rend(); ++t) {
      if (!(o.*t->on)) continue;
      reversed += std::string(reversed.empty() ? "" : ",") + "-" + t->name + "," + t->name;
    }
    const ReuseOptions again = parse_reuse(reversed.empty() ? "none" : reversed);
    for (const auto& t : techniques) ASSERT_EQ(again.*t.on, o.*t.on) << reversed;
  }
}

}  // namespace
}  // namespace hrs::api
