// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// An exact, independent collision reference for tests: the chair's footprint
// rotated by an exact rational rotation (tan-half-angle, within ~1e-16 rad of
// the pose's heading) and tested with CGAL's exact Boolean operations against
// the room and each object's footprint. Slow; only for tests. It does not use
// the C-space, its slices or its convex pieces.

#include <memory>
#include <vector>

#include "geometry/pose.h"
#include "geometry/scene.h"

namespace hrs::test_support {

class ExactReference {
 public:
  //! Uses the scene's room, wheelchair and the objects at their current poses.
  explicit ExactReference(const geometry::Scene& scene);
  ~ExactReference();
  ExactReference(ExactReference&&) noexcept;
  //! True if the chair at `pose` is inside the closed room and its interior
  //! meets no object's interior.
  bool pose_free(const geometry::Pose2& pose) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace hrs::test_support
