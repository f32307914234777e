// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Shared helpers of the planning suites: the scene files, random free poses,
// and an independent check of a returned path (structure, ends, and collision
// by the exact CGAL reference of tests/support/reference.h, never by the
// planner's own C-space).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "geometry/cspace.h"
#include "geometry/scene.h"
#include "rs/reeds_shepp.h"
#include "tests/support/poses.h"
#include "tests/support/reference.h"
#include "tests/support/scenes.h"

namespace hrs::test_support {

//! Paths of the scene files shipped in scenes/ (sorted).
inline std::vector<std::string> planning_scene_files() { return scene_files(); }

//! A shipped scene by file name, e.g. "office.json".
inline geometry::Scene shipped_scene(const std::string& file) {
  return geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/scenes/" + file);
}

//! A uniformly random pose in the room's box that the C-space certifies free.
inline geometry::Pose2 random_free_pose(const geometry::Scene& scene,
                                        const geometry::CSpace& cspace, std::mt19937_64& rng) {
  for (;;) {
    const geometry::Pose2 p = random_pose(scene, rng);
    if (cspace.is_free(p)) return p;
  }
}

//! The exact reference behind a sound prefilter: a pose whose chair is more
//! than 1 cm (computed in doubles, error ~1e-15 m) inside the room and away
//! from every object is free; every other pose goes to the exact CGAL test.
class ReferenceChecker {
 public:
  explicit ReferenceChecker(const geometry::Scene& scene)
      : exact_(scene),
        room_(scene.room.polygon),
        hl_(0.5 * scene.wheelchair.length),
        hw_(0.5 * scene.wheelchair.width) {
    for (const auto& o : scene.objects) objects_.push_back(geometry::world_footprint(o));
  }
  bool pose_free(const geometry::Pose2& pose) const {
    ++checks_;
    if (clearly_free(pose)) return true;
    ++exact_checks_;
    return exact_.pose_free(pose);
  }
  std::size_t checks() const { return checks_; }
  std::size_t exact_checks() const { return exact_checks_; }

 private:
  static constexpr double kMargin = 0.01;
  static double seg_point(geometry::Vec2 p, geometry::Vec2 a, geometry::Vec2 b) {
    const geometry::Vec2 ab = b - a;
    const double l2 = geometry::dot(ab, ab);
    const double t = l2 > 0 ? std::clamp(geometry::dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
    return geometry::norm(p - (a + t * ab));
  }
  static bool inside(geometry::Vec2 p, const geometry::Polygon& poly) {
    bool in = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
      const auto a = poly[i], b = poly[j];
      if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
        in = !in;
    }
    return in;
  }
  //! Distance between the boundaries of two polygons; 0 when edges cross.
  static double boundary_gap(const geometry::Polygon& a, const geometry::Polygon& b) {
    double d = 1e300;
    for (std::size_t i = 0; i < a.size(); ++i) {
      const auto a0 = a[i], a1 = a[(i + 1) % a.size()];
      for (std::size_t j = 0; j < b.size(); ++j) {
        const auto b0 = b[j], b1 = b[(j + 1) % b.size()];
        const double c1 = geometry::cross(a1 - a0, b0 - a0), c2 = geometry::cross(a1 - a0, b1 - a0);
        const double c3 = geometry::cross(b1 - b0, a0 - b0), c4 = geometry::cross(b1 - b0, a1 - b0);
        if (((c1 > 0) != (c2 > 0)) && ((c3 > 0) != (c4 > 0))) return 0.0;
        d = std::min({d, seg_point(a0, b0, b1), seg_point(b0, a0, a1)});
      }
    }
    return d;
  }
  bool clearly_free(const geometry::Pose2& pose) const {
    geometry::Polygon chair;
    for (geometry::Vec2 c : {geometry::Vec2{hl_, hw_}, {-hl_, hw_}, {-hl_, -hw_}, {hl_, -hw_}})
      chair.push_back(geometry::to_world(pose, c));
    if (!inside(pose.position(), room_) || boundary_gap(chair, room_) <= kMargin) return false;
    for (const auto& o : objects_) {
      if (boundary_gap(chair, o) <= kMargin) return false;
      if (inside(o.front(), chair) || inside(chair.front(), o)) return false;
    }
    return true;
  }

  ExactReference exact_;
  geometry::Polygon room_;
  std::vector<geometry::Polygon> objects_;
  double hl_, hw_;
  mutable std::size_t checks_ = 0, exact_checks_ = 0;
};

//! Checks every property a returned path must have; returns the number of
//! reference pose checks done. `what` labels failures.
inline std::size_t expect_valid_path(const ReferenceChecker& reference, const geometry::Pose2& from,
                                     const geometry::Pose2& to, const rs::Path& path, double radius,
                                     const std::string& what, double spacing = 0.001) {
  EXPECT_EQ(path.radius, radius) << what;
  double sum = 0.0;
  for (const rs::Segment& s : path.segments) {
    EXPECT_TRUE(s.steer == rs::Steer::kLeft || s.steer == rs::Steer::kRight ||
                s.steer == rs::Steer::kStraight)
        << what;
    EXPECT_TRUE(s.gear == 1 || s.gear == -1) << what;
    EXPECT_GE(s.length, 0.0) << what;
    sum += s.length;
  }
  EXPECT_NEAR(path.length(), sum, 1e-12) << what;
  // Ends: drive the segments with rs::advance (independent of the planner's
  // bookkeeping) and compare with the requested poses.
  geometry::Pose2 p = from;
  for (const rs::Segment& s : path.segments) p = rs::advance(p, s, radius);
  EXPECT_LE(pose_error(p, to), 1e-6) << what << ": ends at " << p.x << "," << p.y << "," << p.theta;
  const std::vector<geometry::Pose2> poses = rs::sample(from, path, spacing);
  EXPECT_LE(pose_error(poses.front(), from), 1e-12) << what;
  std::size_t bad = 0;
  for (const geometry::Pose2& q : poses) {
    if (!reference.pose_free(q)) {
      if (++bad <= 3)
        ADD_FAILURE() << what << ": pose in collision by the exact reference: " << q.x << "," << q.y
                      << "," << q.theta;
    }
  }
  return poses.size();
}

}  // namespace hrs::test_support
