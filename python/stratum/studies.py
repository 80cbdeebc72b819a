"""stratum.studies: test integrands, integration with any sampler, and
studies (convergence; dimension and importance studies below).

>>> import stratum
>>> r = stratum.integrate("disk", "sobol:owen", 4096, runs=8)
>>> abs(r["error"]) < 6 * r["standard_error"]
True
"""
from __future__ import annotations

import numbers

import numpy as np

from . import _checks, _stratum
from ._stratum import InvalidArgument

__all__ = ["integrands", "integrate", "converge"]

# ============================================================================
# Section: integrands(), integrate(), converge()
# ============================================================================


def _count(name, value, allowed, minimum=1):
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < minimum:
        raise InvalidArgument(f"invalid {name} = {value!r}: {allowed}")
    if value >= 2**64:
        raise InvalidArgument(f"invalid {name} = {value!r}: must be below 2^64")
    return int(value)


def _dimension(d):
    if d is None:
        return 0
    d = _count("d", d, "must be a positive integer")
    if d > 2**32 - 1:
        raise InvalidArgument(f"invalid d = {d}: must be below 2^32")
    return d


def _seed(seed):
    return _checks.seed(seed)


def _small(name, value, allowed, low, high):
    value = _count(name, value, allowed, low)
    if value > high:
        raise InvalidArgument(f"invalid {name} = {value}: {allowed}")
    return value


def _integrand_params(params):
    """Integrand parameters as flat lists of floats (a number or an array-like each)."""
    out = {}
    for key, value in params.items():
        try:
            array = np.asarray(value, dtype=np.float64).ravel()
        except (TypeError, ValueError):
            raise InvalidArgument(f"invalid {key} = {value!r}: must be a number or a list of numbers") from None
        out[key] = array.tolist()
    return out


def integrands() -> list[dict]:
    """Every test integrand: name, description, min_dim, max_dim, default_dim,
    properties and params (name, description, default)."""
    return _stratum.integrands()


def integrate(integrand: str, sampler: str = "random", n: int = 1024, d: int | None = None, seed: int = 0,
              randomize: str | None = None, runs: int = 1, threads: int = 1, confidence: float = 0.95,
              abs_tol: float | None = None, rel_tol: float | None = None, max_n: int | None = None,
              **params) -> dict:
    """Estimate `integrand` over [0,1]^d with `n` points of `sampler`, a
    spec NAME[(KEY=VALUE,...)][:RANDOMIZER] ("sobol:owen",
    "jittered(strata=4x8)"; docs/samplers.md).

    runs=1: one point set; standard_error is s/sqrt(n) of its values
    (standard_error_kind "iid": right for i.i.d. points, only indicative for
    stratified or QMC points). runs >= 2: independent randomizations, run r
    seeded with hash(seed, r); standard_error comes from the replicates
    ("replicates"), or is nan with standard_error_kind "identical-runs" when
    every run gave the same estimate (a sampler that is not randomized, e.g.
    "grid", "zaremba", "hammersley:none": no error estimate, never a false 0). Extra keyword arguments are the integrand's parameters
    (numbers or arrays, e.g. a=[2, 3, 4]). Returns a dict with estimate,
    standard_error, standard_error_kind, exact, error, seconds, run_estimates
    (numpy array) and the resolved integrand, sampler, randomize, d, n, runs;
    interval (low, high), the Student-t confidence interval at level
    `confidence` (estimate +- t_{runs-1} x standard_error over the runs; with
    runs=1, t_{n-1} over the n values), its half_width, and efficiency
    1 / (variance x seconds) with seconds_per_run, as converge has (nan
    without a standard error).

    abs_tol / rel_tol: integrate to a tolerance, doubling n (from `n`, at
    most `max_n`, default 2**24) until half_width <= max(abs_tol, rel_tol *
    |estimate|), as QMCPy's replicated stopping rules do; the result then
    has "tolerance": abs_tol, rel_tol, target, met and the steps (n,
    estimate, half_width, target, seconds). Stopping when the interval is
    first narrow can cover less than `confidence` (optional stopping);
    use 16 or more runs (docs/samplers.md).
    """
    if isinstance(confidence, bool) or not isinstance(confidence, numbers.Real) or not 0 < confidence < 1:
        raise InvalidArgument(f"invalid confidence = {confidence!r}: must be a level strictly between 0 and 1, "
                              "e.g. 0.95")
    n = _count("n", n, "must be a positive integer")
    runs = _small("runs", runs, "must be in [1, 1000000]", 1, 1000000)
    threads = _checks.threads(threads)
    integrand, sampler = _checks.text("integrand", integrand), _checks.text("sampler", sampler)
    randomize = _checks.text("randomize", randomize, optional=True)
    tolerances = []
    for name, value in (("abs_tol", abs_tol), ("rel_tol", rel_tol)):
        if value is not None and (isinstance(value, bool) or not isinstance(value, numbers.Real)):
            raise InvalidArgument(f"invalid {name} = {value!r}: must be a real number")
        tolerances.append(None if value is None else float(value))
    max_n = None if max_n is None else _count("max_n", max_n, "must be a positive integer")
    return _stratum.integrate(integrand, _dimension(d), _integrand_params(params), sampler, randomize, n, runs,
                              _seed(seed), threads, float(confidence), tolerances[0], tolerances[1], max_n)


