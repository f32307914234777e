// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Internals shared by the Reeds–Shepp solver (rs/reeds_shepp.cpp), the
// word table (rs/words.cpp) and the plain single-word evaluator
// (rs/word_eval.cpp); not part of the module's interface. Formulas:
// Reeds & Shepp 1990, §8 (paper §III-B); see rs/reeds_shepp.cpp.
//
// A candidate is one of Reeds and Shepp's base formulas (8.1–8.11, each
// for an "L+" first arc) with a code of symmetry bits: time-flip, reflection
// and backwards. Its parameters (t, u, v) are in units of the turning
// radius, for the query normalised to start at the origin heading +x.

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "rs/reeds_shepp.h"

namespace hrs::rs::detail {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;
inline constexpr double kHalfPi = 0.5 * std::numbers::pi;
inline constexpr double kInf = std::numeric_limits<double>::infinity();
//! Rounding tolerance on path parameters, in units of the turning radius.
inline constexpr double kTol = 1e-11;

//! Wraps to [-π, π]; inputs here are sums of a few angles (|a| < 8π).
inline double mod2pi(double a) {
  while (a > kPi) a -= kTwoPi;
  while (a < -kPi) a += kTwoPi;
  return a;
}

//! Makes an arc angle that must be >= 0 valid: snaps rounding noise to 0 and
//! reads -π as +π. False when the angle is genuinely negative.
inline bool nonneg(double& a) {
  if (a >= 0.0) return true;
  if (a >= -kTol) {
    a = 0.0;
    return true;
  }
  if (a <= -kPi + kTol) {
    a += kTwoPi;
    return true;
  }
  return false;
}
//! Non-angular parameter (straight length) that must be <= 0.
inline bool nonpos_len(double& a) {
  if (a <= 0.0) return true;
  if (a <= kTol) {
    a = 0.0;
    return true;
  }
  return false;
}
//! Mirror of nonneg() for arc angles that must be <= 0 (reads +π as −π).
inline bool nonpos(double& a) {
  if (nonpos_len(a)) return true;
  if (a >= kPi - kTol) {
    a -= kTwoPi;
    return true;
  }
  return false;
}

// ---- Candidates and words ---------------------------------------------------

//! The base formulas of Reeds & Shepp §8 (each for the "L+" first arc).
enum Formula : int {
  kLSL = 0,    //!< 8.1  L+S+L+
  kLSR = 1,    //!< 8.2  L+S+R+
  kLRL = 2,    //!< 8.3  L+R-L± (C|C|C, C|CC)
  kLRLRa = 3,  //!< 8.7  L+R+L-R- (CCu|CuC)
  kLRLRb = 4,  //!< 8.8  L+R-L-R+ (C|CuCu|C)
  kLRSL = 5,   //!< 8.9  L+R-(π/2)S-L-
  kLRSR = 6,   //!< 8.10 L+R-(π/2)S-R-
  kLRSLR = 7,  //!< 8.11 L+R-(π/2)S-L-(π/2)R+
};
inline constexpr int kTimeflip = 8;
inline constexpr int kReflect = 16;
inline constexpr int kBackwards = 32;
inline constexpr int kCodeCount = 64;

//! Segment values (signed, unit radius) and steering of one candidate.
struct Raw {
  std::array<double, 5> value{};
  std::array<Steer, 5> steer{};
  int n = 0;
};

//! Builds the segments of candidate `code` with parameters (t, u, v).
inline Raw raw_segments(int code, double t, double u, double v) {
  constexpr Steer L = Steer::kLeft, R = Steer::kRight, S = Steer::kStraight;
  Raw r;
  auto put = [&r](Steer s, double x) {
    r.steer[r.n] = s;
    r.value[r.n] = x;
    ++r.n;
  };
  switch (code & 7) {
    case kLSL:
      put(L, t), put(S, u), put(L, v);
      break;
    case kLSR:
      put(L, t), put(S, u), put(R, v);
      break;
    case kLRL:
      put(L, t), put(R, u), put(L, v);
      break;
    case kLRLRa:
      put(L, t), put(R, u), put(L, -u), put(R, v);
      break;
    case kLRLRb:
      put(L, t), put(R, u), put(L, u), put(R, v);
      break;
    case kLRSL:
      put(L, t), put(R, -kHalfPi), put(S, u), put(L, v);
      break;
    case kLRSR:
      put(L, t), put(R, -kHalfPi), put(S, u), put(R, v);
      break;
    default:
      put(L, t), put(R, -kHalfPi), put(S, u), put(L, -kHalfPi), put(R, v);
      break;
  }
  if (code & kTimeflip)
    for (int i = 0; i < r.n; ++i) r.value[i] = -r.value[i];
  if (code & kReflect)
    for (int i = 0; i < r.n; ++i)
      if (r.steer[i] != S) r.steer[i] = r.steer[i] == L ? R : L;
  if (code & kBackwards) {
    std::reverse(r.value.begin(), r.value.begin() + r.n);
    std::reverse(r.steer.begin(), r.steer.begin() + r.n);
  }
  return r;
}


//! The 48 words: names, the word of each candidate code, and the codes
//! that produce each word (rs/words.cpp).
struct WordTable {
  std::array<std::string, kWordCount> names;
  //! word id of [code][v < 0]; -1 for codes that do not exist.
  std::array<std::array<int, 2>, kCodeCount> id{};
  //! candidate codes (and required sign of v, 0 = any) producing each word.
  std::array<std::vector<std::pair<int, int>>, kWordCount> sources;

  WordTable();
};
const WordTable& table();

//! Word of candidate `code` with base parameter v (only 8.3 depends on it;
//! v is the formula's value, before the time-flip negates the segments).
int word_of(int code, double v);

// ---- Normalisation ----------------------------------------------------------

//! The goal seen from the start, scaled to unit radius.
struct Local {
  double x = 0.0, y = 0.0, phi = 0.0;
};

inline Local to_local(const Pose2& from, const Pose2& to, double radius) {
  assert(radius > 0.0);
  const double c = std::cos(from.theta), s = std::sin(from.theta);
  const double dx = to.x - from.x, dy = to.y - from.y;
  const double inv = 1.0 / radius;
  return {(c * dx + s * dy) * inv, (-s * dx + c * dy) * inv,
          geometry::wrap_angle(to.theta - from.theta)};
}

//! Snaps rounding noise to zero and sums the magnitudes.
inline double snapped_length(Raw& r) {
  double len = 0.0;
  for (int i = 0; i < r.n; ++i) {
    if (std::abs(r.value[i]) <= kTol) r.value[i] = 0.0;
    len += std::abs(r.value[i]);
  }
  return len;
}

//! The shortest candidate found so far (or of one word): length (unit
//! radius), code and parameters.
struct Best {
  double len = kInf;
  int code = 0;
  double t = 0.0, u = 0.0, v = 0.0;
  void offer(double l, int c, double tt, double uu, double vv) {
    if (l < len) len = l, code = c, t = tt, u = uu, v = vv;
  }
};

//! The path of candidate `b` for turning radius `radius` (zero-length
//! segments dropped).
Path make_path(const Best& b, double radius);

//! The length of candidate `b` after snapping (unit radius).
inline double final_length(const Best& b) {
  Raw r = raw_segments(b.code, b.t, b.u, b.v);
  return snapped_length(r);
}

}  // namespace hrs::rs::detail
