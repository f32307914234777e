// SPDX-License-Identifier: GPL-3.0-or-later
// The 48 words of Reeds and Shepp's sufficient family (Reeds & Shepp 1990,
// §8; paper §III-B): which candidate codes produce each word, their names,
// and the path of a candidate.

#include "rs/candidates.h"

namespace hrs::rs {
namespace detail {
namespace {

//! Nominal gear of each base parameter slot (the sign the formula enforces);
//! for 8.3 the last arc's gear is the sign of v.
std::string nominal_name(int code, bool v_negative) {
  // Use unit-magnitude stand-ins with the enforced signs.
  const int f = code & 7;
  double t = 1.0, u = -1.0, v = 1.0;
  if (f == kLSL || f == kLSR) u = 1.0;
  if (f == kLRL) v = v_negative ? -1.0 : 1.0;
  if (f == kLRLRa) u = 1.0, v = -1.0;
  if (f == kLRSL || f == kLRSR) v = -1.0;
  const Raw r = raw_segments(code, t, u, v);
  std::string name;
  for (int i = 0; i < r.n; ++i) {
    name += static_cast<char>(r.steer[i]);
    name += r.value[i] < 0.0 ? '-' : '+';
  }
  return name;
}

bool code_exists(int code) {
  const int f = code & 7;
  return !(code & kBackwards) || f == kLRL || f == kLRSL || f == kLRSR;
}

}  // namespace

WordTable::WordTable() {
  int count = 0;
  for (int code = 0; code < kCodeCount; ++code) {
    for (int neg = 0; neg < 2; ++neg) {
      id[code][neg] = -1;
      if (!code_exists(code)) continue;
      const std::string name = nominal_name(code, neg == 1);
      int found = -1;
      for (int w = 0; w < count; ++w)
        if (names[w] == name) found = w;
      if (found < 0) {
        assert(count < kWordCount);
        found = count;
        names[count++] = name;
      }
      id[code][neg] = found;
      const int vsign = (code & 7) == kLRL ? (neg ? -1 : 1) : 0;
      if ((code & 7) == kLRL || neg == 0) sources[found].push_back({code, vsign});
    }
  }
  assert(count == kWordCount);
}

const WordTable& table() {
  static const WordTable t;
  return t;
}

int word_of(int code, double v) { return table().id[code][v < 0.0 ? 1 : 0]; }

Path make_path(const Best& b, double radius) {
  Raw r = raw_segments(b.code, b.t, b.u, b.v);
  snapped_length(r);
  Path p;
  p.radius = radius;
  p.segments.reserve(r.n);
  for (int i = 0; i < r.n; ++i) {
    if (r.value[i] == 0.0) continue;
    p.segments.push_back({r.steer[i], r.value[i] < 0.0 ? -1 : 1, std::abs(r.value[i]) * radius});
  }
  return p;
}

}  // namespace detail

std::string_view word_name(int id) {
  assert(id >= 0 && id < kWordCount);
  return detail::table().names[id];
}

int word_id(std::string_view name) {
  for (int w = 0; w < kWordCount; ++w)
    if (detail::table().names[w] == name) return w;
  return -1;
}

}  // namespace hrs::rs