def converge(integrand: str, samplers, n=None, runs: int = 32, d: int | None = None, seed: int = 0,
             threads: int = 1, confidence: float = 0.95, **params) -> dict:
    """Convergence study: for each sampler (a spec
    NAME[(KEY=VALUE,...)][:RANDOMIZER], docs/samplers.md; a list, or one string
    split on the commas outside parentheses) and each N, `runs` independent
    randomizations (run r of sampler s at N seeded with hash(seed, s, N, r)).

    n: "A:B" (powers of two from A to B), "A:B:F" (A, A*F, ... up to B) or a
    list of increasing positive integers; None (the default) is "16:65536",
    where each sampler skips the counts it refuses (2D jittered takes only
    squares) and lists them in its "skipped" (n, reason); a count given
    explicitly that a sampler refuses raises InvalidArgument. Returns a dict:
    integrand, d, exact, runs, n (numpy array, the counts asked for) and
    samplers, a dict keyed by "name:randomizer" of dicts with n (the counts
    it ran), skipped, numpy arrays mean_error, rmse, variance, seconds, efficiency
    (1 / (variance x seconds)), and the fitted log-log slope of variance vs N
    (slope, slope_standard_error, intercept; fitted says "variance", or "mse"
    for a deterministic sampler). slope_interval (low, high) is the slope's
    confidence interval at level `confidence` (slope_confidence), slope +- t x
    slope_sampling_standard_error (t over the runs), the jackknife over runs
    (NaN unless fitted is "variance" and runs >= 3); the residual
    slope_standard_error only says how straight the line is. Numbers other
    than timings do not depend on `threads`.
    """
    integrand = _checks.text("integrand", integrand)
    if isinstance(samplers, str):
        samplers = _stratum.split_spec_list(samplers)
    if not hasattr(samplers, "__iter__"):
        raise InvalidArgument(f"invalid samplers = {samplers!r}: give a list of names (each NAME or NAME:RANDOMIZER)")
    samplers = list(samplers)
    if not samplers or not all(isinstance(s, str) for s in samplers):
        raise InvalidArgument(f"invalid samplers = {samplers!r}: give a list of names (each NAME or NAME:RANDOMIZER)")
    skip_refused = n is None
    if n is None:
        counts = _stratum.parse_counts(_stratum.default_counts)
    elif isinstance(n, str):
        counts = _stratum.parse_counts(n)
    else:
        values = [n] if isinstance(n, numbers.Integral) else list(np.asarray(n).ravel().tolist())
        counts = [_count("n", v, "must be positive integers") for v in values]
    runs = _small("runs", runs, "must be in [2, 1000000] (a variance needs 2 runs)", 2, 1000000)
    threads = _checks.threads(threads)
    if isinstance(confidence, bool) or not isinstance(confidence, numbers.Real) or not 0 < confidence < 1:
        raise InvalidArgument(f"invalid confidence = {confidence!r}: must be a level strictly between 0 and 1, "
                              "e.g. 0.95")
    return _stratum.converge(integrand, _dimension(d), _integrand_params(params), samplers, counts, runs, _seed(seed),
                             threads, skip_refused, float(confidence))


