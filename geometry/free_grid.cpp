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
  double xmin = room[0].x, xmax = room[0].x, ymin = room[0].y, ymax = room[0].y;
  for (const Vec2& v : room) {
    xmin = std::min(xmin, v.x), xmax = std::max(xmax, v.x);
    ymin = std::min(ymin, v.y), ymax = std::max(ymax, v.y);
  }
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
      c = static_cast<std::uint16_t>(c + delta);
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
