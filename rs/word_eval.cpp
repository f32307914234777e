// SPDX-License-Identifier: GPL-3.0-or-later
// The plain single-word evaluator (Reeds & Shepp 1990, §8, eqs. 8.1–8.11;
// paper §III-B): a direct transcription of the formulas, one candidate at a
// time with no shared terms, behind word_length() and word_path(). It is
// written apart from the solver in rs/reeds_shepp.cpp so that the tests can
// check one against the other.

#include "rs/candidates.h"

namespace hrs::rs {
namespace {

using namespace detail;

// |(a, b)| without std::hypot's overflow scaling (unit-radius values, far
// from overflow).
inline double norm2(double a, double b) { return std::sqrt(a * a + b * b); }

//! Parameters (t, u, v) of candidate `code` for the normalised query; false
//! when the candidate's sign constraints fail. Direct transcription of
//! Reeds & Shepp eqs. 8.1–8.11 (no shared terms), as an independent check.
bool eval_candidate(int code, const Local& q, double& t, double& u, double& v) {
  double x = q.x, y = q.y, phi = q.phi;
  if (code & kBackwards) {
    const double xb = x * std::cos(phi) + y * std::sin(phi);
    const double yb = x * std::sin(phi) - y * std::cos(phi);
    x = xb, y = yb;
  }
  if (code & kTimeflip) x = -x, phi = -phi;
  if (code & kReflect) y = -y, phi = -phi;
  const double sp = std::sin(phi), cp = std::cos(phi);
  switch (code & 7) {
    case kLSL: {
      const double xi = x - sp, eta = y - 1.0 + cp;
      u = norm2(xi, eta);
      t = std::atan2(eta, xi);
      if (!nonneg(t)) return false;
      v = mod2pi(phi - t);
      return nonneg(v);
    }
    case kLSR: {
      const double xi = x + sp, eta = y - 1.0 + -cp;
      const double r2 = xi * xi + eta * eta;
      if (r2 < 4.0 - kTol) return false;
      u = std::sqrt(std::max(0.0, r2 - 4.0));
      t = mod2pi(std::atan2(eta, xi) + std::atan2(2.0, u));
      if (!nonneg(t)) return false;
      v = mod2pi(t - phi);
      return nonneg(v);
    }
    case kLRL: {
      const double xi = x - sp, eta = y - 1.0 + cp;
      const double r = norm2(xi, eta);
      if (r > 4.0 + kTol) return false;
      u = -2.0 * std::asin(std::min(1.0, 0.25 * r));
      t = mod2pi(std::atan2(eta, xi) + 0.5 * u + kPi);
      if (!nonneg(t)) return false;
      v = mod2pi(phi - t + u);
      return true;
    }
    case kLRLRa:
    case kLRLRb: {
      const double xi = x + sp, eta = y - 1.0 - cp;
      const double r = norm2(xi, eta);
      double w;  // the tauOmega "v" argument
      if ((code & 7) == kLRLRa) {
        const double rho = 0.25 * (2.0 + r);
        if (rho > 1.0 + kTol) return false;
        u = std::acos(std::min(1.0, rho));
        w = -u;
      } else {
        const double rho = (20.0 - r * r) / 16.0;
        if (rho < -kTol || rho > 1.0 + kTol) return false;
        u = -std::acos(std::clamp(rho, 0.0, 1.0));
        w = u;
      }
      const double delta = mod2pi(u - w);
      const double a = std::sin(u) - std::sin(delta);
      const double b = std::cos(u) - std::cos(delta) - 1.0;
      const double t1 = std::atan2(eta * a - xi * b, xi * a + eta * b);
      const double t2 = 2.0 * (std::cos(delta) - std::cos(w) - std::cos(u)) + 3.0;
      t = mod2pi(t2 < 0.0 ? t1 + kPi : t1);
      if (!nonneg(t)) return false;
      v = mod2pi(t - u + w - phi);
      return (code & 7) == kLRLRa ? nonpos(v) : nonneg(v);
    }
    case kLRSL: {
      const double xi = x - sp, eta = y - 1.0 + cp;
      const double rho = norm2(xi, eta);
      if (rho * rho < 8.0 - kTol) return false;
      const double r = std::sqrt(std::max(0.0, rho * rho - 4.0));
      u = 2.0 - r;
      if (!nonpos_len(u)) return false;
      t = mod2pi(std::atan2(eta, xi) + std::atan2(r, -2.0));
      if (!nonneg(t)) return false;
      v = mod2pi(phi - kHalfPi - t);
      return nonpos(v);
    }
    case kLRSR: {
      const double xi = x + sp, eta = y - 1.0 - cp;
      const double rho = norm2(xi, eta);
      if (rho < 2.0 - kTol) return false;
      t = std::atan2(xi, -eta);
      if (!nonneg(t)) return false;
      u = 2.0 - rho;
      if (!nonpos_len(u)) return false;
      v = mod2pi(t + kHalfPi - phi);
      return nonpos(v);
    }
    default: {
      const double xi = x + sp, eta = y - 1.0 - cp;
      const double rho = norm2(xi, eta);
      if (rho * rho < 20.0 - kTol) return false;
      u = 4.0 - std::sqrt(std::max(0.0, rho * rho - 4.0));
      if (!nonpos_len(u)) return false;
      t = mod2pi(std::atan2((4.0 - u) * xi - 2.0 * eta, -2.0 * xi + (u - 4.0) * eta));
      if (!nonneg(t)) return false;
      v = mod2pi(t - phi);
      return nonneg(v);
    }
  }
}

//! Shortest candidate of `word`: its length (unit radius) and parameters.
Best eval_word(int word, const Local& q) {
  Best best;
  if (word < 0 || word >= kWordCount) return best;
  for (const auto& [code, vsign] : table().sources[word]) {
    double t, u, v;
    if (!eval_candidate(code, q, t, u, v)) continue;
    if (vsign != 0 && (vsign < 0) != (v < 0.0)) continue;
    Raw r = raw_segments(code, t, u, v);
    best.offer(snapped_length(r), code, t, u, v);
  }
  return best;
}

}  // namespace

double word_length(int word, const Pose2& from, const Pose2& to, double radius) {
  return eval_word(word, detail::to_local(from, to, radius)).len * radius;
}

std::optional<Path> word_path(int word, const Pose2& from, const Pose2& to, double radius) {
  const detail::Best b = eval_word(word, detail::to_local(from, to, radius));
  if (!(b.len < detail::kInf)) return std::nullopt;
  return detail::make_path(b, radius);
}

}  // namespace hrs::rs
