"""stratum.local_discrepancy and the registry measures star-box and
koksma-hlawka, against brute force in numpy and closed forms."""
import math

import numpy as np
import pytest
from scipy import integrate

import stratum


def brute_grid(p, r):
    n = len(p)
    return np.array([[np.sum((p[:, 0] < i / r) & (p[:, 1] < j / r)) / n - (i / r) * (j / r)
                      for i in range(r + 1)] for j in range(r + 1)])


def brute_star(p):
    """D* by every critical corner (point coordinates or 1), both limits."""
    n = len(p)
    best = 0.0
    for x in np.append(p[:, 0], 1.0):
        for y in np.append(p[:, 1], 1.0):
            best = max(best, x * y - np.sum((p[:, 0] < x) & (p[:, 1] < y)) / n,
                       np.sum((p[:, 0] <= x) & (p[:, 1] <= y)) / n - x * y)
    return best


@pytest.mark.parametrize("sampler,n,r", [("random", 50, 7), ("halton", 100, 10), ("jittered", 64, 16)])
def test_grid_equals_brute_force(sampler, n, r):
    p = stratum.points(sampler, n, 2, seed=5)
    got = stratum.local_discrepancy(p, r)
    assert got.shape == (r + 1, r + 1)
    np.testing.assert_allclose(got, brute_grid(p, r), rtol=0, atol=1e-14)


def test_grid_counts_half_open_boxes():
    p = np.array([[0.5, 0.5], [0.25, 0.75]])
    got = stratum.local_discrepancy(p, 4)
    # The corner (0.5, 0.5) does not count the point on it; (0.75, 0.75) does.
    assert got[2, 2] == pytest.approx(0 - 0.25, abs=1e-15)
    assert got[3, 3] == pytest.approx(0.5 - 0.5625, abs=1e-15)
    np.testing.assert_allclose(got, brute_grid(p, 4), atol=1e-15)


def test_jittered_grid_vanishes_on_its_strata_corners():
    # k × k jittered: [0, i/k) × [0, j/k) holds exactly i·j of the k² points.
    got = stratum.local_discrepancy(stratum.points("jittered", 64, 2, seed=2), 8)
    assert np.max(np.abs(got)) < 1e-15


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_star_box_matches_brute_force_and_star(seed):
    p = stratum.points("random", 9, 2, seed=seed)
    box = stratum.measure(p, "star-box")
    assert box["value"] == pytest.approx(brute_star(p), abs=1e-15)
    assert box["value"] == pytest.approx(stratum.measure(p, "star")["value"], abs=1e-15)
    e = box["extras"]
    if e["closed"]:
        inside = (p[:, 0] <= e["x"]) & (p[:, 1] <= e["y"])
    else:
        inside = (p[:, 0] < e["x"]) & (p[:, 1] < e["y"])
    assert inside.sum() == e["count"]
    assert abs(e["count"] / len(p) - e["x"] * e["y"]) == pytest.approx(box["value"], abs=1e-15)
    # The grid's largest |Δ| never exceeds D*.
    assert np.max(np.abs(stratum.local_discrepancy(p, 32))) <= box["value"] + 1e-15


def test_koksma_hlawka_errors_and_bounds():
    p = stratum.points("sobol", 256, 2, seed=3)
    x, y = p[:, 0], p[:, 1]
    r = stratum.measure(p, "koksma-hlawka")
    e = r["extras"]
    assert e["star"] == pytest.approx(stratum.measure(p, "star")["value"], abs=1e-15)
    e1 = math.e - 1
    exp_product = integrate.dblquad(lambda b, a: math.exp(a * b), 0, 1, 0, 1, epsabs=1e-13)[0]
    cases = {"xy": (x * y, 0.25, 3.0), "exp-sum": (np.exp(x + y), e1 ** 2, (e1 + math.e) ** 2 - math.e ** 2),
             "rational": (1 / ((1 + x) * (1 + y)), math.log(2) ** 2, 0.75),
             "sin-product": (np.sin(np.pi * x) * np.sin(np.pi * y), 4 / math.pi ** 2, 4.0),
             "exp-product": (np.exp(x * y), exp_product, 3 * e1)}
    worst = 0.0
    for name, (values, integral, variation) in cases.items():
        error = abs(values.mean() - integral)
        assert e["error:" + name] == pytest.approx(error, abs=1e-12), name
        assert e["bound:" + name] == pytest.approx(variation * e["star"], rel=1e-12), name
        worst = max(worst, error / (variation * e["star"]))
    assert e["holds"] == 5
    assert r["value"] == pytest.approx(worst, rel=1e-9) and r["value"] <= 1


@pytest.mark.parametrize("call,word", [
    (lambda: stratum.local_discrepancy(np.full((4, 3), 0.5), 4), "d = 3"),
    (lambda: stratum.local_discrepancy(np.full((4, 2), 0.5), 0), "resolution"),
    (lambda: stratum.local_discrepancy(np.full((4, 2), 0.5), 4097), "resolution"),
    (lambda: stratum.local_discrepancy(np.full((4, 2), 0.5), True), "resolution"),
    (lambda: stratum.local_discrepancy(np.array([[0.5, 1.5], [0.1, 0.2]]), 4), r"point\[0\]\[1\] = 1.5"),
    (lambda: stratum.measure(np.full((4, 3), 0.5), "star-box"), "star-box"),
])
def test_bad_input(call, word):
    with pytest.raises(stratum.InvalidArgument, match=word):
        call()
