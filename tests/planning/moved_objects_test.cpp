// SPDX-License-Identifier: GPL-3.0-or-later
// moved_objects_clear (planning/moved_objects.h) against an independent
// reference: footprints placed and measured in long double (a crossing test
// for "inside", then the distance to every edge), over thousands of random
// layouts with a fixed seed. Convex footprints with one point placed at
// margin ± 1 nm outward from an edge's interior or a vertex check the
// boundary: at margin + 1 nm the object is clear, at margin − 1 nm it is not.

#include "planning/moved_objects.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace hrs::planning {
namespace {

using geometry::Pose2;
using geometry::Vec2;
using Real = long double;

struct RealPoint {
  Real x, y;
};

//! The footprint placed at `pose`, in long double.
std::vector<RealPoint> place(const geometry::Polygon& local, const Pose2& pose) {
  const Real c = std::cos(static_cast<Real>(pose.theta)),
             s = std::sin(static_cast<Real>(pose.theta));
  std::vector<RealPoint> out;
  for (const Vec2& v : local)
    out.push_back({pose.x + c * v.x - s * v.y, pose.y + s * v.x + c * v.y});
  return out;
}

//! Distance from `p` to the closed polygon `poly` (0 inside).
Real reference_distance(Vec2 p, const std::vector<RealPoint>& poly) {
  const Real px = p.x, py = p.y;
  bool inside = false;
  Real best = INFINITY;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const RealPoint a = poly[j], b = poly[i];
    if ((a.y > py) != (b.y > py) && px < a.x + (b.x - a.x) * (py - a.y) / (b.y - a.y))
      inside = !inside;
    const Real ex = b.x - a.x, ey = b.y - a.y;
    const Real t =
        std::clamp(((px - a.x) * ex + (py - a.y) * ey) / (ex * ex + ey * ey), Real(0), Real(1));
    best = std::min(best, std::hypot(px - (a.x + t * ex), py - (a.y + t * ey)));
  }
  return inside ? 0 : best;
}

bool reference_clear(const geometry::Scene& scene, const std::vector<Pose2>& then,
                     const std::vector<Pose2>& now, const std::vector<Vec2>& points, double margin,
                     bool old_poses_too) {
  for (std::size_t i = 0; i < now.size(); ++i) {
    if (now[i] == then[i]) continue;
    std::vector<Pose2> poses{now[i]};
    if (old_poses_too) poses.push_back(then[i]);
    for (const Pose2& pose : poses) {
      const std::vector<RealPoint> poly = place(scene.objects[i].footprint, pose);
      for (const Vec2& p : points)
        if (reference_distance(p, poly) <= margin) return false;
    }
  }
  return true;
}

double uniform(std::mt19937_64& rng, double a, double b) {
  return std::uniform_real_distribution<double>(a, b)(rng);
}

//! A counter-clockwise polygon around the origin: convex (a regular polygon
//! with jittered angles) or star-shaped with radii between 0.2 and 1 m.
geometry::Polygon random_footprint(std::mt19937_64& rng, bool convex) {
  const int n = 3 + static_cast<int>(rng() % 6);
  const double r = uniform(rng, 0.2, 1.0);
  geometry::Polygon out;
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * std::numbers::pi * (k + uniform(rng, -0.3, 0.3)) / n;
    const double rk = convex ? r : uniform(rng, 0.2, 1.0);
    out.push_back({rk * std::cos(a), rk * std::sin(a)});
  }
  return out;
}

Pose2 random_pose(std::mt19937_64& rng) {
  return {uniform(rng, -3.0, 3.0), uniform(rng, -3.0, 3.0), uniform(rng, -3.2, 3.2)};
}

TEST(MovedObjects, RandomLayoutsMatchTheReference) {
  std::mt19937_64 rng(20261123);
  int clear = 0, blocked = 0;
  for (int c = 0; c < 4000; ++c) {
    geometry::Scene scene;
    const int objects = 1 + static_cast<int>(rng() % 4);
    std::vector<Pose2> then, now;
    for (int i = 0; i < objects; ++i) {
      geometry::Object o;
      o.footprint = random_footprint(rng, rng() % 2 == 0);
      scene.objects.push_back(o);
      then.push_back(random_pose(rng));
      now.push_back(rng() % 3 == 0 ? then.back() : random_pose(rng));
    }
    std::vector<Vec2> points;
    const int n = static_cast<int>(rng() % 12);
    for (int k = 0; k < n; ++k)
      points.push_back({uniform(rng, -5.0, 5.0), uniform(rng, -5.0, 5.0)});
    const double margin = rng() % 8 == 0 ? 0.0 : uniform(rng, 0.0, 1.5);
    const bool old_too = rng() % 2 == 0;
    const bool want = reference_clear(scene, then, now, points, margin, old_too);
    ASSERT_EQ(moved_objects_clear(scene, then, now, points, margin, old_too), want) << "case " << c;
    ++(want ? clear : blocked);
  }
  // Both answers are well represented.
  EXPECT_GT(clear, 800);
  EXPECT_GT(blocked, 800);
}

