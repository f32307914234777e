// SPDX-License-Identifier: GPL-3.0-or-later
// geometry::polygon_distance (the clearance of goal poses and the escape's
// "near" test) against an independent measure: the smallest distance between
// points sampled every 5 mm along both boundaries, which exceeds the true
// distance by at most 5 mm, and CGAL's exact overlap predicate. Random
// star-shaped polygons (simple by construction) and rotated rectangles, from
// far apart to overlapping and nested; plus analytic cases.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "geometry/polygon_ops.h"
#include "geometry/scene.h"

namespace hrs::geometry {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kStep = 0.005;

//! Boundary points at most kStep apart, vertices included.
std::vector<Vec2> boundary_samples(const Polygon& p) {
  std::vector<Vec2> out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2 a = p[i], b = p[(i + 1) % p.size()];
    const int n = std::max(1, static_cast<int>(std::ceil(norm(b - a) / kStep)));
    for (int k = 0; k < n; ++k) out.push_back(a + (static_cast<double>(k) / n) * (b - a));
  }
  return out;
}

double sampled_distance(const Polygon& a, const Polygon& b) {
  const std::vector<Vec2> sa = boundary_samples(a), sb = boundary_samples(b);
  double best = std::numeric_limits<double>::infinity();
  for (const Vec2& p : sa)
    for (const Vec2& q : sb) best = std::min(best, norm(p - q));
  return best;
}

//! A star-shaped polygon around `c`: sorted angles, radii in [r0, r1].
Polygon star(std::mt19937_64& rng, Vec2 c, double r0, double r1) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int n = 3 + static_cast<int>(unit(rng) * 6);
  std::vector<double> angles;
  for (int i = 0; i < n; ++i) angles.push_back(2.0 * kPi * (i + 0.8 * unit(rng)) / n);
  Polygon p;
  for (double t : angles) {
    const double r = r0 + (r1 - r0) * unit(rng);
    p.push_back({c.x + r * std::cos(t), c.y + r * std::sin(t)});
  }
  return p;
}

Polygon rectangle(Vec2 c, double w, double h, double theta) {
  Polygon p;
  for (Vec2 v : {Vec2{w / 2, h / 2}, Vec2{-w / 2, h / 2}, Vec2{-w / 2, -h / 2}, Vec2{w / 2, -h / 2}})
    p.push_back(to_world({c.x, c.y, theta}, v));
  return p;
}

TEST(PolygonDistance, MatchesSampledBoundariesAndTheExactOverlapTest) {
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> pos(-2.0, 2.0), ang(-kPi, kPi), size(0.2, 1.2);
  int apart = 0, overlapping = 0, nested = 0;
  for (int i = 0; i < 1500; ++i) {
    const Vec2 ca{0.0, 0.0}, cb{pos(rng), pos(rng)};
    const Polygon a = i % 2 ? star(rng, ca, 0.2, 0.9) : rectangle(ca, size(rng), size(rng), ang(rng));
    // Every tenth pair nests a small polygon inside the other's core.
    const Polygon b = i % 10 == 0 ? rectangle(ca, 0.05, 0.05, ang(rng))
                      : i % 3   ? star(rng, cb, 0.1, 0.7)
                                : rectangle(cb, size(rng), size(rng), ang(rng));
    const double d = polygon_distance(a, b);
    ASSERT_EQ(d, polygon_distance(b, a)) << i;
    if (interiors_overlap(a, b)) {
      ++overlapping;
      if (i % 10 == 0) ++nested;
      EXPECT_EQ(d, 0.0) << "pair " << i << " overlaps";
      continue;
    }
    ++apart;
    const double s = sampled_distance(a, b);
    EXPECT_LE(d, s + 1e-12) << "pair " << i;
    EXPECT_GE(d, s - kStep) << "pair " << i;
  }
  EXPECT_GT(apart, 300);
  EXPECT_GT(overlapping, 300);
  EXPECT_GT(nested, 100);
}

TEST(PolygonDistance, AnalyticCases) {
  const Polygon unit{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  auto shifted = [&](double dx, double dy) {
    Polygon p = unit;
    for (Vec2& v : p) v = v + Vec2{dx, dy};
    return p;
  };
  EXPECT_DOUBLE_EQ(polygon_distance(unit, shifted(1.5, 0.0)), 0.5);           // side by side
  EXPECT_DOUBLE_EQ(polygon_distance(unit, shifted(0.3, 1.25)), 0.25);         // above, offset
  EXPECT_NEAR(polygon_distance(unit, shifted(2.0, 2.0)), std::sqrt(2.0), 1e-15);  // corners
  EXPECT_EQ(polygon_distance(unit, shifted(1.0, 0.0)), 0.0);                  // touching
  EXPECT_EQ(polygon_distance(unit, shifted(0.5, 0.5)), 0.0);                  // crossing
  const Polygon inner{{0.4, 0.4}, {0.6, 0.4}, {0.6, 0.6}, {0.4, 0.6}};
  EXPECT_EQ(polygon_distance(unit, inner), 0.0);                              // nested
  EXPECT_EQ(polygon_distance(inner, unit), 0.0);
}

}  // namespace
}  // namespace hrs::geometry
