// SPDX-License-Identifier: GPL-3.0-or-later
// The planner configuration (optimize/planner_config.h) and its text form
// (api::parse_planner): what each preset contains, the name/parse round
// trip on random configurations, and the refusals.

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>

#include "api/operations.h"
#include "api/reuse_list.h"
#include "geometry/error.h"
#include "optimize/planner_config.h"

namespace hrs::api {
namespace {

using optimize::PlannerConfig;
using planning::ReuseOptions;

//! Every field that decides a design, compared one by one.
void expect_same(const PlannerConfig& a, const PlannerConfig& b, const std::string& what) {
  EXPECT_EQ(a.preset, b.preset) << what;
  EXPECT_EQ(a.proposed, b.proposed) << what;
  for (const PlannerConfig::Switch& s : PlannerConfig::switches())
    EXPECT_EQ(a.*s.on, b.*s.on) << what << " switch " << s.name;
  if (!a.proposed) return;
  for (const ReuseOptions::Technique& t : ReuseOptions::techniques())
    EXPECT_EQ(a.reuse.*t.on, b.reuse.*t.on) << what << " technique " << t.name;
  for (const ReuseOptions::Parameter& p : ReuseOptions::parameters())
    EXPECT_EQ(a.reuse.*p.value, b.reuse.*p.value) << what << " parameter " << p.technique;
}

TEST(PlannerConfig, PresetsSayWhatTheyContain) {
  const PlannerConfig literal = parse_planner("literal");
  EXPECT_FALSE(literal.proposed);
  EXPECT_FALSE(literal.goalskip || literal.refuse || literal.escape || literal.early ||
               literal.prefer);

  const PlannerConfig paper = parse_planner("paper");
  EXPECT_TRUE(paper.proposed);
  EXPECT_EQ(paper.reuse.names(), "samples,steering,paths,trees");
  EXPECT_FALSE(paper.goalskip || paper.refuse || paper.escape || paper.early || paper.prefer);

  const PlannerConfig baseline = parse_planner("baseline");
  EXPECT_FALSE(baseline.proposed);
  EXPECT_TRUE(baseline.goalskip && baseline.refuse && baseline.escape && baseline.early &&
              baseline.prefer);

  const PlannerConfig d = parse_planner("default");
  EXPECT_TRUE(d.proposed);
  EXPECT_EQ(d.reuse.names(), parse_reuse("all").names());
  EXPECT_TRUE(d.goalskip && d.refuse && d.escape && d.early && d.prefer);
  // The library's default is the command's default.
  expect_same(PlannerConfig{}, d, "PlannerConfig{}");
  expect_same(parse_planner("proposed"), d, "proposed alias");
  EXPECT_EQ(parse_planner("proposed").name(), "default");
}

TEST(PlannerConfig, NamesParseBackOnRandomConfigurations) {
  std::mt19937_64 rng(20261125);
  std::bernoulli_distribution coin(0.5);
  std::uniform_int_distribution<int> pick(0, 3), value(1, 5000);
  const char* presets[] = {"literal", "paper", "baseline", "default"};
  for (int i = 0; i < 4000; ++i) {
    PlannerConfig c = PlannerConfig::from_preset(presets[pick(rng)]);
    for (const PlannerConfig::Switch& s : PlannerConfig::switches())
      if (coin(rng)) c.*s.on = coin(rng);
    if (c.proposed) {
      for (const ReuseOptions::Technique& t : ReuseOptions::techniques())
        if (coin(rng)) c.reuse.*t.on = coin(rng);
      for (const ReuseOptions::Parameter& p : ReuseOptions::parameters())
        if (c.reuse.*p.on && coin(rng)) c.reuse.*p.value = value(rng);
    }
    const std::string name = c.name();
    expect_same(parse_planner(name), c, name);
    EXPECT_EQ(parse_planner(name).name(), name);
    if (HasFailure()) break;
  }
}

TEST(PlannerConfig, ItemsApplyLeftToRight) {
  EXPECT_EQ(parse_planner("baseline,-escape").name(), "baseline,-escape");
  EXPECT_FALSE(parse_planner("baseline,-escape").escape);
  EXPECT_EQ(parse_planner("baseline,-escape,escape").name(), "baseline");
  EXPECT_EQ(parse_planner("default,-trees").name(), "default,-trees");
  EXPECT_EQ(parse_planner("paper,refuse,budget=500").name(), "paper,refuse,budget=500");
  EXPECT_EQ(parse_planner("literal,goalskip").name(), "literal,goalskip");
}

TEST(PlannerConfig, NonsenseIsRefusedWithOneMessage) {
  auto message = [](const std::string& text) {
    try {
      parse_planner(text);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message("fast"),
            "--planner: unknown planner preset 'fast' (default, baseline, paper, literal)");
  EXPECT_NE(message("baseline,trees").find("the baseline preset plans each leg with the RRT"),
            std::string::npos);
  EXPECT_NE(message("literal,budget=300").find("literal preset"), std::string::npos);
  EXPECT_NE(message("default,bogus").find("unknown item 'bogus'"), std::string::npos);
  EXPECT_NE(message("default,budget=0").find("budget=N"), std::string::npos);
  EXPECT_NE(message("").find("unknown planner preset ''"), std::string::npos);
  EXPECT_NE(message("default,").find("unknown item ''"), std::string::npos);
}

TEST(PlannerConfig, FrontEndOptionsTranslateIntoOneConfiguration) {
  const PlannerConfig c = design_planner("default", std::string("samples,steering"),
                                         std::string("escape,early"));
  EXPECT_EQ(c.reuse.names(), "samples,steering");
  EXPECT_FALSE(c.escape || c.early);
  EXPECT_TRUE(c.refuse);
  expect_same(parse_planner(c.name()), c, c.name());
  EXPECT_THROW(design_planner("baseline", std::string("all"), std::nullopt), InputError);
  EXPECT_THROW(design_planner("default", std::nullopt, std::string("trees")), InputError);
  expect_same(design_planner("baseline", std::nullopt, std::string("none")),
              parse_planner("baseline"), "--disable none");
}

}  // namespace
}  // namespace hrs::api