TEST(MovedObjects, PointsAtTheMarginOfAnEdgeOrAVertex) {
  std::mt19937_64 rng(7);
  int cases = 0;
  for (int c = 0; c < 4000; ++c) {
    geometry::Scene scene;
    geometry::Object o;
    o.footprint = random_footprint(rng, true);
    scene.objects.push_back(o);
    // The two poses 20 m apart: only the one the point is placed at is near it.
    const Pose2 first = random_pose(rng);
    const std::vector<Pose2> then{first}, now{{first.x + 20.0, first.y, uniform(rng, -3.2, 3.2)}};
    const bool old_too = rng() % 2 == 0;
    const Pose2 at = old_too && rng() % 2 == 0 ? then[0] : now[0];
    const double margin = rng() % 8 == 0 ? 0.0 : uniform(rng, 0.0, 1.5);
    // Edge j from w[j] to w[j + 1]; outward is to the right of it (CCW).
    geometry::Polygon w;
    for (const Vec2& v : o.footprint) w.push_back(geometry::to_world(at, v));
    const std::size_t j = rng() % w.size();
    const Vec2 a = w[j], b = w[(j + 1) % w.size()];
    const Vec2 along = (1.0 / geometry::norm(b - a)) * (b - a);
    const Vec2 normal{along.y, -along.x};
    Vec2 base, out, in;
    if (rng() % 2 == 0) {
      base = a + uniform(rng, 0.05, 0.95) * (b - a);  // an edge's interior
      out = normal;
      in = normal;
    } else {
      // Vertex b: out in a direction between the outward normals of its
      // edges (its nearest point is then b), in along its angle's bisector.
      const Vec2 c2 = w[(j + 2) % w.size()];
      const Vec2 along2 = (1.0 / geometry::norm(c2 - b)) * (c2 - b);
      const Vec2 normal2{along2.y, -along2.x};
      const double t = uniform(rng, 0.1, 0.9);
      const Vec2 mix = (1.0 - t) * normal + t * normal2;
      base = b;
      out = (1.0 / geometry::norm(mix)) * mix;
      in = (1.0 / geometry::norm(normal + normal2)) * (normal + normal2);
    }
    for (const double d : {margin + 1e-9, margin - 1e-9}) {
      // d < 0 (margin 0): 1 nm inside the footprint.
      const std::vector<Vec2> points{base + d * (d < 0.0 ? in : out)};
      const bool want = reference_clear(scene, then, now, points, margin, old_too);
      ASSERT_EQ(want, d > margin) << "case " << c;  // the reference sees the boundary
      ASSERT_EQ(moved_objects_clear(scene, then, now, points, margin, old_too), want)
          << "case " << c << " offset " << d - margin;
      ++cases;
    }
  }
  EXPECT_EQ(cases, 8000);
}

TEST(MovedObjects, OnlyMovedObjectsCountAndOldPosesOnlyWhenAsked) {
  geometry::Scene scene;
  geometry::Object o;
  o.footprint = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  scene.objects = {o, o};
  const std::vector<Pose2> then{{0, 0, 0}, {5, 0, 0}}, now{{0, 0, 0}, {5, 3, 0}};
  // Inside object 0, which did not move.
  EXPECT_TRUE(moved_objects_clear(scene, then, now, std::vector<Vec2>{{0, 0}}, 0.1, true));
  // Near object 1's old pose only.
  const std::vector<Vec2> near_old{{5.55, 0.0}};
  EXPECT_TRUE(moved_objects_clear(scene, then, now, near_old, 0.1, false));
  EXPECT_FALSE(moved_objects_clear(scene, then, now, near_old, 0.1, true));
  // Near its new pose.
  EXPECT_FALSE(moved_objects_clear(scene, then, now, std::vector<Vec2>{{5.0, 3.58}}, 0.1, false));
  // Layouts of another size prove nothing.
  EXPECT_FALSE(moved_objects_clear(scene, std::vector<Pose2>{then[0]}, std::vector<Pose2>{now[0]},
                                   near_old, 0.1, false));
}

}  // namespace
}  // namespace hrs::planning