# ============================================================================
# Section: study_dimension(), study_importance()
# (append below; extend __all__ with `__all__ += [...]`)
# ============================================================================

__all__ += ["study_dimension", "study_importance", "study_mis", "rectangle_irradiance"]


def _studies_int(name, value, low, high, allowed):
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or not low <= value <= high:
        raise InvalidArgument(f"invalid {name} = {value!r}: {allowed}")
    return int(value)


def _studies_range(name, value, high):
    """"A:B", "A", an integer or a pair (A, B) into (A, B) with 1 <= A <= B <= high."""
    allowed = f"must be A:B or A, integers with 1 <= A <= B <= {high}"
    if isinstance(value, str):
        parts = value.split(":")
        if len(parts) not in (1, 2) or not all(p.isdigit() for p in parts):
            raise InvalidArgument(f"invalid {name} = {value}: {allowed}")
        lo, hi = int(parts[0]), int(parts[-1])
    elif isinstance(value, numbers.Integral) and not isinstance(value, bool):
        lo = hi = int(value)
    else:
        try:
            lo, hi = value
        except (TypeError, ValueError):
            raise InvalidArgument(f"invalid {name} = {value!r}: {allowed}") from None
        for v in (lo, hi):
            if isinstance(v, bool) or not isinstance(v, numbers.Integral):
                raise InvalidArgument(f"invalid {name} = {value!r}: {allowed}")
    if not 1 <= lo <= hi <= high:
        shown = value if isinstance(value, str) else repr(value)
        raise InvalidArgument(f"invalid {name} = {shown}: {allowed}")
    return int(lo), int(hi)


def _studies_lengths(name, values):
    try:
        array = np.asarray(values, dtype=np.float64).ravel()
    except (TypeError, ValueError):
        raise InvalidArgument(f"invalid {name} = {values!r}: must be a number or a list of numbers") from None
    return array.tolist()


def study_dimension(dims="1:10", n="16:65536", runs: int = 16, rule: str = "midpoint",
                    integrand: str = "sine-product", sobol: bool = True, seed: int = 0, threads: int = 1) -> dict:
    """Product quadrature rule vs Monte Carlo as the dimension grows (lecture §6).

    For each d in `dims` ("A:B", an int or a pair) the product rule with m
    points per axis (rule "midpoint", order 2, error ~ N^(-2/d); or "gauss",
    Gauss-Legendre) at N = m^d in the range `n` (about one m per doubling),
    `runs` Monte Carlo estimates (and Owen-scrambled Sobol' ones if `sobol`) at
    the same N. `integrand`: "sine-product" (prod (pi/2) sin(pi x_j), exact
    variance known) or a smooth registry integrand such as "genz-gaussian".
    Returns a dict: rule, integrand, runs and series, a list with one dict per
    d: d, exact, variance (nan if unknown), numpy arrays m, n, product_error,
    mc_rmse, mc_predicted (sigma/sqrt(N)), sobol_rmse, and the fitted log-log
    slopes product_slope (with product_predicted_slope, -2/d for midpoint),
    mc_slope, sobol_slope. Does not depend on `threads`.
    """
    lo_d, hi_d = _studies_range("dims", dims, 64)
    lo_n, hi_n = _studies_range("n", n, 2**24)
    runs = _studies_int("runs", runs, 2, 100000, "must be in [2, 100000] (an RMSE needs 2 runs)")
    threads = _checks.threads(threads)
    seed = _checks.seed(seed)
    return _stratum.study_dimension(lo_d, hi_d, lo_n, hi_n, runs, str(rule), str(integrand), bool(sobol), seed,
                                    threads)


