// RS-decomposition by adaptive sampling (paper §V-A); see decomposition.h.

#include "rs/decomposition.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <set>

namespace hrs::rs {
namespace {

double weight(const DecompositionOptions& o) {
  return o.heading_weight > 0.0 ? o.heading_weight : o.radius;
}

}  // namespace

Decomposition::Decomposition(const DecompositionOptions& options, std::mt19937_64& rng)
    : options_(options), tree_(weight(options)) {
  const Pose2 origin{};
  auto add = [&](const Pose2& p, int word) {
    samples_.push_back({p, word});
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
    const auto nn = tree_.nearest(p);
    if (nn >= 0 && samples_[nn].word == word) {
      ++agreeing;
    } else {
      agreeing = 0;
      add(p, word);
    }
  }
}

Pose2 Decomposition::uniform(std::mt19937_64& rng) const {
  // The empty room twice the size, centred on the start.
  std::uniform_real_distribution<double> x(-options_.room_width, options_.room_width);
  std::uniform_real_distribution<double> y(-options_.room_depth, options_.room_depth);
  std::uniform_real_distribution<double> t(-std::numbers::pi, std::numbers::pi);
  const double px = x(rng), py = y(rng);
  return {px, py, t(rng)};
}

Pose2 Decomposition::relative(const Pose2& from, const Pose2& to) const {
  const double c = std::cos(from.theta), s = std::sin(from.theta);
  const double dx = to.x - from.x, dy = to.y - from.y;
  return {c * dx + s * dy, -s * dx + c * dy, geometry::wrap_angle(to.theta - from.theta)};
}

int Decomposition::predict_word(const Pose2& from, const Pose2& to) const {
  return samples_[tree_.nearest(relative(from, to))].word;
}

std::optional<Path> Decomposition::predicted_path(const Pose2& from, const Pose2& to) const {
  return word_path(predict_word(from, to), from, to, options_.radius);
}

double Decomposition::predicted_length(const Pose2& from, const Pose2& to) const {
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
