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
    (lambda: stratum.local_discrepancy(np.empty((0, 2)), 4), "invalid n = 0"),
    (lambda: stratum.local_discrepancy(np.array([[0.5, 0.5]]), 4), "invalid n = 1"),
    (lambda: stratum.local_discrepancy(np.full((4, 2), np.nan), 4), r"point\[0\]\[0\] = nan"),
    (lambda: stratum.measure(np.full((4, 3), 0.5), "star-box"), "star-box"),
])
def test_bad_input(call, word):
    with pytest.raises(stratum.InvalidArgument, match=word):
        call()


# stratum.star_discrepancy_box, stratum.koksma_hlawka, stratum.variation_test_functions.

E1 = math.e - 1
# name: (f, integral, V_HK) with V_HK of a product g(x)h(y) = (V(g)+|g(1)|)(V(h)+|h(1)|) - |g(1)h(1)|
# (Owen 2005, "Multidimensional variation for quasi-Monte Carlo", eq. (12)).
CLOSED_FORMS = {
    "xy": (lambda x, y: x * y, 0.25, 2 * 2 - 1),
    "exp-sum": (lambda x, y: np.exp(x + y), E1 ** 2, (E1 + math.e) ** 2 - math.e ** 2),
    "rational": (lambda x, y: 1 / ((1 + x) * (1 + y)), math.log(2) ** 2, 1 - 0.25),
    "sin-product": (lambda x, y: np.sin(np.pi * x) * np.sin(np.pi * y), 4 / math.pi ** 2, 2 * 2),
    "exp-product": (lambda x, y: np.exp(x * y),
                    integrate.dblquad(lambda b, a: math.exp(a * b), 0, 1, 0, 1, epsabs=1e-13)[0], 3 * E1),
}


@pytest.mark.parametrize("sampler,n,seed", [("random", 7, 1), ("random", 12, 2), ("halton", 10, 0), ("sobol", 16, 3),
                                            ("jittered", 9, 4)])
def test_star_discrepancy_box_matches_brute_force(sampler, n, seed):
    p = stratum.points(sampler, n, 2, seed=seed)
    box = stratum.star_discrepancy_box(p)
    assert set(box) == {"value", "x", "y", "closed", "count"}
    assert isinstance(box["closed"], bool) and isinstance(box["count"], int)
    assert box["value"] == pytest.approx(brute_star(p), abs=1e-15)
    # The box's sweep rounds count/N differently from the exact D* methods: equal to an ulp or so.
    assert box["value"] == pytest.approx(stratum.discrepancy(p, "star"), abs=1e-15)
    if box["closed"]:  # too many points: the upper edges count
        inside = (p[:, 0] <= box["x"]) & (p[:, 1] <= box["y"])
        assert box["count"] / n - box["x"] * box["y"] == pytest.approx(box["value"], abs=1e-15)
    else:
        inside = (p[:, 0] < box["x"]) & (p[:, 1] < box["y"])
        assert box["x"] * box["y"] - box["count"] / n == pytest.approx(box["value"], abs=1e-15)
    assert inside.sum() == box["count"]


def test_star_discrepancy_box_of_a_known_set():
    # One point at (1/2, 1/2) twice: [0,1)² holds both, volume 1 → Δ = 0; the
    # closed box [0,1/2]² holds both with volume 1/4 → D* = 3/4 (approached from above).
    box = stratum.star_discrepancy_box([[0.5, 0.5], [0.5, 0.5]])
    assert box == {"value": 0.75, "x": 0.5, "y": 0.5, "closed": True, "count": 2}


def test_variation_test_functions_closed_forms():
    rows = stratum.variation_test_functions()
    assert [row["function"] for row in rows] == list(CLOSED_FORMS)
    for row in rows:
        _, integral, variation = CLOSED_FORMS[row["function"]]
        assert row["integral"] == pytest.approx(integral, abs=1e-13)
        assert row["variation"] == pytest.approx(variation, rel=1e-14)
        assert row["formula"] and row["derivation"]


