// SPDX-License-Identifier: GPL-3.0-or-later
// RS-decomposition by adaptive sampling (paper §V-A); see decomposition.h.

#include "rs/decomposition.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>

#include "geometry/random.h"

namespace hrs::rs {
namespace {

double weight(const DecompositionOptions& o) {
  return o.heading_weight > 0.0 ? o.heading_weight : o.radius;
}

}  // namespace

//! The look-up grid: nx × ny × nt cells over [−W, W] × [−D, D] × [−π, π);
//! kUnknown until a cell's word is first asked for.
struct Decomposition::Grid {
  static constexpr std::uint8_t kUnknown = 0xff;
  int nx = 0, ny = 0, nt = 0;
  double cx = 0, cy = 0, ct = 0;  //!< cell sizes
  std::unique_ptr<std::atomic<std::uint8_t>[]> words;
};

Decomposition::~Decomposition() = default;
Decomposition::Decomposition(Decomposition&&) noexcept = default;
Decomposition& Decomposition::operator=(Decomposition&&) noexcept = default;

Decomposition::Decomposition(const DecompositionOptions& options, std::mt19937_64& rng)
    : options_(options),
      grid_index_(weight(options), -options.room_width, options.room_width, -options.room_depth,
                  options.room_depth),
      tree_(weight(options)) {
  static_assert(kWordCount < Grid::kUnknown, "a word id must fit a grid cell");
  const Pose2 origin{};
  auto add = [&](const Pose2& p, int word) {
    samples_.push_back({p, word});
    grid_index_.insert(p);
    tree_.insert(p);
  };
  for (int i = 0; i < options_.initial_samples; ++i) {
    const Pose2 p = uniform(rng);
    add(p, shortest_word(origin, p, options_.radius).word);
  }
  int agreeing = 0;
  while (agreeing < options_.stop_after && samples_.size() < options_.max_samples) {
    const Pose2 p = uniform(rng);
    ++drawn_;
    const int word = shortest_word(origin, p, options_.radius).word;
    const auto nn = grid_index_.nearest(p);  // p is in the box
    if (nn >= 0 && samples_[nn].word == word) {
      ++agreeing;
    } else {
      agreeing = 0;
      add(p, word);
    }
  }
  if (options_.grid_cell > 0.0 && options_.grid_angle > 0.0) {
    auto g = std::make_unique<Grid>();
    g->nx =
        std::max(1, static_cast<int>(std::ceil(2.0 * options_.room_width / options_.grid_cell)));
    g->ny =
        std::max(1, static_cast<int>(std::ceil(2.0 * options_.room_depth / options_.grid_cell)));
    g->nt = std::max(1, static_cast<int>(std::ceil(2.0 * std::numbers::pi / options_.grid_angle)));
    g->cx = 2.0 * options_.room_width / g->nx;
    g->cy = 2.0 * options_.room_depth / g->ny;
    g->ct = 2.0 * std::numbers::pi / g->nt;
    const std::size_t n = static_cast<std::size_t>(g->nx) * g->ny * g->nt;
    g->words = std::make_unique<std::atomic<std::uint8_t>[]>(n);
    for (std::size_t i = 0; i < n; ++i)
      g->words[i].store(Grid::kUnknown, std::memory_order_relaxed);
    grid_ = std::move(g);
  }
}

Pose2 Decomposition::uniform(std::mt19937_64& rng) const {
  // The empty room twice the size, centred on the start.
  // Uniform draws from the top bits of the engine (geometry/random.h): the
  // same numbers with every standard library.
  const double px = (2.0 * uniform01(rng) - 1.0) * options_.room_width;
  const double py = (2.0 * uniform01(rng) - 1.0) * options_.room_depth;
  const double pt = (2.0 * uniform01(rng) - 1.0) * std::numbers::pi;
  return {px, py, pt};
}

Pose2 Decomposition::relative(const Pose2& from, const Pose2& to) const {
  const double c = std::cos(from.theta), s = std::sin(from.theta);
  const double dx = to.x - from.x, dy = to.y - from.y;
  return {c * dx + s * dy, -s * dx + c * dy, geometry::wrap_angle(to.theta - from.theta)};
}

std::int32_t Decomposition::nearest_sample(const Pose2& q) const {
  return in_box(q) ? grid_index_.nearest(q) : tree_.nearest(q);
}

int Decomposition::nearest_word(const Pose2& from, const Pose2& to) const {
  return nearest_sample_word(relative(from, to));
}

int Decomposition::nearest_sample_word(const Pose2& q) const {
  return samples_[nearest_sample(q)].word;
}

bool Decomposition::in_box(const Pose2& q) const {
  return std::abs(q.x) <= options_.room_width && std::abs(q.y) <= options_.room_depth;
}

int Decomposition::predict_word(const Pose2& from, const Pose2& to) const {
  const Pose2 q = relative(from, to);
  if (!grid_) return nearest_sample_word(q);
  if (!in_box(q)) return shortest_word({}, q, options_.radius).word;
  const Grid& g = *grid_;
  const double fx = (q.x + options_.room_width) / g.cx;
  const double fy = (q.y + options_.room_depth) / g.cy;
  const double ft = (q.theta + std::numbers::pi) / g.ct;
  if (!(fx >= 0.0 && fx < g.nx && fy >= 0.0 && fy < g.ny))  // on the box's far edge (or NaN)
    return nearest_sample_word(q);
  const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
  const int it = std::clamp(static_cast<int>(ft), 0, g.nt - 1);
  const std::size_t cell = (static_cast<std::size_t>(it) * g.ny + iy) * g.nx + ix;
  std::uint8_t w = g.words[cell].load(std::memory_order_relaxed);
  if (w == Grid::kUnknown) {
    // Every thread that races here computes the same word.
    const Pose2 centre{-options_.room_width + (ix + 0.5) * g.cx,
                       -options_.room_depth + (iy + 0.5) * g.cy,
                       -std::numbers::pi + (it + 0.5) * g.ct};
    w = static_cast<std::uint8_t>(shortest_word({}, centre, options_.radius).word);
    g.words[cell].store(w, std::memory_order_relaxed);
  }
  return w;
}

std::optional<Path> Decomposition::predicted_path(const Pose2& from, const Pose2& to) const {
  if (grid_ && !in_box(relative(from, to))) return shortest_path(from, to, options_.radius);
  return word_path(predict_word(from, to), from, to, options_.radius);
}

double Decomposition::predicted_length(const Pose2& from, const Pose2& to) const {
  if (grid_ && !in_box(relative(from, to))) return shortest_length(from, to, options_.radius);
  return word_length(predict_word(from, to), from, to, options_.radius);
}

Path Decomposition::exact_path(const Pose2& from, const Pose2& to) const {
  return shortest_path(from, to, options_.radius);
}

int Decomposition::region_count() const {
  std::set<int> words;
  for (const auto& s : samples_) words.insert(s.word);
  return static_cast<int>(words.size());
}

DecompositionAccuracy Decomposition::evaluate(int queries, std::mt19937_64& rng) const {
  DecompositionAccuracy acc;
  const Pose2 origin{};
  int right = 0, infeasible = 0;
  double excess = 0.0, rel = 0.0;
  for (int i = 0; i < queries; ++i) {
    const Pose2 q = uniform(rng);
    const double exact = shortest_length(origin, q, options_.radius);
    const double pred = predicted_length(origin, q);
    if (pred <= exact + 1e-9 * (1.0 + exact)) {
      ++right;
    } else if (std::isinf(pred)) {
      ++infeasible;
    } else {
      ++acc.mispredicted_feasible;
      excess += pred - exact;
      rel += exact > 0.0 ? (pred - exact) / exact : 0.0;
    }
  }
  acc.queries = queries;
  if (queries > 0) {
    acc.word_accuracy = static_cast<double>(right) / queries;
    acc.infeasible_fraction = static_cast<double>(infeasible) / queries;
  }
  if (acc.mispredicted_feasible > 0) {
    acc.mean_excess = excess / acc.mispredicted_feasible;
    acc.mean_relative_excess = rel / acc.mispredicted_feasible;
  }
  return acc;
}

}  // namespace hrs::rs
