// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Paper §V-C: RRT trees kept between layouts, rooted at goal poses, reused
// while their root barely moves and rebuilt past a node count (the paper's
// 30, from its Fig. "rrt-it").

#include <cstdint>
#include <map>
#include <optional>

#include "geometry/cspace.h"
#include "geometry/pose.h"
#include "planning/reuse_options.h"
#include "planning/rrt.h"

namespace hrs::planning {

using geometry::Pose2;

//! Where an RRT tree is rooted: a goal pose of an object (−1: the door).
struct RootKey {
  int object = -1;
  int slot = 0;
  friend auto operator<=>(const RootKey&, const RootKey&) = default;
};

//! §V-C: RRT trees by root. A tree is handed out only while its root moved
//! at most `tree_root_tolerance`; it is moved rigidly onto the new root (its
//! edges are RS segments, so node poses are re-driven from the root), every
//! edge is re-checked continuously and invalid subtrees are dropped.
class TreeStore {
 public:
  TreeStore(const geometry::CSpace& cspace, double radius, const ReuseOptions& options)
      : cspace_(&cspace), radius_(radius), options_(options) {}

  //! A pruned copy of the tree of `root` moved onto `from`, or nullopt when
  //! there is none, its root moved too far, or it is too large. Counts the
  //! edge checks into `checks`. Const: safe from parallel tours.
  std::optional<RrtTree> usable(const RootKey& root, const Pose2& from,
                                std::uint64_t* checks = nullptr) const;
  //! Keeps `tree` for `root`, or forgets the root's tree when `tree` has
  //! more than tree_max_nodes nodes (rebuilt next time).
  void put(const RootKey& root, RrtTree tree);
  std::size_t size() const { return trees_.size(); }

 private:
  const geometry::CSpace* cspace_;
  double radius_;
  ReuseOptions options_;
  std::map<RootKey, RrtTree> trees_;
};

}  // namespace hrs::planning
