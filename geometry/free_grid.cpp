// SPDX-License-Identifier: GPL-3.0-or-later
// Certified outer approximation of the free C-space; see free_grid.h for the
// argument.
//
// Rounding. Every quantity below (rotated core corners, Minkowski differences,
// scanline crossings, cell centres) is a few floating-point operations on
// coordinates bounded by 1 km, so it is off by less than 1e-12 m. A centre
// that the computation puts inside A ⊕ (−core) is therefore within 1e-12 m of
// the true set, and the core used for the proof (shrunk by m − ε, ε = 1 mm)
// overlaps A by nearly ε: far beyond any rounding.

#include "geometry/free_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "geometry/polygon_ops.h"

namespace hrs::geometry {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kSlack = 1e-3;  // ε: metres of overlap the rasterized cores keep
constexpr std::size_t kMaxCells = std::size_t{64} << 20;

}  // namespace

FreeGrid::FreeGrid(const Scene& scene, FreeGridOptions options) : slices_(options.slices) {
  if (!(options.cell > 0) || slices_ < 8)
    throw std::invalid_argument("FreeGrid: cell must be > 0 and slices >= 8");
  const Polygon& room = scene.room.polygon;
  const auto [xmin, ymin, xmax, ymax] = bounding_box(room);
  // Cells tile the room's box exactly, so every centre is inside it.
  nx_ = std::max(1, static_cast<int>(std::ceil((xmax - xmin) / options.cell)));
  ny_ = std::max(1, static_cast<int>(std::ceil((ymax - ymin) / options.cell)));
  if (static_cast<double>(nx_) * ny_ * slices_ > static_cast<double>(kMaxCells))
    throw std::invalid_argument("FreeGrid: more than 64 M cells");
  xmin_ = xmin, ymin_ = ymin;
  hx_ = (xmax - xmin) / nx_, hy_ = (ymax - ymin) / ny_;
  dtheta_ = 2.0 * kPi / slices_;

  const double hl = 0.5 * scene.wheelchair.length, hw = 0.5 * scene.wheelchair.width;
  const double reach = std::hypot(hl, hw);
  margin_ = reach * 0.5 * dtheta_ + 0.5 * std::hypot(hx_, hy_) + kSlack;
  const double cl = hl - margin_, cw = hw - margin_;
  if (!(cl > 0) || !(cw > 0))
    throw std::invalid_argument("FreeGrid: cells too coarse for the chair (empty core)");
  cores_.resize(slices_);
  for (int k = 0; k < slices_; ++k) {
    const double theta = -kPi + (k + 0.5) * dtheta_;
    const Vec2 local[4] = {{cl, cw}, {-cl, cw}, {-cl, -cw}, {cl, -cw}};
    for (int i = 0; i < 4; ++i) cores_[k][i] = rotate(local[i], theta);
  }
  counts_.assign(static_cast<std::size_t>(nx_) * ny_ * slices_, 0);
  if (slices_ <= 64)
    free_mask_.assign(static_cast<std::size_t>(nx_) * ny_,
                      slices_ == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << slices_) - 1);

  // The outside of the room, as convex pieces reaching beyond any core.
  for (const Polygon& wall : complement_pieces(room, reach + 0.1))
    for (int k = 0; k < slices_; ++k) rasterize(wall, k, +1);
  for (const Object& o : scene.objects) {
    objects_.push_back({o.pose, convex_partition(o.footprint)});
    cover_object(static_cast<int>(objects_.size()) - 1, +1);
  }
}

void FreeGrid::move_object(int index, const Pose2& pose) {
  if (objects_.at(index).pose == pose) return;
  cover_object(index, -1);
  objects_[index].pose = pose;
  cover_object(index, +1);
}

void FreeGrid::cover_object(int index, int delta) {
  const ObjectState& o = objects_[index];
  for (const Polygon& local : o.local_pieces) {
    Polygon world;
    for (const Vec2& v : local) world.push_back(to_world(o.pose, v));
    for (int k = 0; k < slices_; ++k) rasterize(world, k, delta);
  }
}

