// SPDX-License-Identifier: GPL-3.0-or-later
#include "planning/proof_oracle.h"

#include <stdexcept>

namespace hrs::planning {

ProofOracle::ProofOracle(const geometry::Scene& scene, const geometry::CSpace& cspace,
                         geometry::FreeGridOptions grid, std::size_t max_cells)
    : scene_(&scene), cspace_(&cspace), grid_options_(grid), max_cells_(max_cells) {}

ProofOracle::~ProofOracle() = default;

void ProofOracle::invalidate() {
  std::lock_guard lock(mutex_);
  current_ = false;
}

bool ProofOracle::disconnected(const geometry::Pose2& from, const geometry::Pose2& to) const {
  std::unique_ptr<geometry::ReachabilityQuery> query;
  {
    std::lock_guard lock(mutex_);
    if (!grid_ && !unavailable_) {
      try {
        grid_ = std::make_unique<geometry::FreeGrid>(*scene_, grid_options_);
      } catch (const std::invalid_argument&) {
        unavailable_ = true;  // cells too coarse for this chair: no proofs
      }
    }
    if (!grid_) return false;
    if (!current_) {
      for (int i = 0; i < cspace_->object_count(); ++i)
        grid_->move_object(i, cspace_->object_pose(i));
      current_ = true;
    }
    if (idle_.empty()) {
      query = std::make_unique<geometry::ReachabilityQuery>();
    } else {
      query = std::move(idle_.back());
      idle_.pop_back();
    }
  }
  // The grid is not written again before the next invalidate(): reads are safe.
  const bool proven = query->query(*grid_, from, to, max_cells_) ==
                      geometry::ReachabilityQuery::Answer::kDisconnected;
  std::lock_guard lock(mutex_);
  idle_.push_back(std::move(query));
  return proven;
}

}  // namespace hrs::planning
