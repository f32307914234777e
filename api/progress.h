// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The one progress reporter of the front ends: a bar with the count done,
// the elapsed time and an ETA on stderr, redrawn in place. `hrspace design`
// shows the annealing's iterations with it, `hrspace experiment` a study's
// runs. It draws only when `on` (the callers pass isatty(stderr)).
#include <chrono>
#include <string>

namespace hrs::api {

//! "m:ss" of a duration in seconds (rounded).
std::string format_clock(double seconds);

class ProgressBar {
 public:
  ProgressBar(bool on, std::string name, long total);
  //! Redraws the line: "NAME [####....] done/total  m:ss  ETA m:ss  text".
  void show(long done, const std::string& text) const;
  //! Erases the line.
  void clear() const;

 private:
  bool on_;
  std::string name_;
  long total_;
  std::chrono::steady_clock::time_point t0_;
};

}  // namespace hrs::api
