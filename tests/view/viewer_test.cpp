// SPDX-License-Identifier: GPL-3.0-or-later
// design.html's data (view/viewer.h): the cusps against the gear changes
// of each leg's segments, driven here by a separate arc-and-line
// integrator; the footprints against the objects' local footprints moved
// to their poses here; the path against the tours' waypoints. The route
// width is the value of access::route_width_at (the function the viewer
// calls; tests/access checks the width itself) at every 7th path point. And the page: the same bytes for any
// thread count, and a scene name that tries to close the data's <script>.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "access/accessibility.h"
#include "geometry/scene.h"
#include "optimize/design.h"
#include "optimize/design_io.h"
#include "view/viewer.h"

namespace {

using hrs::geometry::Pose2;
using nlohmann::json;

hrs::optimize::DesignResult run(const std::string& file, int threads, int iterations = 40) {
  hrs::optimize::DesignOptions o;
  o.seed = 3;
  o.iterations = iterations;
  o.threads = threads;
  return hrs::optimize::design(
      hrs::geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/scenes/" + file), o);
}

//! The page's embedded data, parsed back.
json page_data(const std::string& html) {
  const std::string open = "<script id=\"hrspace-data\" type=\"application/json\">";
  const std::size_t a = html.find(open);
  EXPECT_NE(a, std::string::npos);
  const std::size_t b = html.find("</script>", a);
  return json::parse(html.substr(a + open.size(), b - a - open.size()));
}

//! Drives one segment (steer L/S/R, gear ±1, arc length) with turning
//! radius r: an arc about the centre to the steering side, or a line.
Pose2 drive(Pose2 p, char steer, int gear, double length, double r) {
  const double s = gear * length;
  if (steer == 'S') return {p.x + s * std::cos(p.theta), p.y + s * std::sin(p.theta), p.theta};
  const double k = steer == 'L' ? 1.0 : -1.0;
  const double th = p.theta + k * s / r;
  return {p.x + k * r * (std::sin(th) - std::sin(p.theta)),
          p.y - k * r * (std::cos(th) - std::cos(p.theta)), th};
}

class ViewerTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    result_ = new hrs::optimize::DesignResult(run("bedroom.json", 1));
  }
  static void TearDownTestSuite() { delete result_; }
  static hrs::optimize::DesignResult* result_;
};
hrs::optimize::DesignResult* ViewerTest::result_ = nullptr;

TEST_F(ViewerTest, CuspsAreTheGearChangesOfEveryLeg) {
  const json data = json::parse(hrs::view::design_data(*result_, "t", ""));
  const json tours = json::parse(hrs::optimize::tours_document(*result_))["tours"];
  const double r = result_->layout.wheelchair.turning_radius;
  int tours_with_cusps = 0;
  ASSERT_EQ(data["tours"].size(), tours.size());
  for (std::size_t k = 0; k < tours.size(); ++k) {
    std::vector<Pose2> cusps;
    for (const json& leg : tours[k]["legs"]) {
      Pose2 p{leg["from"][0], leg["from"][1], leg["from"][2]};
      const json& seg = leg["segments"];
      for (std::size_t i = 0; i < seg.size(); ++i) {
        p = drive(p, seg[i]["steer"].get<std::string>()[0], seg[i]["gear"], seg[i]["length"], r);
        if (i + 1 < seg.size() && seg[i]["gear"] != seg[i + 1]["gear"]) cusps.push_back(p);
      }
    }
    const json& drawn = data["tours"][k]["cusps"];
    ASSERT_EQ(drawn.size(), cusps.size()) << "tour " << k;
    for (std::size_t i = 0; i < cusps.size(); ++i) {
      EXPECT_NEAR(drawn[i][0].get<double>(), cusps[i].x, 2e-4) << "tour " << k << " cusp " << i;
      EXPECT_NEAR(drawn[i][1].get<double>(), cusps[i].y, 2e-4) << "tour " << k << " cusp " << i;
    }
    tours_with_cusps += cusps.empty() ? 0 : 1;
  }
  EXPECT_GT(tours_with_cusps, 0) << "no tour of this design reverses: the test checks nothing";
}

