"""Measures of point sets: discrepancies, stratification and geometry.

Every measure of the C++ registry (the same list as ``stratum discrepancy
--measure``) is reachable here:

>>> import stratum
>>> x = stratum.points("halton", 256, 2, randomize="none")
>>> r = stratum.measure(x, "l2-star")                  # dict: value, kind, lower, upper, extras
>>> r["kind"], r["value"] == stratum.discrepancy(x, "l2-star")
('exact', True)
>>> [m["name"] for m in stratum.measures()][:4]
['l2-star', 'cd', 'wd', 'md']

Return conventions (docs/discrepancy.md):

- scipy's method names "CD", "WD", "MD" and "L2-star" give exactly what
  ``scipy.stats.qmc.discrepancy`` gives: the SQUARED centered, wrap-around and
  mixture discrepancies, and the L2-star discrepancy itself (not squared).
- registry names ("l2-star", "cd", "wd", "md", "star", "edge", "edge-random",
  "t-value", "min-distance", ...) give the registry's ``value``: the
  discrepancy itself for every L2 discrepancy (its square is in
  ``measure(...)["extras"]["squared"]``), the exact star or edge discrepancy,
  the RMS for "edge-random" (mean and max in its extras), and so on; see each
  measure's description in ``measures()``.
"""
from __future__ import annotations

import numbers
import warnings

import numpy as np

from . import _checks, _stratum
from ._stratum import InvalidArgument

__all__ = ["measures", "measure", "discrepancy", "local_discrepancy", "star_discrepancy_box", "koksma_hlawka",
           "variation_test_functions"]

# scipy.stats.qmc.discrepancy's method names and the registry measure behind each.
_SCIPY_METHODS = {"CD": "cd", "WD": "wd", "MD": "md", "L2-star": "l2-star"}


def _points(x) -> np.ndarray:
    """x as a C-ordered float64 array of shape (n, d); a 1-D array is n points in one dimension."""
    array = _checks.real_array("x", x, "an array of numbers of shape (n, d)")
    if array.ndim == 1:
        array = array[:, None]
    if array.ndim != 2:
        raise InvalidArgument(f"invalid x = array of shape {array.shape}: must have shape (n, d), or (n,) for d = 1")
    return np.ascontiguousarray(array)


def _param_text(name, value) -> str:
    if isinstance(value, str):
        return value
    if isinstance(value, (bool, np.bool_)):
        return "1" if value else "0"
    if isinstance(value, (numbers.Integral, np.integer)):
        return str(int(value))
    if isinstance(value, (numbers.Real, np.floating)):
        return repr(float(value))
    raise InvalidArgument(f"invalid {name} = {value!r}: must be a number or a string")


def _threads(threads) -> int:
    return _checks.threads(threads)


def measures() -> list[dict]:
    """Every measure of point sets: name, description (definition and source,
    and what its value is), min_dim, max_dim (0: any) and params (name,
    description, default)."""
    return _stratum.measures()


def measure(x, name: str, threads: int = 1, **params) -> dict:
    """Measure `name` of the points x (shape (n, d), n >= 2, coordinates in [0, 1]).

    Returns a dict: ``value`` (the measure; for kind "bounds" the upper bound),
    ``kind`` ("exact", "bounds": the exact value lies in [lower, upper], or
    "estimate": a random estimate such as the random-edge RMS), ``lower`` and
    ``upper`` (floats for bounds, else None) and ``extras`` (a dict of
    floats, e.g. {"squared": ...} for the L2 discrepancies, {"mean": ...,
    "max": ..., "lines": ...} for "edge-random").
    Keyword arguments are the measure's parameters (see ``measures()``).
    The result does not depend on ``threads``. Raises InvalidArgument (a
    ValueError) naming the row and column of a point outside [0, 1], NaN or
    Inf, for n < 2, an unknown measure or parameter, or a d the measure is not
    defined for.
    """
    if not isinstance(name, str):
        raise InvalidArgument(f"invalid measure = {name!r}: must be a measure name (see stratum.measures())")
    points = _points(x)
    text = {key: _param_text(key, value) for key, value in params.items()}
    return _stratum.measure(points, name, _threads(threads), text)