void FreeGrid::rasterize(const Polygon& piece, int k, int delta) {
  // C-obstacle of the core: the hull of every piece vertex minus every core
  // corner (the core is centred on the pose).
  std::vector<Vec2> pts;
  pts.reserve(piece.size() * 4);
  for (const Vec2& a : piece)
    for (const Vec2& c : cores_[k]) pts.push_back(a - c);
  const std::vector<Vec2> p = convex_hull_doubles(std::move(pts));
  if (p.size() < 3) return;
  double pymin = p[0].y, pymax = p[0].y;
  for (const Vec2& v : p) pymin = std::min(pymin, v.y), pymax = std::max(pymax, v.y);
  const int row_lo = std::max(0, static_cast<int>(std::ceil((pymin - ymin_) / hy_ - 0.5)));
  const int row_hi = std::min(ny_ - 1, static_cast<int>(std::floor((pymax - ymin_) / hy_ - 0.5)));
  for (int iy = row_lo; iy <= row_hi; ++iy) {
    const double y = ymin_ + (iy + 0.5) * hy_;
    double xa = std::numeric_limits<double>::infinity(), xb = -xa;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec2 u = p[i], v = p[(i + 1) % p.size()];
      if ((u.y - y) * (v.y - y) > 0) continue;  // the edge does not reach the line
      if (u.y == v.y) {
        xa = std::min({xa, u.x, v.x}), xb = std::max({xb, u.x, v.x});
        continue;
      }
      const double x = u.x + (y - u.y) / (v.y - u.y) * (v.x - u.x);
      xa = std::min(xa, x), xb = std::max(xb, x);
    }
    if (!(xa <= xb)) continue;
    const int lo = std::max(0, static_cast<int>(std::ceil((xa - xmin_) / hx_ - 0.5)));
    const int hi = std::min(nx_ - 1, static_cast<int>(std::floor((xb - xmin_) / hx_ - 0.5)));
    for (int ix = lo; ix <= hi; ++ix) {
      std::uint16_t& c = counts_[index(ix, iy, k)];
      const bool was_free = c == 0;
      c = static_cast<std::uint16_t>(c + delta);
      if (!free_mask_.empty() && was_free != (c == 0))
        free_mask_[static_cast<std::size_t>(iy) * nx_ + ix] ^= std::uint64_t{1} << k;
    }
  }
}

std::size_t FreeGrid::cell_of(const Pose2& pose) const {
  const int ix = std::clamp(static_cast<int>(std::floor((pose.x - xmin_) / hx_)), 0, nx_ - 1);
  const int iy = std::clamp(static_cast<int>(std::floor((pose.y - ymin_) / hy_)), 0, ny_ - 1);
  const int k = std::clamp(static_cast<int>(std::floor((wrap_angle(pose.theta) + kPi) / dtheta_)),
                           0, slices_ - 1);
  return index(ix, iy, k);
}

Pose2 FreeGrid::centre(std::size_t cell) const {
  int ix, iy, k;
  coords(cell, ix, iy, k);
  return {xmin_ + (ix + 0.5) * hx_, ymin_ + (iy + 0.5) * hy_, -kPi + (k + 0.5) * dtheta_};
}

std::size_t FreeGrid::blocked_count() const {
  return static_cast<std::size_t>(
      std::count_if(counts_.begin(), counts_.end(), [](std::uint16_t c) { return c != 0; }));
}

