// SPDX-License-Identifier: GPL-3.0-or-later
// Reeds–Shepp shortest paths (paper §III-B, §V-A).
//
// Formulas: J. A. Reeds and L. A. Shepp, "Optimal paths for a car that goes
// both forwards and backwards", Pacific J. Math. 145(2), 1990, §8, eqs.
// 8.1–8.11 (with the corrections of 8.3/8.4 and 8.11 noted in OMPL's
// ReedsSheppStateSpace by M. Moll, and the presentation in S. M. LaValle,
// "Planning Algorithms", 2006, §15.3.2). Written from those equations; the
// structure here differs from OMPL's:
//  * The query is normalised once (start at the origin heading +x, unit
//    radius). Every formula reads one of two points, A = (x - sin φ,
//    y - 1 + cos φ) or B = (x + sin φ, y - 1 - cos φ); the time-flipped query
//    (-x, y, -φ) sees (-A.x, A.y) and (-B.x, B.y), so one sqrt and one atan2
//    serve both (the angle becomes π - θ). Angles that depend only on |A| or
//    |B| (atan2(2, u), asin, acos, the tauOmega rotation) are shared likewise.
//  * Each (formula, symmetry pair) has a lower bound from |A| or |B| alone and
//    the heading change; it is skipped when the bound is not below the best
//    length so far, before any atan2/asin/acos is evaluated.
//  * Sign constraints accept rounding noise (|value| <= kTol is snapped to
//    zero, an angle of -π counts as +π), where OMPL rejects values below
//    -10 ε; this finds the true minimum at family boundaries.
// The word table: rs/words.cpp. word_length()/word_path() evaluate single
// words by a separate, direct transcription of the formulas
// (rs/word_eval.cpp), which the tests use as an independent check. Driving,
// sampling and joining paths: rs/path.cpp.

#include "rs/reeds_shepp.h"

#include "rs/candidates.h"