TEST_F(ViewerTest, PathWidthsAndStopsFollowTheTours) {
  const json data = json::parse(hrs::view::design_data(*result_, "t", ""));
  int checked = 0;
  for (std::size_t k = 0; k < result_->tours.size(); ++k) {
    const auto& tour = result_->tours[k];
    const json& t = data["tours"][k];
    EXPECT_EQ(t["found"].get<bool>(), tour.found);
    EXPECT_EQ(t["sequence"].get<std::vector<std::string>>(), tour.sequence);
    EXPECT_EQ(t["stops"].size(), tour.legs.size());
    std::size_t n = 0;
    for (const auto& leg : tour.legs) n += leg.waypoints.size() - (n == 0 ? 0 : 1);
    ASSERT_EQ(t["path"].size(), n);
    ASSERT_EQ(t["width"].size(), n);
    for (std::size_t i = 0; i < n; i += 7) {
      const Pose2 p{t["path"][i][0], t["path"][i][1], t["path"][i][2]};
      EXPECT_NEAR(t["width"][i].get<double>(), hrs::access::route_width_at(result_->layout, p), 2e-3);
      ++checked;
    }
    if (!tour.legs.empty()) {
      const Pose2 end = tour.legs.back().waypoints.back();
      EXPECT_NEAR(t["path"].back()[0].get<double>(), end.x, 1e-4);
      EXPECT_EQ(t["stops"].back().get<std::size_t>(), n - 1);
    }
  }
  EXPECT_GT(checked, 50);
}

TEST_F(ViewerTest, ObjectsAreTheLayoutsFootprints) {
  const json data = json::parse(hrs::view::design_data(*result_, "t", ""));
  ASSERT_EQ(data["objects"].size(), result_->layout.objects.size());
  for (std::size_t i = 0; i < result_->layout.objects.size(); ++i) {
    // The local footprint rotated by the heading and moved to the position.
    const auto& o = result_->layout.objects[i];
    const double c = std::cos(o.pose.theta), s = std::sin(o.pose.theta);
    const json& poly = data["objects"][i]["poly"];
    ASSERT_EQ(poly.size(), o.footprint.size());
    for (std::size_t v = 0; v < o.footprint.size(); ++v) {
      const double lx = o.footprint[v].x, ly = o.footprint[v].y;
      EXPECT_NEAR(poly[v][0].get<double>(), o.pose.x + c * lx - s * ly, 1e-4);
      EXPECT_NEAR(poly[v][1].get<double>(), o.pose.y + s * lx + c * ly, 1e-4);
    }
  }
  int unmet = 0;
  for (const json& o : data["objects"]) unmet += static_cast<int>(o["unmet"].size());
  EXPECT_EQ(unmet, result_->preferences.total - result_->preferences.met);
  EXPECT_EQ(data["trace"]["iteration"].size(), result_->trace.size());
}

TEST(Viewer, SameBytesForAnyThreadCount) {
  const auto one = run("office.json", 1, 25), two = run("office.json", 2, 25);
  const std::string a = hrs::view::design_html(one, "office", "{}");
  EXPECT_EQ(a, hrs::view::design_html(two, "office", "{}"));
  EXPECT_EQ(page_data(a)["tours"].size(), one.tours.size());
}

TEST(Viewer, ATitleCannotCloseTheDataScript) {
  const auto r = run("office.json", 1, 0);
  const std::string title = "x</script><script>alert(1)</script>";
  const std::string html = hrs::view::design_html(r, title, "");
  const std::string plain = hrs::view::design_html(r, "x", "");
  auto count = [](const std::string& s, const std::string& what) {
    int n = 0;
    for (std::size_t p = 0; (p = s.find(what, p)) != std::string::npos; p += what.size()) ++n;
    return n;
  };
  EXPECT_EQ(count(html, "</script>"), count(plain, "</script>"));
  EXPECT_EQ(page_data(html)["title"].get<std::string>(), title);
  EXPECT_TRUE(page_data(html)["accessibility"].is_null());
}

}  // namespace