ReachabilityQuery::Answer ReachabilityQuery::query(const FreeGrid& grid, const Pose2& a,
                                                   const Pose2& b, std::size_t max_cells) {
  const std::size_t words = (grid.cell_count() + 63) / 64;
  for (auto& m : marks_) {
    if (m.size() != words) m.assign(words, 0);
  }
  for (std::size_t c : visited_) marks_[0][c >> 6] = marks_[1][c >> 6] = 0;
  visited_.clear();
  const std::size_t ends[2] = {grid.cell_of(a), grid.cell_of(b)};
  if (grid.blocked(ends[0]) || grid.blocked(ends[1])) return Answer::kUnknown;
  if (ends[0] == ends[1]) return Answer::kConnected;
  std::size_t head[2] = {0, 0};
  for (int s = 0; s < 2; ++s) {
    queue_[s].assign(1, ends[s]);
    marks_[s][ends[s] >> 6] |= std::uint64_t{1} << (ends[s] & 63);
    visited_.push_back(ends[s]);
  }
  const int nx = grid.nx(), ny = grid.ny(), nk = grid.slices();
  for (;;) {
    for (int s = 0; s < 2; ++s) {
      if (head[s] == queue_[s].size()) return Answer::kDisconnected;
      if (visited_.size() >= max_cells) return Answer::kUnknown;
      int ix, iy, k;
      grid.coords(queue_[s][head[s]++], ix, iy, k);
      for (int dy = -1; dy <= 1; ++dy) {
        const int y = iy + dy;
        if (y < 0 || y >= ny) continue;
        for (int dx = -1; dx <= 1; ++dx) {
          const int x = ix + dx;
          if (x < 0 || x >= nx) continue;
          for (int dk = -1; dk <= 1; ++dk) {
            const int kk = (k + dk + nk) % nk;
            const std::size_t n = grid.index(x, y, kk);
            const std::uint64_t bit = std::uint64_t{1} << (n & 63);
            if (marks_[s][n >> 6] & bit) continue;
            if (grid.blocked(n)) continue;
            if (marks_[1 - s][n >> 6] & bit) return Answer::kConnected;
            marks_[s][n >> 6] |= bit;
            visited_.push_back(n);
            queue_[s].push_back(n);
          }
        }
      }
    }
  }
}

}  // namespace hrs::geometry

namespace hrs::geometry {
namespace {

//! Column masks of n slices (n <= 64): cyclic shifts, dilation by one
//! slice and the fill of seeds along runs of free slices.
struct SliceRing {
  int n;
  std::uint64_t full;
  explicit SliceRing(int slices)
      : n(slices), full(slices == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << slices) - 1) {}
  std::uint64_t up(std::uint64_t r) const { return ((r << 1) | (r >> (n - 1))) & full; }
  std::uint64_t down(std::uint64_t r) const { return ((r >> 1) | (r << (n - 1))) & full; }
  std::uint64_t dilate(std::uint64_t r) const { return r | up(r) | down(r); }
  //! Every bit of `free` joined to a bit of `seed & free` through set bits
  //! of `free`, around the ring: a Kogge–Stone occluded fill each way (the
  //! chess-bitboard technique), twice, the second pass after carrying the
  //! wrap-around (bit n−1 ↔ bit 0).
  std::uint64_t fill(std::uint64_t seed, std::uint64_t free) const {
    std::uint64_t r = seed & free;
    for (int pass = 0; pass < 2 && r; ++pass) {
      std::uint64_t gen = r, pro = free;
      for (int s = 1; s < 64; s <<= 1) {
        gen |= pro & (gen << s);
        pro &= pro << s;
      }
      std::uint64_t gen2 = gen;
      pro = free;
      for (int s = 1; s < 64; s <<= 1) {
        gen2 |= pro & (gen2 >> s);
        pro &= pro >> s;
      }
      r = gen2;
      const std::uint64_t top = std::uint64_t{1} << (n - 1);
      if ((r & top) && (free & 1)) r |= 1;
      if ((r & 1) && (free & top)) r |= top;
    }
    return r;
  }
};

}  // namespace

