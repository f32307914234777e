// SPDX-License-Identifier: GPL-3.0-or-later
#include "api/progress.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <utility>

namespace hrs::api {

std::string format_clock(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
  return buf;
}

ProgressBar::ProgressBar(bool on, std::string name, long total)
    : on_(on), name_(std::move(name)), total_(total), t0_(std::chrono::steady_clock::now()) {}

void ProgressBar::show(long done, const std::string& text) const {
  if (!on_) return;
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  const double eta = done > 0 ? elapsed / static_cast<double>(done) * static_cast<double>(total_ - done) : 0.0;
  constexpr long kWidth = 30;
  const long filled = total_ > 0 ? kWidth * done / total_ : kWidth;
  std::string bar(static_cast<std::size_t>(std::max(0L, std::min(kWidth, filled))), '#');
  bar.resize(kWidth, '.');
  char line[320];
  std::snprintf(line, sizeof line, "\r\033[K%s [%s] %ld/%ld  %s  ETA %s  %s", name_.c_str(),
                bar.c_str(), done, total_, format_clock(elapsed).c_str(),
                done > 0 ? format_clock(eta).c_str() : "?", text.c_str());
  std::cerr << line << std::flush;
}

void ProgressBar::clear() const {
  if (on_) std::cerr << "\r\033[K" << std::flush;
}

}  // namespace hrs::api
