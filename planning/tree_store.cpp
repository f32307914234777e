// SPDX-License-Identifier: GPL-3.0-or-later
#include "planning/tree_store.h"

#include <vector>

#include "planning/motion_validator.h"
#include "planning/path_ops.h"

namespace hrs::planning {

std::optional<RrtTree> TreeStore::usable(const RootKey& root, const Pose2& from,
                                         std::uint64_t* checks) const {
  const auto it = trees_.find(root);
  if (it == trees_.end() || it->second.nodes.empty()) return std::nullopt;
  const RrtTree& stored = it->second;
  if (static_cast<int>(stored.nodes.size()) > options_.tree_max_nodes) return std::nullopt;
  if (pose_gap(stored.root(), from) > options_.tree_root_tolerance) return std::nullopt;

  // Move the tree rigidly with its root (nodes re-driven along their edges),
  // then keep the nodes whose whole chain of edges is still free. Parents
  // precede their children, so one forward pass suffices.
  MotionValidator validator(*cspace_, radius_);
  const std::size_t n = stored.nodes.size();
  std::vector<Pose2> pose(n);
  std::vector<std::int32_t> remap(n, -1);
  RrtTree out;
  out.nodes.reserve(n);
  pose[0] = from;
  remap[0] = 0;
  out.nodes.push_back({from, -1, rs::Path{{}, radius_}, 0.0});
  for (std::size_t i = 1; i < n; ++i) {
    const RrtTree::Node& node = stored.nodes[i];
    const std::int32_t parent = remap[node.parent];
    if (parent < 0) continue;
    const Pose2 start = pose[node.parent];
    if (!validator.path_free(start, node.edge)) continue;
    pose[i] = rs::end_pose(start, node.edge);
    remap[i] = static_cast<std::int32_t>(out.nodes.size());
    out.nodes.push_back({pose[i], parent, node.edge, node.cost});
  }
  if (checks) *checks += validator.checks();
  return out;
}

void TreeStore::put(const RootKey& root, RrtTree tree) {
  if (tree.nodes.empty() || static_cast<int>(tree.nodes.size()) > options_.tree_max_nodes) {
    trees_.erase(root);
    return;
  }
  trees_[root] = std::move(tree);
}

}  // namespace hrs::planning
