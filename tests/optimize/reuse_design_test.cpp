// SPDX-License-Identifier: GPL-3.0-or-later
// Designs with the proposed planner (paper §V, planning/reuse.h): with every
// reuse technique off it is the baseline exactly; with all on, the same seed
// gives the same layout and tours for 1 and 2 threads, every waypoint of a
// found tour is free by the exact CGAL reference (not the C-space the
// planners use), and report.json carries the reuse counters.

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "api/reuse_list.h"
#include "geometry/scene.h"
#include "optimize/design.h"
#include "optimize/design_io.h"
#include "planning/reuse.h"
#include "tests/support/reference.h"

namespace hrs::optimize {
namespace {

geometry::Scene scene(const std::string& name) {
  return geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/scenes/" + name + ".json");
}

DesignResult run(const geometry::Scene& s, bool proposed, const std::string& reuse, int threads,
                 int iterations = 25) {
  DesignOptions o;
  o.seed = 3;
  o.iterations = iterations;
  o.threads = threads;
  o.planner = hrs::optimize::PlannerConfig::from_preset(proposed ? "default" : "baseline");
  if (proposed) o.planner.reuse = api::parse_reuse(reuse);
  return design(s, o);
}

std::string layout_of(const DesignResult& r) { return geometry::write_scene(r.layout); }

TEST(ProposedDesign, AllReuseOffEqualsBaselineExactly) {
  for (const std::string name : {"office", "bedroom"}) {
    const geometry::Scene s = scene(name);
    const DesignResult base = run(s, false, "none", 2);
    const DesignResult off = run(s, true, "none", 2);
    EXPECT_EQ(layout_of(base), layout_of(off)) << name;
    EXPECT_EQ(tours_document(base), tours_document(off)) << name;
    EXPECT_EQ(base.final.total(), off.final.total()) << name;
    EXPECT_EQ(base.initial.total(), off.initial.total()) << name;
    ASSERT_EQ(base.trace.size(), off.trace.size());
    for (std::size_t i = 0; i < base.trace.size(); ++i) {
      const double a = base.trace[i].anneal.proposed_cost, b = off.trace[i].anneal.proposed_cost;
      EXPECT_TRUE(a == b || (std::isnan(a) && std::isnan(b))) << i << ": " << a << " vs " << b;
    }
    EXPECT_GT(off.counters.legs_planned, 0u);
  }
}

TEST(ProposedDesign, SameSeedSameBytesForOneAndTwoThreads) {
  int found = 0;
  for (const std::string name : {"living_room", "bedroom"}) {
    const geometry::Scene s = scene(name);
    const DesignResult one = run(s, true, "all", 1);
    const DesignResult two = run(s, true, "all", 2);
    EXPECT_EQ(layout_of(one), layout_of(two)) << name;
    EXPECT_EQ(tours_document(one), tours_document(two)) << name;
    // The counters are counted from the pure outcomes: equal as well.
    EXPECT_EQ(one.counters.legs_database, two.counters.legs_database) << name;
    EXPECT_EQ(one.counters.legs_repaired, two.counters.legs_repaired) << name;
    EXPECT_EQ(one.counters.legs_planned, two.counters.legs_planned) << name;
    EXPECT_EQ(one.counters.legs_failed, two.counters.legs_failed) << name;
    EXPECT_EQ(one.counters.rrt_iterations, two.counters.rrt_iterations) << name;
    // Reuse actually happened.
    EXPECT_GT(one.counters.legs_database, 0u) << name;
    EXPECT_EQ(one.tours_invalidated, 0) << name;
    // The found tours drive through free space (waypoints 5 cm apart).
    const test_support::ExactReference reference(one.layout);
    long waypoints = 0, blocked = 0;
    for (const planning::Tour& t : one.tours) {
      if (!t.found) continue;
      ++found;
      for (const auto& leg : t.legs)
        for (const geometry::Pose2& w : leg.waypoints) {
          ++waypoints;
          if (!reference.pose_free(w)) ++blocked;
        }
    }
    EXPECT_EQ(blocked, 0) << name << ": of " << waypoints << " waypoints";
  }
  EXPECT_GT(found, 0);
}

TEST(ProposedDesign, ReportCarriesTheReuseCounters) {
  const DesignResult r = run(scene("office"), true, "paths,trees", 2, 10);
  RunInfo info;
  info.planner = "proposed";
  const auto report = nlohmann::json::parse(report_document(r, info));
  ASSERT_TRUE(report.contains("reuse"));
  const auto& reuse = report["reuse"];
  EXPECT_EQ(reuse["techniques"], "paths,trees");
  EXPECT_EQ(reuse["legs_database"].get<std::uint64_t>(), r.counters.legs_database);
  EXPECT_EQ(reuse["legs_repaired"].get<std::uint64_t>(), r.counters.legs_repaired);
  EXPECT_EQ(reuse["legs_planned"].get<std::uint64_t>(), r.counters.legs_planned);
  std::uint64_t histogram = 0;
  for (const auto& bin : reuse["rrt_iterations_histogram"])
    histogram += bin["legs"].get<std::uint64_t>();
  EXPECT_EQ(histogram, r.counters.legs_planned);
  const auto baseline =
      nlohmann::json::parse(report_document(run(scene("office"), false, "none", 2, 3), {}));
  EXPECT_FALSE(baseline.contains("reuse"));
}

}  // namespace
}  // namespace hrs::optimize