namespace hrs::rs {
namespace {

using namespace detail;

// ---- The fast solver --------------------------------------------------------

//! A direction in the plane standing for the angle atan2(y, x): a path
//! parameter of a candidate known before any atan2 is evaluated. Products add
//! angles and conjugates negate them, so a candidate's arcs t and v are
//! directions built from A or B, the heading and rotations whose sine and
//! cosine are algebraic (Reeds & Shepp's formulas add atan2(2, u),
//! atan2(r, −2), π/2 or u/2 + π to θ_A or θ_B).
struct Dir {
  double x, y;
};
inline Dir mul(Dir a, Dir b) { return {a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x}; }
inline Dir conj(Dir a) { return {a.x, -a.y}; }

//! Slack of the pre-checks: a sine (relative to the direction's L1 norm,
//! which is at least its length) or a length in units of the radius. The
//! directions agree with the angles the exact evaluation computes to about
//! 1e-8 (a cosine taken as sqrt(1 - sin²) near sin = 1 loses half the
//! digits), so a slack of 1e-6, far above that and above kTol, rejects only
//! candidates that the exact evaluation would reject too or would not
//! offer as shorter.
constexpr double kSlack = 1e-6;
//! False only when the angle of d lies in (−π + 1e-6, −1e-6): an arc that
//! nonneg() rejects after mod2pi.
inline bool may_nonneg(Dir d) { return d.y >= -kSlack * (std::abs(d.x) + std::abs(d.y)); }
//! The mirror of may_nonneg() for nonpos().
inline bool may_nonpos(Dir d) { return d.y <= kSlack * (std::abs(d.x) + std::abs(d.y)); }
//! A lower bound of |angle of d| (in [0, π]) given inv = 1 / |d| (0 for
//! d = 0): |θ| >= |sin θ| when cos θ >= 0; otherwise |θ| = π/2 + β with
//! β >= sin β = −cos θ. The families know |d| from |A| or |B| and the
//! norms of their rotations, so no square root is taken per candidate.
inline double angle_floor(Dir d, double inv) {
  return d.x >= 0.0 ? std::abs(d.y) * inv : kHalfPi - d.x * inv;
}
//! 1 / n, or 0 for n = 0 (whose angle_floor() is then 0).
inline double inverse(double n) { return n > 0.0 ? 1.0 / n : 0.0; }

//! One query (X, Y, Φ) with its time-flip (-X, Y, -Φ), and the quantities
//! the formula families share: A = (X - sin Φ, Y - 1 + cos Φ) and
//! B = (X + sin Φ, Y - 1 - cos Φ), their norms, and their angles computed at
//! most once (atan2 is the costly part). `flags` adds kReflect/kBackwards to
//! the codes; `hb` = |Φ| is a lower bound on the total arc length.
struct PairQuery {
  PairQuery(double X, double Y, double phi, double S, double C, double omc, double opc, int flags,
            double hb)
      : flags(flags),
        hb(hb),
        ax(X - S),
        ay(Y - omc),
        bx(X + S),
        by(Y - opc),
        ra2(ax * ax + ay * ay),
        rb2(bx * bx + by * by),
        // |B|² - 4 expanded (S² + opc² = 2 opc) so that it has no
        // cancellation against 4 for nearby queries, where LSR's straight
        // part is tiny.
        rb2m4(X * X + 2.0 * X * S + Y * Y - 2.0 * Y * opc - 2.0 * omc),
        ra(std::sqrt(ra2)),
        rb(std::sqrt(rb2)),
        sphi(S),
        cphi(C),
        phis{phi, -phi} {}
  double angle_a() {
    if (!have_a) theta_a = std::atan2(ay, ax), have_a = true;
    return theta_a;
  }
  double angle_b() {
    if (!have_b) theta_b = std::atan2(by, bx), have_b = true;
    return theta_b;
  }
  //! θ_A of the query (m = 0) or π − θ_A of its time-flip (m = 1), as an
  //! angle and as a direction.
  double theta_a_of(int m) { return m ? kPi - angle_a() : angle_a(); }
  double theta_b_of(int m) { return m ? kPi - angle_b() : angle_b(); }
  Dir dir_a(int m) const { return {m ? -ax : ax, ay}; }
  Dir dir_b(int m) const { return {m ? -bx : bx, by}; }
  //! The direction of −Φ (m = 0) or +Φ (m = 1): subtracts the heading.
  Dir minus_heading(int m) const { return {cphi, m ? sphi : -sphi}; }
  //! The code of a word of this query: base word, flags, time-flip of m = 1.
  int code(int word, int m) const { return word | flags | (m ? kTimeflip : 0); }

