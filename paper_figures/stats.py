"""Statistics for REPRODUCTION.md: means with their spread, confidence
intervals (a seeded percentile bootstrap for ratios and differences of
means, Wilson's interval for proportions) and verdicts that only say
"reproduced" or "differs" when the interval supports it.

The bootstrap resamples each group with replacement (2000 times, fixed
seed, so a re-run writes the same text); the 95 % interval is the 2.5th
and 97.5th percentile of the resampled statistic (Efron and Tibshirani,
An Introduction to the Bootstrap, 1993, ch. 13). Wilson's interval for k
successes of n: (p + z²/2n ± z·sqrt(p(1−p)/n + z²/4n²)) / (1 + z²/n),
z = 1.96 (Wilson, JASA 22, 1927)."""

import math
import random

Z95 = 1.959963984540054
RESAMPLES = 2000


def clean(values):
    return [x for x in values if x is not None and not math.isnan(x)]


def mean_sd(values):
    """(mean, sample sd, n) of the finite values; (nan, nan, 0) when none."""
    v = clean(values)
    if not v:
        return float("nan"), float("nan"), 0
    m = sum(v) / len(v)
    sd = math.sqrt(sum((x - m) ** 2 for x in v) / (len(v) - 1)) if len(v) > 1 else 0.0
    return m, sd, len(v)


def _percentiles(samples):
    samples = sorted(samples)
    lo = samples[int(0.025 * (len(samples) - 1))]
    hi = samples[int(math.ceil(0.975 * (len(samples) - 1)))]
    return lo, hi


def bootstrap(a, b, statistic, seed=1):
    """Percentile 95 % interval of statistic(mean(a), mean(b)) over
    resamples of a and b; None when either group has fewer than 2 values."""
    a, b = clean(a), clean(b)
    if len(a) < 2 or len(b) < 2:
        return None
    rng = random.Random(seed)
    out = []
    for _ in range(RESAMPLES):
        ma = sum(rng.choice(a) for _ in a) / len(a)
        mb = sum(rng.choice(b) for _ in b) / len(b)
        v = statistic(ma, mb)
        if v is not None and not math.isnan(v):
            out.append(v)
    if len(out) < RESAMPLES // 2:
        return None
    return _percentiles(out)


def ratio_ci(new, ref):
    """95 % interval of mean(new) / mean(ref)."""
    return bootstrap(new, ref, lambda x, y: x / y if y > 0 else float("nan"))


def diff_ci(new, ref):
    """95 % interval of mean(new) − mean(ref)."""
    return bootstrap(new, ref, lambda x, y: x - y)


def wilson(k, n):
    """Wilson's 95 % interval of a proportion k / n."""
    if n == 0:
        return float("nan"), float("nan")
    p = k / n
    z2 = Z95 * Z95
    centre = (p + z2 / (2 * n)) / (1 + z2 / n)
    half = Z95 * math.sqrt(p * (1 - p) / n + z2 / (4 * n * n)) / (1 + z2 / n)
    return max(0.0, centre - half), min(1.0, centre + half)


def reduction_text(ci):
    """A time ratio's interval as a reduction in percent: '−62 % [−70, −51]'."""
    lo, hi = ci
    return f"[{-100 * (1 - lo):+.0f}, {-100 * (1 - hi):+.0f}] %"


def verdict_interval(ci, claim_lo, claim_hi):
    """Verdict of a claim that a quantity lies in [claim_lo, claim_hi], from
    its 95 % interval `ci`, relative to 'no effect' at 0: reproduced when
    the interval overlaps the claim and excludes no effect; differs when it
    excludes both the claim and no effect; otherwise no detectable
    difference (from no effect, or from the claim)."""
    if ci is None:
        return "too few runs for an interval"
    lo, hi = ci
    overlaps = lo <= claim_hi and hi >= claim_lo
    excludes_zero = lo > 0 or hi < 0
    if overlaps and excludes_zero:
        return "reproduced"
    if excludes_zero and not overlaps:
        return "differs: larger than the paper's" if lo > claim_hi else \
            "differs: smaller than the paper's"
    return "no detectable difference from no effect"
