// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The RS-decomposition (paper §V-A): the configuration space around a start
// pose, partitioned approximately by the word of the shortest Reeds–Shepp
// path. Built by adaptive sampling: K uniform samples in an empty room twice
// the room's size (start at its centre, heading +x), then more uniform
// samples, each kept only when its nearest existing sample (kd-tree) has a
// different shortest word, until `stop_after` consecutive samples agree.
// A query is answered by the word of the nearest sample (the paper's mode:
// one word evaluated instead of 48) or exactly (all words). The prediction
// is an approximation: evaluate() measures how often it is right and what it
// costs when it is not.
//
// Look-up grid (our departure from the paper's kd-tree look-up): a
// nearest-sample search costs microseconds, more than solving all 48 words
// once, so predictions go through a grid over the sampled box (cells of
// `grid_cell` metres × `grid_angle` radians). A cell holds the shortest word
// at its centre, solved on first use; later queries in the cell cost one
// array read. It is the same partition by words, sampled on a regular grid
// instead of adaptively: evaluate() measures its accuracy. Queries outside
// the box use the nearest adaptive sample. Filling is thread-safe and
// deterministic (a cell's word depends only on the cell).
//
// Outside the sampled box (goals farther from the start than the doubled
// room reaches along the start's axes, which a rotated start produces) the
// grid has no cells and a nearest-sample search there costs about 2.5 µs,
// several exact queries. So with the grid on, such queries are answered
// exactly: predict_word() gives the shortest word and predicted_length()/
// predicted_path() the shortest path. With the grid off (the paper's
// look-up, `grid_cell <= 0`) every query goes to the nearest sample.

#include <cstdint>
#include <memory>
#include <optional>
#include <random>
#include <vector>

#include "rs/kd_tree.h"
#include "rs/pose_grid.h"
#include "rs/reeds_shepp.h"

namespace hrs::rs {

//! Parameters of the decomposition (defaults are the paper's).
struct DecompositionOptions {
  double radius = 1.0;                  //!< turning radius, metres
  double room_width = 4.0;              //!< room extent along x, metres (sampled: 2x)
  double room_depth = 4.0;              //!< room extent along y, metres (sampled: 2x)
  int initial_samples = 1000;           //!< K, uniform samples before refinement
  int stop_after = 100;                 //!< consecutive agreeing samples that end refinement
  std::size_t max_samples = 1'000'000;  //!< safety cap on kept samples
  //! Heading weight of the nearest-neighbour metric, metres per radian;
  //! <= 0 means the turning radius (an arc of angle a has length r·a).
  double heading_weight = 0.0;
  //! Look-up grid cell: metres along x and y, radians along θ; either <= 0
  //! turns the grid off (every query searches the nearest sample).
  double grid_cell = 0.05;
  double grid_angle = 0.0872664625997164788;  //!< 5°
};

//! One kept sample: a goal pose relative to the start and its shortest word.
struct DecompositionSample {
  Pose2 pose;    //!< in the start's frame (start at the origin, heading +x)
  int word = 0;  //!< id of the shortest word, see word_name()
};

//! How well the prediction does on random queries.
struct DecompositionAccuracy {
  int queries = 0;
  double word_accuracy = 0.0;         //!< fraction where the predicted word is a shortest one
  double infeasible_fraction = 0.0;   //!< fraction where the predicted word cannot connect
  double mean_excess = 0.0;           //!< metres, mean over feasible mispredictions
  double mean_relative_excess = 0.0;  //!< mean (predicted - exact) / exact, same queries
  int mispredicted_feasible = 0;      //!< queries counted in the means
};

class Decomposition {
 public:
  //! Builds the decomposition with randomness from `rng` (deterministic for a
  //! given seed and options).
  Decomposition(const DecompositionOptions& options, std::mt19937_64& rng);
  ~Decomposition();
  Decomposition(Decomposition&&) noexcept;
  Decomposition& operator=(Decomposition&&) noexcept;

  //! Word predicted for the goal `to` seen from `from`: through the grid
  //! when it is on (the exact word outside the sampled box), else the
  //! nearest sample's.
  int predict_word(const Pose2& from, const Pose2& to) const;
  //! Word of the sample nearest to the relative pose of `to` (no grid).
  int nearest_word(const Pose2& from, const Pose2& to) const;
  //! Paper mode: the path of the predicted word, or nullopt when that word
  //! cannot connect the poses.
  std::optional<Path> predicted_path(const Pose2& from, const Pose2& to) const;
  //! Length of predicted_path(), +infinity when it does not exist (no allocation).
  double predicted_length(const Pose2& from, const Pose2& to) const;
  //! Exact mode: the shortest path over all 48 words.
  Path exact_path(const Pose2& from, const Pose2& to) const;

  //! Queries with start at the origin and goals uniform in the sampled box.
  DecompositionAccuracy evaluate(int queries, std::mt19937_64& rng) const;

  const DecompositionOptions& options() const { return options_; }
  const std::vector<DecompositionSample>& samples() const { return samples_; }
  //! Number of distinct words among the samples.
  int region_count() const;
  //! Uniform samples drawn while refining (kept or not).
  std::size_t drawn() const { return drawn_; }

 private:
  Pose2 relative(const Pose2& from, const Pose2& to) const;
  //! Whether the relative pose `q` lies in the sampled box.
  bool in_box(const Pose2& q) const;
  //! Word of the sample nearest to the relative pose `q`.
  int nearest_sample_word(const Pose2& q) const;
  Pose2 uniform(std::mt19937_64& rng) const;
  struct Grid;

  //! Index of the sample nearest to `q` (relative pose).
  std::int32_t nearest_sample(const Pose2& q) const;

  DecompositionOptions options_;
  //! The samples twice: a bucket grid over the sampled box (queries inside
  //! it: every query of the build, most look-ups) and a kd-tree (queries
  //! outside it, where rings of cells would have to grow to the box).
  PoseGrid grid_index_;
  PoseKdTree tree_;
  std::vector<DecompositionSample> samples_;
  std::size_t drawn_ = 0;
  std::unique_ptr<Grid> grid_;  //!< null when off
};

}  // namespace hrs::rs