  int flags;
  double hb;
  double ax, ay, bx, by, ra2, rb2, rb2m4, ra, rb;
  double sphi, cphi;  //!< sin Φ, cos Φ (pre-checks only)
  double phis[2];     //!< Φ of the query and of its time-flip
  double theta_a = 0.0, theta_b = 0.0;
  bool have_a = false, have_b = false;
};

//! Whether a candidate whose length is at least `floor` may be shorter than
//! the best so far (always, in the unpruned reference solver).
inline bool may_beat(double floor, const Best& best) { return floor - kSlack < best.len; }
//! Whether a family whose candidates are at least `floor` long is evaluated.
template <int kMode>
inline bool family_open(double floor, const Best& best) {
  return kMode < 1 || floor < best.len;
}

// The formula families of Reeds and Shepp (1990), numbered as in their
// §8; each offers the query's and its time-flip's solutions to `best`.
// kMode >= 1 (Pruning::kFamilyBounds): a family is skipped when a bound from
// |A| or |B| and the heading change is not below the best length.
// kMode >= 2 (Pruning::kFull): each of its two candidates is also skipped
// when the directions of its arcs t and v break their sign constraints or
// bound its length above the best by more than kSlack; only the survivors
// evaluate atan2, asin and acos. These pre-checks skip only candidates that
// best.offer() would not take, so modes 1 and 2 agree bit for bit. Mode 1
// differs from mode 0 only among words whose lengths tie within rounding.

//! 8.1 L+S+L+: A = u (cos t, sin t), v = φ - t.
template <int kMode>
inline void csc_lsl(PairQuery& q, Best& best) {
  if (!family_open<kMode>(q.ra + q.hb, best)) return;
  for (int m = 0; m < 2; ++m) {
    if constexpr (kMode >= 2) {
      const Dir dt = q.dir_a(m), dv = conj(mul(dt, q.minus_heading(m)));
      if (!may_nonneg(dt) || !may_nonneg(dv)) continue;
      const double inv = inverse(q.ra);  // |dt| = |dv| = |A|
      if (!may_beat(angle_floor(dt, inv) + q.ra + angle_floor(dv, inv), best)) continue;
    }
    double t = mod2pi(q.theta_a_of(m));
    if (!nonneg(t)) continue;
    double v = mod2pi(q.phis[m] - t);
    if (!nonneg(v)) continue;
    best.offer(t + q.ra + v, q.code(kLSL, m), t, q.ra, v);
  }
}

//! 8.2 L+S+R+: |B|² = u² + 4, t = θ_B + atan2(2, u), v = t - φ.
template <int kMode>
inline void csc_lsr(PairQuery& q, Best& best) {
  if (!(q.rb2m4 >= -kTol)) return;
  const double u = std::sqrt(std::max(0.0, q.rb2m4));
  if (!family_open<kMode>(u + q.hb, best)) return;
  double alpha = kInf;
  for (int m = 0; m < 2; ++m) {
    if constexpr (kMode >= 2) {
      const Dir dt = mul(q.dir_b(m), {u, 2.0}), dv = mul(dt, q.minus_heading(m));
      if (!may_nonneg(dt) || !may_nonneg(dv)) continue;
      const double inv = inverse(q.rb2);  // |(u, 2)| = |B|
      if (!may_beat(angle_floor(dt, inv) + u + angle_floor(dv, inv), best)) continue;
    }
    if (alpha == kInf) alpha = std::atan2(2.0, u);
    double t = mod2pi(q.theta_b_of(m) + alpha);
    if (!nonneg(t)) continue;
    double v = mod2pi(t - q.phis[m]);
    if (!nonneg(v)) continue;
    best.offer(t + u + v, q.code(kLSR, m), t, u, v);
  }
}

//! 8.3 L+R-L±: |A| = 4 sin(-u/2), t = θ_A + u/2 + π, v = φ - t + u.
//! Lower bound |u| = 2 asin(|A|/4) >= |A|/2.
template <int kMode>
inline void ccc_lrl(PairQuery& q, Best& best) {
  if (!(q.ra <= 4.0 + kTol)) return;
  if (!family_open<kMode>(std::max(0.5 * q.ra, q.hb), best)) return;
  const double h = std::min(1.0, 0.25 * q.ra);  // sin(-u/2)
  // u/2 + π as a direction, and u; asin(h) >= h bounds |u| until u is needed.
  const double k = std::sqrt(std::max(0.0, 1.0 - h * h));
  const Dir half{-k, h}, whole{1.0 - 2.0 * h * h, -2.0 * h * k};
  const double inv = inverse(q.ra);
  double u = kInf;
  for (int m = 0; m < 2; ++m) {
    if constexpr (kMode >= 2) {
      const Dir dt = mul(q.dir_a(m), half), dv = mul(conj(mul(dt, q.minus_heading(m))), whole);
      if (!may_nonneg(dt) ||
          !may_beat(angle_floor(dt, inv) + 2.0 * h + angle_floor(dv, inv), best))
        continue;
    }
    if (u == kInf) {
      u = -2.0 * std::asin(h);
      if (!family_open<kMode>(std::max(-u, q.hb), best)) return;
    }
    double t = mod2pi(q.theta_a_of(m) + 0.5 * u + kPi);
    if (!nonneg(t)) continue;
    const double v = mod2pi(q.phis[m] - t + u);
    best.offer(t - u + std::abs(v), q.code(kLRL, m), t, u, v);
  }
}

//! 8.7 L+R+L-R-: ρ = (2 + |B|)/4 = cos u; tauOmega with v = -u, where
//! atan2(ηA' - ξB', ξA' + ηB') = θ_B + atan2(-B', A').
template <int kMode>
inline void cccc_lrlr_a(PairQuery& q, Best& best) {
  const double rho7 = 0.25 * (2.0 + q.rb);
  if (!(rho7 <= 1.0 + kTol)) return;
  if (!family_open<kMode>(std::max(2.0 * std::sqrt(2.0 * std::max(0.0, 1.0 - rho7)), q.hb), best))
    return;
  // The pre-checks' rotations from cos u = ρ alone (u in [0, π/3], as ρ >= 1/2);
  // acos and the exact sines and cosines wait for a surviving candidate.
  const double c1 = std::min(1.0, rho7), s1 = std::sqrt(std::max(0.0, 1.0 - c1 * c1));
  const double c2 = 2.0 * c1 * c1 - 1.0, s2 = 2.0 * s1 * c1;
  const double pa = s1 - s2, pb = c1 - c2 - 1.0;
  // The flip term 2 (cos 2u - 2 cos u) + 3 = (2 cos u - 1)² is >= 0; only
  // rounding makes it negative, near cos u = 1/2, where the pre-check is off.
  const double flip_term = 2.0 * (c2 - 2.0 * c1) + 3.0;
  const bool sure = flip_term > 1e-9;
  const Dir turn{pa, -pb};
  const double inv = inverse(q.rb * std::sqrt(pa * pa + pb * pb));
  const double u_floor = 2.0 * std::sqrt(2.0 * std::max(0.0, 1.0 - rho7));  // <= 2u
  double u = kInf, rot = 0.0, flip = 0.0;
  for (int m = 0; m < 2; ++m) {
    if constexpr (kMode >= 2) {
      const Dir dt = mul(q.dir_b(m), turn);
      const Dir dv = mul(mul(dt, {c2, -s2}), q.minus_heading(m));
      if (sure && (!may_nonneg(dt) || !may_nonpos(dv) ||
                   !may_beat(angle_floor(dt, inv) + u_floor + angle_floor(dv, inv), best)))
        continue;
    }
    if (u == kInf) {
      u = std::acos(std::min(1.0, rho7));
      if (!family_open<kMode>(std::max(2.0 * u, q.hb), best)) return;
      const double delta = mod2pi(2.0 * u);
      const double su = std::sin(u), cu = std::cos(u);
      const double sd = std::sin(delta), cd = std::cos(delta);
      const double a_ = su - sd, b_ = cu - cd - 1.0;
      rot = std::atan2(-b_, a_);
      flip = 2.0 * (cd - 2.0 * cu) + 3.0 < 0.0 ? kPi : 0.0;
    }
    double t = mod2pi(q.theta_b_of(m) + rot + flip);
    if (!nonneg(t)) continue;
    double v = mod2pi(t - 2.0 * u - q.phis[m]);
    if (!nonpos(v)) continue;
    best.offer(t + 2.0 * u - v, q.code(kLRLRa, m), t, u, v);
  }
}

//! 8.8 L+R-L-R+: ρ = (20 - |B|²)/16 = cos u, u in [-π/2, 0]; tauOmega with
//! v = u (δ = 0, so the flip term 5 - 4 cos u is always positive).
template <int kMode>
inline void cccc_lrlr_b(PairQuery& q, Best& best) {
  const double rho8 = (16.0 - q.rb2m4) / 16.0;
  if (!(rho8 >= -kTol && rho8 <= 1.0 + kTol)) return;
  if (!family_open<kMode>(std::max(2.0 * std::sqrt(2.0 * std::max(0.0, 1.0 - rho8)), q.hb), best))
    return;
  const double cu = std::clamp(rho8, 0.0, 1.0);
  const Dir turn{-std::sqrt(std::max(0.0, 1.0 - cu * cu)), 2.0 - cu};  // (sin u, 2 - cos u)
  const double inv = inverse(q.rb * std::sqrt(5.0 - 4.0 * cu));
  const double u_floor = 2.0 * std::sqrt(2.0 * (1.0 - cu));  // <= -2u
  double u = kInf, rot = 0.0;
  for (int m = 0; m < 2; ++m) {
    if constexpr (kMode >= 2) {
      const Dir dt = mul(q.dir_b(m), turn), dv = mul(dt, q.minus_heading(m));
      if (!may_nonneg(dt) || !may_nonneg(dv) ||
          !may_beat(angle_floor(dt, inv) + u_floor + angle_floor(dv, inv), best))
        continue;
    }
    if (u == kInf) {
      u = -std::acos(cu);
      if (!family_open<kMode>(std::max(-2.0 * u, q.hb), best)) return;
      rot = std::atan2(2.0 - std::cos(u), std::sin(u));
    }
    double t = mod2pi(q.theta_b_of(m) + rot);
    if (!nonneg(t)) continue;
    double v = mod2pi(t - q.phis[m]);
    if (!nonneg(v)) continue;
    best.offer(t - 2.0 * u + v, q.code(kLRLRb, m), t, u, v);
  }
}

//! 8.9 L+R-(π/2)S-L-: |A|² = 4 + (2 - u)², t = θ_A + atan2(r, -2),
//! v = φ - π/2 - t. Needs u <= 0, i.e. r >= 2.
template <int kMode>
inline void ccsc_lrsl(PairQuery& q, Best& best, double hb_half) {
  if (!(q.ra2 >= 8.0 - kTol)) return;
  const double r = std::sqrt(q.ra2 - 4.0);
  double u = 2.0 - r;
  if (!nonpos_len(u)) return;
  if (!family_open<kMode>(-u + hb_half, best)) return;
  double alpha = kInf;
  for (int m = 0; m < 2; ++m) {
    if constexpr (kMode >= 2) {
      const Dir dt = mul(q.dir_a(m), {-2.0, r});
      // φ − π/2 − t: the conjugate of (t + π/2 − φ).
      const Dir dv = conj(mul(mul(dt, {0.0, 1.0}), q.minus_heading(m)));
      if (!may_nonneg(dt) || !may_nonpos(dv)) continue;
      const double inv = inverse(q.ra2);  // |(-2, r)| = |A|
      if (!may_beat(angle_floor(dt, inv) + kHalfPi - u + angle_floor(dv, inv), best))
        continue;
    }
    if (alpha == kInf) alpha = std::atan2(r, -2.0);
    double t = mod2pi(q.theta_a_of(m) + alpha);
    if (!nonneg(t)) continue;
    double v = mod2pi(q.phis[m] - kHalfPi - t);
    if (!nonpos(v)) continue;
    best.offer(t + kHalfPi - u - v, q.code(kLRSL, m), t, u, v);
  }
}

//! 8.10 L+R-(π/2)S-R-: (-η, ξ) = |B| (cos t, sin t), u = 2 - |B|,
//! v = t + π/2 - φ.
template <int kMode>
inline void ccsc_lrsr(PairQuery& q, Best& best, double hb_half) {
  if (!(q.rb >= 2.0 - kTol)) return;
  double u = 2.0 - q.rb;
  if (!nonpos_len(u)) return;
  if (!family_open<kMode>(-u + hb_half, best)) return;
  for (int m = 0; m < 2; ++m) {
    if constexpr (kMode >= 2) {
      const Dir dt = mul(q.dir_b(m), {0.0, 1.0});
      const Dir dv = mul(mul(dt, {0.0, 1.0}), q.minus_heading(m));
      if (!may_nonneg(dt) || !may_nonpos(dv)) continue;
      const double inv = inverse(q.rb);
      if (!may_beat(angle_floor(dt, inv) + kHalfPi - u + angle_floor(dv, inv), best))
        continue;
    }
    double t = mod2pi(q.theta_b_of(m) + kHalfPi);
    if (!nonneg(t)) continue;
    double v = mod2pi(t + kHalfPi - q.phis[m]);
    if (!nonpos(v)) continue;
    best.offer(t + kHalfPi - u - v, q.code(kLRSR, m), t, u, v);
  }
}

//! 8.11 L+R-(π/2)S-L-(π/2)R+: |B|² = 4 + (4 - u)², t = θ_B + atan2(4 - u, -2),
//! v = t - φ. Needs u <= 0, i.e. |B|² >= 20.
template <int kMode>
inline void ccscc_lrslr(PairQuery& q, Best& best) {
  if (!(q.rb2m4 >= 16.0 - kTol)) return;
  const double r = std::sqrt(q.rb2m4);
  double u = 4.0 - r;
  if (!nonpos_len(u)) return;
  if (!family_open<kMode>(-u + std::max(kPi, q.hb), best)) return;
  double alpha = kInf;
  for (int m = 0; m < 2; ++m) {
    if constexpr (kMode >= 2) {
      const Dir dt = mul(q.dir_b(m), {-2.0, r}), dv = mul(dt, q.minus_heading(m));
      if (!may_nonneg(dt) || !may_nonneg(dv)) continue;
      const double inv = inverse(q.rb2);  // |(-2, r)| = |B|
      if (!may_beat(angle_floor(dt, inv) + kPi - u + angle_floor(dv, inv), best))
        continue;
    }
    if (alpha == kInf) alpha = std::atan2(r, -2.0);
    double t = mod2pi(q.theta_b_of(m) + alpha);
    if (!nonneg(t)) continue;
    double v = mod2pi(t - q.phis[m]);
    if (!nonneg(v)) continue;
    best.offer(t + kPi - u + v, q.code(kLRSLR, m), t, u, v);
  }
}

//! Every family for the query (X, Y, Φ) and its time-flip; S and C are
//! sin Φ and cos Φ, `omc` and `opc` are 1 - cos Φ and 1 + cos Φ without
//! cancellation. With kBackwards in `flags`, the families whose backwards
//! form another call covers are skipped.
template <int kMode>
inline void solve_pair(PairQuery& q, Best& best) {
  const double hb = q.hb;
  const bool backwards = q.flags & kBackwards;
  if (!backwards) {
    csc_lsl<kMode>(q, best);
    csc_lsr<kMode>(q, best);
  }
  ccc_lrl<kMode>(q, best);
  if (!backwards) {
    cccc_lrlr_a<kMode>(q, best);
    cccc_lrlr_b<kMode>(q, best);
  }
  const double hb_half = std::max(kHalfPi, hb);
  ccsc_lrsl<kMode>(q, best, hb_half);
  ccsc_lrsr<kMode>(q, best, hb_half);
  if (!backwards) ccscc_lrslr<kMode>(q, best);
}

//! The shortest candidate, with the pruning of `kMode` (a Pruning value):
//! 0 evaluates every candidate, 1 skips families by their bounds, 2 also
//! pre-checks each candidate. With a finite `cap` (unit radius) only
//! candidates shorter than it are offered: every pruning test compares a
//! bound with the best length so far, so a query whose shortest candidate is
//! below the cap gets the same answer bit for bit, and any other query gets
//! code 0 and an infinite length.
template <int kMode = 2>
Best solve(const Local& q, double cap = kInf) {
  const double s = std::sin(q.phi), c = std::cos(q.phi);
  // 1 -/+ cos φ without cancellation: s² / (1 ± c) where 1 ± c is large.
  const double omc = c > 0.0 ? s * s / (1.0 + c) : 1.0 - c;
  const double opc = c < 0.0 ? s * s / (1.0 - c) : 1.0 + c;
  const double hb = std::abs(q.phi);
  const double xb = q.x * c + q.y * s, yb = q.x * s - q.y * c;
  // Forward words first (CSC usually wins far away), then the reflection,
  // then the backwards words seen from the goal.
  PairQuery pairs[4] = {{q.x, q.y, q.phi, s, c, omc, opc, 0, hb},
                        {q.x, -q.y, -q.phi, -s, c, omc, opc, kReflect, hb},
                        {xb, yb, q.phi, s, c, omc, opc, kBackwards, hb},
                        {xb, -yb, -q.phi, -s, c, omc, opc, kBackwards | kReflect, hb}};
  Best best;
  best.len = cap;
  best.code = -1;
  for (PairQuery& p : pairs) solve_pair<kMode>(p, best);
  if (best.code < 0) best.code = 0, best.len = kInf;
  return best;
}

}  // namespace

// ---- Shortest paths ---------------------------------------------------------

Path shortest_path(const Pose2& from, const Pose2& to, double radius) {
  Path p = make_path(solve(to_local(from, to, radius)), radius);
#ifndef NDEBUG
  // As OMPL's ReedsSheppStateSpace does in debug builds: the path driven from
  // `from` ends at `to` (up to rounding that grows with the distances).
  const double scale = 1.0 + radius + std::hypot(to.x - from.x, to.y - from.y);
  assert(geometry::pose_gap(end_pose(from, p), to) <= 1e-6 * scale);
#endif
  return p;
}

double shortest_length(const Pose2& from, const Pose2& to, double radius) {
  return final_length(solve(to_local(from, to, radius))) * radius;
}

std::size_t first_shortest(std::span<const Pose2> from, const Pose2& to, double radius,
                           std::vector<std::pair<double, std::size_t>>& scratch) {
  // A skipped pose's length is at least its bound, which exceeds the best by
  // more than the rounding of either (~1e-15 relative for room-sized poses).
  constexpr double kRounding = 1e-9;  // relative
  scratch.clear();
  for (std::size_t i = 0; i < from.size(); ++i)
    scratch.emplace_back(length_lower_bound(from[i], to, radius), i);
  std::sort(scratch.begin(), scratch.end());
  // Once a length is known, later poses are solved with a cap just above
  // it (solve()): a pose that can win or tie gets its exact length, and the
  // others stop at the first bounds that exceed the cap. The cap's margin
  // covers the snapping of final_length() (at most 5 kTol).
  std::size_t best = from.size();
  double best_length = std::numeric_limits<double>::infinity();
  const double inv = 1.0 / radius;
  for (const auto& [bound, i] : scratch) {
    if (bound > best_length + kRounding * (1.0 + best_length)) break;
    const double cap = best_length * inv + kRounding * (1.0 + best_length * inv);
    const Best b = solve(to_local(from[i], to, radius), cap);
    const double d = b.len < kInf ? final_length(b) * radius : kInf;
    if (d < best_length || (best < from.size() && d == best_length && i < best)) {
      best_length = d;
      best = i;
    }
  }
  return best;
}

ShortestWord shortest_word(const Pose2& from, const Pose2& to, double radius) {
  const Best b = solve(to_local(from, to, radius));
  return {final_length(b) * radius, word_of(b.code, b.v)};
}

ShortestWord shortest_word(const Pose2& from, const Pose2& to, double radius, Pruning pruning) {
  const Local q = to_local(from, to, radius);
  const Best b = pruning == Pruning::kNone           ? solve<0>(q)
                 : pruning == Pruning::kFamilyBounds ? solve<1>(q)
                                                     : solve<2>(q);
  return {final_length(b) * radius, word_of(b.code, b.v)};
}

}  // namespace hrs::rs