def discrepancy(x, method: str = "CD", threads: int = 1, **params) -> float:
    """One number measuring the points x (shape (n, d), coordinates in [0, 1]).

    method:
      - scipy's names "CD", "WD", "MD", "L2-star": the value
        ``scipy.stats.qmc.discrepancy(x, method=method)`` returns, i.e. the
        squared centered / wrap-around / mixture discrepancy and the L2-star
        discrepancy itself (computed by stratum: O(N log N) for L2-star with
        d <= 3, vectorized and threaded O(d N^2) otherwise). Unlike scipy, n >= 2
        is required (``stratum.qmc.discrepancy`` accepts n = 1 as scipy does).
      - any registry name (``[m["name"] for m in stratum.measures()]``): that
        measure's ``value``: "l2-star", "cd", "wd", "md" the discrepancy
        itself (not squared); "star" the exact star discrepancy D*; "edge" the
        exact edge discrepancy; "edge-random" the RMS over random lines
        (params ``lines=``, ``seed=``; mean and max via ``measure()``);
        "t-value", "min-distance", ... as their descriptions say.
        For a measure whose result is of kind "bounds" (e.g. the star
        discrepancy where it cannot be computed exactly) the upper bound is
        returned with a warning; ``measure()`` gives both bounds.
    """
    if isinstance(method, str) and method in _SCIPY_METHODS:
        result = measure(x, _SCIPY_METHODS[method], threads, **params)
        return result["value"] if method == "L2-star" else result["extras"]["squared"]
    if not isinstance(method, str) or method not in [m["name"] for m in measures()]:
        names = ", ".join(list(_SCIPY_METHODS) + [m["name"] for m in measures()])
        raise InvalidArgument(f"invalid method = {method!r}: allowed {names}")
    result = measure(x, method, threads, **params)
    if result["kind"] == "bounds":
        warnings.warn(f"{method}: only bounds were computed, [{result['lower']}, {result['upper']}]; "
                      "returning the upper bound (stratum.measure gives both)", stacklevel=2)
    return result["value"]


def local_discrepancy(x, resolution: int = 64) -> np.ndarray:
    """Local discrepancy of 2D points on the grid of corners (i/R, j/R), i, j = 0..R.

    Returns an array D of shape (R + 1, R + 1) with D[j, i] = n(x, y)/N - x*y at
    x = i/R, y = j/R, where n counts the points in [0, x) x [0, y) (LECTURE.md
    §10). max |D| is a lower bound on the star discrepancy; the box attaining
    D* itself is ``star_discrepancy_box(x)``. Raises InvalidArgument for d != 2,
    R outside [1, 4096] or a point outside [0, 1].
    """
    if (isinstance(resolution, (bool, np.bool_)) or not isinstance(resolution, (numbers.Integral, np.integer))
            or not 1 <= resolution <= 4096):
        raise InvalidArgument(f"invalid resolution = {resolution!r}: must be an integer in [1, 4096]")
    return _stratum.local_discrepancy(_points(x), int(resolution))


def star_discrepancy_box(x, threads: int = 1) -> dict:
    """Where the star discrepancy of 2D points x (n >= 2, at most 20000) is attained.

    Returns {"value": D*, "x": ..., "y": ...: the box [0, x) x [0, y),
    "closed": bool, "count": int}. closed is True when the box holds too many
    points, count/N - x*y = D*, with the points on its upper edges counted (the
    supremum is approached from above); False when it holds too few, x*y -
    count/N = D*, counting [0, x) x [0, y). The registry measure "star-box"
    (``stratum discrepancy -m star-box``) underneath; O(N^2) time.
    """
    result = measure(x, "star-box", threads)
    extras = result["extras"]
    return {"value": result["value"], "x": extras["x"], "y": extras["y"], "closed": extras["closed"] == 1.0,
            "count": int(extras["count"])}


def variation_test_functions() -> list[dict]:
    """The 2D test functions of the Koksma-Hlawka check: function (name),
    formula, integral (exact, over [0, 1]^2), variation (Hardy-Krause,
    anchored at 1, closed form) and derivation (how the variation follows)."""
    return _stratum.variation_test_functions()


def koksma_hlawka(x, star_discrepancy: float | None = None, threads: int = 1) -> list[dict]:
    """The Koksma-Hlawka inequality |mean f(x_i) - integral f| <= V_HK(f) * D*
    (Niederreiter 1992, Thm. 2.11) checked on 2D points x for every test
    function of ``variation_test_functions()``.

    star_discrepancy: D* of x, or an upper bound on it; None computes it with
    the registry's "star" measure (exact for n <= 2^18, else Thiemard's upper
    bound, which keeps the inequality true).
    Returns one dict per function: the keys of ``variation_test_functions()``
    and estimate (mean f(x_i)), error (|estimate - integral|), bound
    (variation * D*), holds (error <= bound, up to 1e-12 of rounding), star
    (the D* used) and star_kind ("exact", "upper bound" or "given").
    """
    points = _points(x)
    if points.shape[1] != 2:
        raise InvalidArgument(f"invalid d = {points.shape[1]}: the Koksma-Hlawka test functions are 2D")
    if star_discrepancy is None:
        star, kind = _stratum.koksma_hlawka_star(points, _threads(threads))
    else:
        if isinstance(star_discrepancy, (bool, np.bool_)) or not isinstance(star_discrepancy, (numbers.Real, np.floating)):
            raise InvalidArgument(f"invalid star_discrepancy = {star_discrepancy!r}: must be a number in [0, 1]")
        star, kind = float(star_discrepancy), "given"
    rows = _stratum.koksma_hlawka(points, star)
    for row in rows:
        row["star"], row["star_kind"] = star, kind
    return rows