void ReachableSet::fill(const FreeGrid& grid, const Pose2& start) {
  if (!grid.has_column_masks())
    throw std::invalid_argument("ReachableSet: the grid has more than 64 slices");
  grid_ = &grid;
  const std::size_t columns = static_cast<std::size_t>(grid.nx()) * grid.ny();
  reached_.assign(columns, 0);
  distance_.clear();
  reached_columns_ = 0;
  queue_.clear();
  const SliceRing ring(grid.slices());
  const std::size_t cell = grid.cell_of(start);
  const std::size_t c0 = cell / grid.slices();
  const std::uint64_t seed = std::uint64_t{1} << (cell % grid.slices());
  if (!(grid.free_slices(c0) & seed)) {
    distance_.assign(columns, std::numeric_limits<double>::infinity());
    return;
  }
  reached_[c0] = ring.fill(seed, grid.free_slices(c0));
  queue_.push_back(static_cast<std::uint32_t>(c0));
  const int nx = grid.nx(), ny = grid.ny();
  for (std::size_t head = 0; head < queue_.size(); ++head) {
    const std::size_t c = queue_[head];
    const int ix = static_cast<int>(c % nx), iy = static_cast<int>(c / nx);
    const std::uint64_t spread = ring.dilate(reached_[c]);
    for (int dy = -1; dy <= 1; ++dy) {
      const int y = iy + dy;
      if (y < 0 || y >= ny) continue;
      for (int dx = -1; dx <= 1; ++dx) {
        const int x = ix + dx;
        if (x < 0 || x >= nx || (dx == 0 && dy == 0)) continue;
        const std::size_t n = static_cast<std::size_t>(y) * nx + x;
        const std::uint64_t free = grid.free_slices(n);
        if (!(spread & free & ~reached_[n])) continue;
        const std::uint64_t grown = ring.fill(spread & free, free) & ~reached_[n];
        if (!grown) continue;
        reached_[n] |= grown;
        queue_.push_back(static_cast<std::uint32_t>(n));
      }
    }
  }
  reached_columns_ = static_cast<std::size_t>(
      std::count_if(reached_.begin(), reached_.end(), [](std::uint64_t m) { return m != 0; }));
  chamfer();
}

bool ReachableSet::contains(const Pose2& pose) const {
  if (!grid_) return false;
  const std::size_t cell = grid_->cell_of(pose);
  return (reached_[cell / grid_->slices()] >> (cell % grid_->slices())) & 1;
}

bool ReachableSet::column_reached(const Pose2& pose) const {
  return grid_ && reached_[grid_->column_of(pose)] != 0;
}

double ReachableSet::column_share() const {
  return reached_.empty() ? 0.0
                          : static_cast<double>(reached_columns_) /
                                static_cast<double>(reached_.size());
}

double ReachableSet::distance_to(const Pose2& pose) const {
  if (!grid_ || reached_columns_ == 0) return std::numeric_limits<double>::infinity();
  return distance_[grid_->column_of(pose)];
}

void ReachableSet::chamfer() {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const int nx = grid_->nx(), ny = grid_->ny();
  {
    // Two-pass 8-neighbour chamfer transform (Rosenfeld–Pfaltz, 1966).
    distance_.assign(reached_.size(), kInf);
    for (std::size_t c = 0; c < reached_.size(); ++c)
      if (reached_[c]) distance_[c] = 0.0;
    const double hx = grid_->hx(), hy = grid_->hy(), hd = std::hypot(hx, hy);
    auto relax = [&](int x, int y, int dx, int dy, double w) {
      const int u = x + dx, v = y + dy;
      if (u < 0 || u >= nx || v < 0 || v >= ny) return;
      double& d = distance_[static_cast<std::size_t>(y) * nx + x];
      d = std::min(d, distance_[static_cast<std::size_t>(v) * nx + u] + w);
    };
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        relax(x, y, -1, 0, hx), relax(x, y, 0, -1, hy);
        relax(x, y, -1, -1, hd), relax(x, y, 1, -1, hd);
      }
    for (int y = ny - 1; y >= 0; --y)
      for (int x = nx - 1; x >= 0; --x) {
        relax(x, y, 1, 0, hx), relax(x, y, 0, 1, hy);
        relax(x, y, 1, 1, hd), relax(x, y, -1, 1, hd);
      }
  }
}

}  // namespace hrs::geometry