def study_importance(runs: int = 16, samples: int = 4096, sizes=(0.25, 1.0, 4.0), distances=(0.25, 1.0, 4.0),
                     radiance: float = 1.0, seed: int = 0, threads: int = 1) -> dict:
    """Importance sampling measured (lecture §3): irradiance at a point with
    normal +z.

    Returns a dict: runs, samples, and two column dicts of numpy arrays,
    "hemisphere" (uniform sky, then a unit square light at height 1: a =
    uniform hemisphere, b = cosine-weighted) and "light" (a square light of
    each size at each distance, sizes outer: a = sampled by area, b = by solid
    angle). Columns: scene, method_a, method_b, size, distance, exact (closed
    form), estimate_a/_b, estimate_stderr_a/_b, variance_a/_b (per sample),
    variance_stderr_a/_b, predicted_variance_a/_b, seconds_per_sample_a/_b,
    efficiency_a/_b (1 / (variance x seconds)), variance_ratio (a/b),
    variance_ratio_stderr, predicted_variance_ratio, time_ratio (a/b) and
    efficiency_ratio (b over a). Only the timings depend on `threads`.
    """
    runs = _studies_int("runs", runs, 2, 100000, "must be in [2, 100000] (a standard error needs 2 runs)")
    samples = _studies_int("samples", samples, 2, 2**30, "must be in [2, 2^30]")
    threads = _checks.threads(threads)
    seed = _checks.seed(seed)
    return _stratum.study_importance(runs, samples, _studies_lengths("sizes", sizes),
                                     _studies_lengths("distances", distances), _studies_number("radiance", radiance),
                                     seed, threads)


def study_mis(exponents=(1, 10, 100, 1000), angles=(2, 10, 30, 60), runs: int = 16, samples: int = 1024,
              beta: float = 2.0, seed: int = 0, threads: int = 1) -> dict:
    """Multiple importance sampling measured (Veach 1997, section 9.2): the
    light a normalized Phong lobe of exponent e reflects from a round light of
    half-angle `angles` degrees (exact: 1 - cos^(e+1) a), by light sampling,
    BSDF sampling, and half of each combined by the balance and the power
    (exponent `beta`) heuristics.

    Returns a dict of columns, one row per (exponent, angle), exponents outer:
    exponent, angle, exact, best_single ("light"/"bsdf"), balance_over_best
    and power_over_best (predicted variance over the better single
    strategy's), balance_bound (Veach's bound 2 min(V) + I^2), and per method
    (suffix _light, _bsdf, _balance, _power): estimate, estimate_stderr,
    variance (per sample), variance_stderr, predicted_variance. The same
    numbers as `stratum study mis --json`; does not depend on `threads`.
    """
    runs = _studies_int("runs", runs, 2, 100000, "must be in [2, 100000] (a standard error needs 2 runs)")
    samples = _studies_int("samples", samples, 4, 2**32, "must be even, in [4, 2^32]")
    threads = _checks.threads(threads)
    seed = _checks.seed(seed)
    return _stratum.study_mis(_studies_lengths("exponents", exponents), _studies_lengths("angles", angles), runs,
                              samples, _studies_number("beta", beta), seed, threads)


def _studies_number(name, value):
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise InvalidArgument(f"invalid {name} = {value!r}: must be a number")
    return float(value)


def _studies_vector(name, value):
    array = np.asarray(_studies_lengths(name, value))
    if array.shape != (3,):
        raise InvalidArgument(f"invalid {name} = {value!r}: must be 3 numbers")
    return array.tolist()


def rectangle_irradiance(corner, edge_u, edge_v, radiance: float = 1.0) -> float:
    """Irradiance at the origin (normal +z) from the rectangle corner +
    s*edge_u + t*edge_v (s, t in [0,1], perpendicular edges, entirely above
    z = 0) of uniform radiance, by Lambert's polygon formula (Lambert 1760;
    Arvo 1995): E = (L/2) sum_i Theta_i (n . Gamma_i)."""
    return _stratum.rectangle_irradiance(_studies_vector("corner", corner), _studies_vector("edge_u", edge_u),
                                         _studies_vector("edge_v", edge_v), _studies_number("radiance", radiance))
