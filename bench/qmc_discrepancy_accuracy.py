#!/usr/bin/python3
"""Accuracy of stratum.qmc.discrepancy and scipy.stats.qmc.discrepancy
against a reference that is exact to ~1e-15 relative or better.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/qmc_discrepancy_accuracy.py [--max-n 4096]

The four measures are small differences of O(1) sums (scipy's definitions:
CD, WD, MD squared, L2-star as a root). The reference computes every term
(each single-sum and pair-sum term, a product of d factors) in numpy's
long double (64-bit significand) from the exact double coordinates, splits
each into two doubles (hi + lo, exact) and adds them all with math.fsum
(exact), so its only error is one long-double rounding per term. At n = 64
it is checked against exact rational arithmetic (fractions). Points:
uniform random (numpy default_rng(1)) and scrambled Sobol' (stratum.qmc,
seed 1), d = 2 and 5. Prints a Markdown table of relative errors.
"""
import argparse
import math
from fractions import Fraction

import numpy as np
from scipy.stats import qmc as scipy_qmc

from stratum import qmc as stratum_qmc

LD = np.longdouble


def _parts(values, scale=1.0):
    """Long doubles as doubles hi + lo (exact), times `scale`, a power of two (exact)."""
    values = np.asarray(values, dtype=LD).ravel()
    hi = values.astype(np.float64)
    lo = (values - hi.astype(LD)).astype(np.float64)
    return np.concatenate([hi, lo]) * scale


def _pair_parts(x, kernel, scale, block=256):
    """The terms Π_k kernel(x_ik, x_jk) of every pair, in long double, as exact double parts."""
    n = len(x)
    for start in range(0, n, block):
        a = x[start:start + block, None, :]
        yield _parts(np.prod(kernel(a, x[None, :, :]), axis=2), scale)


def _total(*groups):
    """The exact sum of every part, rounded once (math.fsum over a stream: one block in memory at a time)."""
    def stream():
        for group in groups:
            for part in ([group] if isinstance(group, np.ndarray) else group):
                yield from part.tolist()
    return math.fsum(stream())


def reference(x, method):
    """scipy's definitions, terms in long double, every sum exact, one rounding at the end."""
    n, d = x.shape
    assert n & (n - 1) == 0, "n must be a power of two (the scales 2/n, 1/n² are then exact)"
    x = x.astype(LD)
    half = LD(1) / 2
    if method == "CD":
        c = np.abs(x - half)
        single = np.prod(1 + c / 2 - c * c / 2, axis=1)
        pairs = _pair_parts(x, lambda a, b: 1 + np.abs(a - half) / 2 + np.abs(b - half) / 2 - np.abs(a - b) / 2,
                            1.0 / n**2)
        return _total(_parts([(LD(13) / 12) ** d]), _parts(single, -2.0 / n), pairs)
    if method == "WD":
        pairs = _pair_parts(x, lambda a, b: LD(3) / 2 - np.abs(a - b) * (1 - np.abs(a - b)), 1.0 / n**2)
        return _total(_parts([-(LD(4) / 3) ** d]), pairs)
    if method == "MD":
        c = np.abs(x - half)
        single = np.prod(LD(5) / 3 - c / 4 - c * c / 4, axis=1)
        pairs = _pair_parts(x, lambda a, b: LD(15) / 8 - np.abs(a - half) / 4 - np.abs(b - half) / 4
                            - 3 * np.abs(a - b) / 4 + (a - b) ** 2 / 2, 1.0 / n**2)
        return _total(_parts([(LD(19) / 12) ** d]), _parts(single, -2.0 / n), pairs)
    # L2-star, returned as a root by scipy
    single = np.prod(1 - x * x, axis=1)
    pairs = _pair_parts(x, lambda a, b: 1 - np.maximum(a, b), 1.0 / n**2)
    return math.sqrt(_total(_parts([LD(1) / 3**d]), _parts(single, -(2.0 ** (1 - d)) / n), pairs))


def exact_rational(x, method):
    """The same definitions in fractions (small n only)."""
    n, d = x.shape
    q = [[Fraction(float(v)) for v in row] for row in x]
    h = Fraction(1, 2)

    def prod(values):
        out = Fraction(1)
        for v in values:
            out *= v
        return out

    if method == "CD":
        single = sum(prod(1 + abs(v - h) / 2 - abs(v - h) ** 2 / 2 for v in row) for row in q)
        pairs = sum(prod(1 + abs(a - h) / 2 + abs(b - h) / 2 - abs(a - b) / 2 for a, b in zip(r, s)) for r in q for s in q)
        return Fraction(13, 12) ** d - Fraction(2, n) * single + pairs / n**2
    if method == "WD":
        pairs = sum(prod(Fraction(3, 2) - abs(a - b) * (1 - abs(a - b)) for a, b in zip(r, s)) for r in q for s in q)
        return -Fraction(4, 3) ** d + pairs / n**2
    if method == "MD":
        single = sum(prod(Fraction(5, 3) - abs(v - h) / 4 - abs(v - h) ** 2 / 4 for v in row) for row in q)
        pairs = sum(prod(Fraction(15, 8) - abs(a - h) / 4 - abs(b - h) / 4 - 3 * abs(a - b) / 4 + (a - b) ** 2 / 2
                         for a, b in zip(r, s)) for r in q for s in q)
        return Fraction(19, 12) ** d - Fraction(2, n) * single + pairs / n**2
    single = sum(prod(1 - v * v for v in row) for row in q)
    pairs = sum(prod(1 - max(a, b) for a, b in zip(r, s)) for r in q for s in q)
    return Fraction(1, 3**d) - Fraction(2, 2**d) * single / n + pairs / n**2  # the square; compared squared


def points(kind, n, d):
    if kind == "random":
        return np.random.default_rng(1).random((n, d))
    return stratum_qmc.Sobol(d, seed=1).random(n)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--max-n", type=int, default=4096)
    args = parser.parse_args()
    methods = ("CD", "WD", "MD", "L2-star")
    # The reference against exact rationals.
    worst = 0.0
    for method in methods:
        for d in (2, 5):
            x = points("random", 64, d)
            exact = exact_rational(x, method)
            ours = reference(x, method) ** (2 if method == "L2-star" else 1)
            worst = max(worst, abs(Fraction(ours) - exact) / abs(exact))
    print(f"reference vs exact rationals (n = 64, d = 2, 5, four methods): worst relative error {float(worst):.1e}\n")
    print("| points | method | d | n | value | stratum rel. error | scipy rel. error |")
    print("|---|---|---:|---:|---:|---:|---:|")
    for kind in ("random", "sobol"):
        for method in methods:
            for d in (2, 5):
                n = 256
                while n <= args.max_n:
                    x = points(kind, n, d)
                    ref = reference(x, method)
                    ours = stratum_qmc.discrepancy(x, method=method)
                    theirs = scipy_qmc.discrepancy(x, method=method)
                    print(f"| {kind} | {method} | {d} | {n} | {ref:.3e} | {abs(ours - ref) / ref:.1e} | "
                          f"{abs(theirs - ref) / ref:.1e} |", flush=True)
                    n *= 4


if __name__ == "__main__":
    main()