@pytest.mark.parametrize("sampler,n", [("sobol", 256), ("random", 100), ("halton", 64)])
def test_koksma_hlawka_against_numpy(sampler, n):
    p = stratum.points(sampler, n, 2, seed=7)
    star = brute_star(p)
    rows = stratum.koksma_hlawka(p)
    assert [row["function"] for row in rows] == list(CLOSED_FORMS)
    for row in rows:
        f, integral, variation = CLOSED_FORMS[row["function"]]
        mean = f(p[:, 0], p[:, 1]).mean()
        assert row["star"] == pytest.approx(star, abs=1e-15) and row["star_kind"] == "exact"
        assert row["estimate"] == pytest.approx(mean, abs=1e-13)
        assert row["error"] == pytest.approx(abs(mean - integral), abs=1e-13)
        assert row["bound"] == pytest.approx(variation * star, rel=1e-13)
        # The inequality itself (Niederreiter 1992, Thm. 2.11), checked here with numpy's numbers.
        assert abs(mean - integral) <= variation * star and row["holds"]


def test_koksma_hlawka_with_a_given_star():
    p = stratum.points("random", 40, 2, seed=11)
    tiny = 1e-4  # far below D* of 40 points (at least 1/(2·40)): the bound must fail for some function
    rows = stratum.koksma_hlawka(p, star_discrepancy=tiny)
    failing = 0
    for row in rows:
        f, integral, variation = CLOSED_FORMS[row["function"]]
        error = abs(f(p[:, 0], p[:, 1]).mean() - integral)
        assert row["star"] == tiny and row["star_kind"] == "given"
        assert row["bound"] == pytest.approx(variation * tiny, rel=1e-14)
        assert row["holds"] == (error <= variation * tiny)
        failing += not row["holds"]
    assert failing > 0
    # Given the exact D*, the rows are those computed with it.
    assert stratum.koksma_hlawka(p, brute_star(p))[0]["bound"] == pytest.approx(rows[0]["bound"] / tiny * brute_star(p))


@pytest.mark.parametrize("call,word", [
    (lambda: stratum.star_discrepancy_box(np.full((4, 3), 0.5)), "d = 3"),
    (lambda: stratum.star_discrepancy_box(np.empty((0, 2))), "n = 0"),
    (lambda: stratum.star_discrepancy_box(np.random.default_rng(0).random((20001, 2))), "n = 20001"),
    (lambda: stratum.koksma_hlawka(np.full((4, 3), 0.5)), "d = 3"),
    (lambda: stratum.koksma_hlawka(np.empty((0, 2))), "n = 0"),
    (lambda: stratum.koksma_hlawka(np.empty((0, 2)), 0.1), "n = 0"),  # a given D* skips the star measure
    (lambda: stratum.koksma_hlawka(np.full((4, 2), 0.5), -0.1), r"star_discrepancy = -0.1"),
    (lambda: stratum.star_discrepancy_box(np.full((4, 2), 0.5), threads=-1), "threads = -1"),
    (lambda: stratum.koksma_hlawka(np.array([[0.5, 0.5]])), "n = 1"),
    (lambda: stratum.koksma_hlawka(np.array([[0.5, -0.1], [0.1, 0.2]])), r"point\[0\]\[1\] = -0.1"),
    (lambda: stratum.koksma_hlawka(np.full((4, 2), 0.5), 1.5), "star_discrepancy = 1.5"),
    (lambda: stratum.koksma_hlawka(np.full((4, 2), 0.5), float("nan")), "star_discrepancy = nan"),
    (lambda: stratum.koksma_hlawka(np.full((4, 2), 0.5), "0.1"), "star_discrepancy = '0.1'"),
    (lambda: stratum.koksma_hlawka(np.full((4, 2), 0.5), True), "star_discrepancy = True"),
])
def test_bad_input_of_box_and_koksma_hlawka(call, word):
    with pytest.raises(stratum.InvalidArgument, match=word):
        call()
