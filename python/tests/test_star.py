"""stratum.discrepancy(x, method="star") and stratum.measure(x, "star", ...):
exact values against closed forms and a brute force written here, bounds
bracketing the exact value, and bad input."""
import itertools
import warnings

import numpy as np
import pytest

import stratum


def brute_force_star(x):
    """sup_z |#{p < z}/N - vol(z)| over z on the grid of coordinates (and 1),
    at z and just above z (the closed box). O(N^(d+1) d): small inputs only."""
    n, d = x.shape
    axes = [np.unique(np.append(x[:, j], 1.0)) for j in range(d)]
    best = 0.0
    for corner in itertools.product(*axes):
        z = np.array(corner)
        for c in (z, np.minimum(z + 1e-12, 1.0)):
            inside = np.all(x < c, axis=1).sum() / n
            best = max(best, abs(inside - np.prod(c)))
    return best


def radical_inverse_2(i):
    r, f = 0.0, 0.5
    while i:
        r += f * (i & 1)
        i >>= 1
        f *= 0.5
    return r


@pytest.mark.parametrize("n,d,seed", [(20, 2, 1), (33, 2, 2), (12, 3, 3), (7, 4, 4)])
def test_star_matches_brute_force(n, d, seed):
    x = np.random.default_rng(seed).random((n, d))
    assert stratum.discrepancy(x, method="star") == pytest.approx(brute_force_star(x), abs=1e-9)
    r = stratum.measure(x, "star")
    assert r["kind"] == "exact" and r["lower"] is None and r["upper"] is None


def test_star_ties_and_ones_match_brute_force():
    x = np.random.default_rng(9).integers(0, 5, size=(25, 2)) / 4.0
    assert stratum.discrepancy(x, method="star") == pytest.approx(brute_force_star(x), abs=1e-9)


def test_star_one_dimension_closed_form():
    # Niederreiter 1992, Theorem 2.6.
    x = np.random.default_rng(3).random((41, 1))
    s = np.sort(x[:, 0])
    n = len(s)
    expected = 1 / (2 * n) + np.max(np.abs(s - (2 * np.arange(1, n + 1) - 1) / (2 * n)))
    assert stratum.discrepancy(x, method="star") == pytest.approx(expected, abs=1e-15)


@pytest.mark.parametrize("m", [2, 5, 8, 11])
def test_star_hammersley_closed_form(m):
    # De Clerck 1986: N D* = m/3 + 13/9 - (-1)^m 4 / (9 2^m) for (i/N, phi_2(i)), N = 2^m.
    n = 2**m
    x = np.array([[i / n, radical_inverse_2(i)] for i in range(n)])
    expected = (m / 3 + 13 / 9 - (-1) ** m * 4 / (9 * n)) / n
    assert stratum.discrepancy(x, method="star") == pytest.approx(expected, rel=1e-13)


def test_star_bounds_bracket_exact():
    x = np.random.default_rng(5).random((200, 3))
    exact = stratum.discrepancy(x, method="star")
    r = stratum.measure(x, "star", method="bounds", delta=0.05)
    assert r["kind"] == "bounds"
    assert r["lower"] <= exact <= r["upper"]
    assert r["upper"] - r["lower"] <= 0.05 + 1e-12
    assert r["value"] == r["upper"] and r["extras"]["delta"] == 0.05


def test_star_beyond_exact_limit_gives_bounds_with_warning():
    x = np.random.default_rng(6).random((300, 6))  # 300 > 260, the exact (DEM) limit at d = 6: auto chooses bounds
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        value = stratum.discrepancy(x, method="star")
    assert any("bounds" in str(w.message) for w in caught)
    r = stratum.measure(x, "star")
    assert r["kind"] == "bounds" and r["lower"] <= value == r["upper"]


def test_star_threads_do_not_change_result():
    x = np.random.default_rng(7).random((6000, 2))
    assert stratum.measure(x, "star", threads=1)["value"] == stratum.measure(x, "star", threads=2)["value"]


@pytest.mark.parametrize(
    "shape,params,message",
    [
        ((300, 6), {"method": "exact"}, "invalid d = 6"),
        ((300, 6), {"method": "exact"}, "method=bounds"),
        ((10, 2), {"method": "fast"}, "invalid method = fast"),
        ((10, 2), {"method": "bounds", "delta": 1.5}, "invalid delta = 1.5"),
        ((10, 2), {"lines": 5}, "invalid measure-param = lines=5: star takes"),
        ((1, 2), {}, "invalid n = 1"),
    ],
)
def test_star_bad_input(shape, params, message):
    x = np.random.default_rng(8).random(shape)
    with pytest.raises(ValueError, match=message.replace("(", r"\(")):
        stratum.measure(x, "star", **params)


def test_star_point_outside_names_row_and_column():
    x = np.random.default_rng(8).random((5, 2))
    x[3, 1] = 1.25
    with pytest.raises(ValueError, match=r"point\[3\]\[1\] = 1.25"):
        stratum.discrepancy(x, method="star")
