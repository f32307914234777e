// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Aggregation of experiment runs: mean, sample standard deviation and count
// per group of runs, and ratios of group means against a reference group
// (e.g. baseline planning time / proposed planning time, per room).

#include <optional>
#include <string>
#include <vector>

#include "experiments/table.h"

namespace hrs::experiments {

struct Summary {
  double mean = 0.0;
  double sd = 0.0;  //!< sample standard deviation (n − 1); 0 when n < 2
  int n = 0;
};

//! Mean, sample sd and count of `values` (all finite; NaNs are skipped).
Summary summarize(const std::vector<double>& values);

//! One row per distinct combination of `group_by` cells (in order of first
//! appearance), with the group cells, `n`, and for each measure present in
//! the group `<measure>_mean` and `<measure>_sd` over the rows where it is a
//! number. Measures absent from every row of a group are left out.
Table summarize_table(const Table& rows, const std::vector<std::string>& group_by,
                      const std::vector<std::string>& measures);

//! Adds `<measure>_ratio_vs_<reference>` to every summary row: the mean of
//! the row whose `column` is `reference` and whose other `match` cells are
//! equal, divided by this row's mean (so a faster planner has a ratio > 1
//! for a time). Left out where there is no reference row or a zero mean.
void add_ratio(Table& summary, const std::string& column, const std::string& reference,
               const std::vector<std::string>& match, const std::string& measure);

}  // namespace hrs::experiments
