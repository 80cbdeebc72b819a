"""The finite stratified and Latin patterns through stratum.points."""
import numpy as np
import pytest
from scipy.stats import qmc

import stratum


def cells(x, k):
    """Index of the 1/k interval of every value (values are in [0, 1))."""
    return np.floor(x * k).astype(np.int64)


def assert_latin(column, n):
    assert np.array_equal(np.sort(cells(column, n)), np.arange(n))


def test_pattern_entries_are_registered():
    info = {s["name"]: s for s in stratum.samplers()}
    for name in ["random", "grid", "jittered", "n-rooks", "latin-hypercube", "multi-jittered", "cmj",
                 "n-queens", "latin-square", "zaremba"]:
        assert info[name]["kind"] == "pattern"
    assert "alias" in info["latin-hypercube"]["description"]
    assert info["grid"]["randomizers"] == ["none", "cp"]
    assert info["zaremba"]["randomizers"] == ["none", "cp"]


def test_grid_values_exact():
    x = stratum.points("grid", 32, 2, strata="4x8")
    i = np.arange(32)
    assert np.array_equal(x[:, 0], ((i % 4) + 0.5) / 4)
    assert np.array_equal(x[:, 1], ((i // 4) + 0.5) / 8)
    y = stratum.points("grid", 27, 3)
    assert set(np.unique(y)) == {1 / 6, 0.5, 5 / 6}


@pytest.mark.parametrize("d, n, strata", [(1, 9, None), (2, 64, None), (2, 12, "3x4"), (3, 60, "3x4x5"), (4, 81, None)])
def test_jittered_one_point_per_stratum(d, n, strata):
    kwargs = {"strata": strata} if strata else {}
    x = stratum.points("jittered", n, d, seed=3, **kwargs)
    shape = [int(s) for s in strata.split("x")] if strata else [round(n ** (1 / d))] * d
    flat = np.ravel_multi_index(tuple(cells(x[:, j], shape[j]) for j in range(d)), shape)
    assert np.array_equal(np.sort(flat), np.arange(n))


def test_n_rooks_is_latin_and_latin_hypercube_is_its_alias():
    a = stratum.points("n-rooks", 500, 5, seed=9)
    b = stratum.points("latin-hypercube", 500, 5, seed=9)
    assert np.array_equal(a, b)
    for j in range(5):
        assert_latin(a[:, j], 500)
    assert not np.array_equal(a, stratum.points("n-rooks", 500, 5, seed=10))


def test_centered_n_rooks_has_scipys_centred_values():
    ours = stratum.points("n-rooks", 20, 3, seed=1, centered=True)
    theirs = qmc.LatinHypercube(d=3, scramble=False, seed=1).random(20)
    assert np.array_equal(np.sort(ours, axis=0), np.sort(theirs, axis=0))


@pytest.mark.parametrize("name, n, params, shape", [
    ("multi-jittered", 64, {}, (8, 8)),
    ("multi-jittered", 72, {}, (8, 9)),
    ("multi-jittered", 32, {"strata": "8x4"}, (8, 4)),
    ("cmj", 256, {}, (16, 16)),
    ("cmj", 90, {}, (9, 10)),
    ("cmj", 32, {"aspect": 2}, (8, 4)),
])
def test_multi_jittered_latin_and_stratified(name, n, params, shape):
    x = stratum.points(name, n, 2, seed=4, **params)
    assert_latin(x[:, 0], n)
    assert_latin(x[:, 1], n)
    m, k = shape
    flat = cells(x[:, 1], k) * m + cells(x[:, 0], m)
    assert np.array_equal(np.sort(flat), np.arange(n))


@pytest.mark.parametrize("method", ["random", "formula"])
@pytest.mark.parametrize("n", [1, 4, 5, 6, 7, 8, 9, 10, 49, 64, 100, 1000, 4096])
def test_n_queens_condition(n, method):
    """The queens' cells are those of the fixed n x n grid unrotated (none); the
    default, cp, rotates the whole pattern (so it is unbiased): the same cells
    then sit on the grid shifted by the rotation, wrapped."""
    for seed in range(3):
        x = stratum.points("n-queens", n, 2, seed=seed, method=method, randomize="none")
        col, row = cells(x[:, 0], n), cells(x[:, 1], n)
        assert len(set(col)) == n and len(set(row)) == n
        assert len(set(col - row)) == n and len(set(col + row)) == n
        rotated = stratum.points("n-queens", n, 2, seed=seed, method=method)
        shift = (rotated - x) % 1.0  # one rotation for every point
        assert np.allclose(shift, shift[0], atol=1e-12) or n == 1


def test_n_queens_random_is_default_deterministic_and_seeded():
    a = stratum.points("n-queens", 200, 2, seed=5)
    assert np.array_equal(a, stratum.points("n-queens", 200, 2, seed=5, method="random"))
    assert np.array_equal(a, stratum.points("n-queens", 200, 2, seed=5, threads=2))
    b = stratum.points("n-queens", 200, 2, seed=6)
    assert not np.array_equal(cells(a, 200), cells(b, 200))


def test_n_queens_random_is_spread_where_the_formula_is_not():
    """n = 256: fraction of the 16 x 16 coarse blocks holding a point (formula: 1/8, on two lines)."""
    def blocks(x):
        c = cells(x, 16)
        return len(set(c[:, 0] * 16 + c[:, 1])) / 256
    for seed in range(5):
        assert blocks(stratum.points("n-queens", 256, 2, seed=seed, method="formula")) < 0.2
        assert blocks(stratum.points("n-queens", 256, 2, seed=seed)) > 0.5


@pytest.mark.parametrize("method", ["jacobson-matthews", "permuted-cyclic"])
def test_latin_square_is_latin_and_an_orthogonal_array(method):
    m = 9
    x = stratum.points("latin-square", m * m, 3, seed=2, method=method)
    c = cells(x, m)
    for a, b in [(0, 1), (0, 2), (1, 2)]:
        assert np.array_equal(np.sort(c[:, a] * m + c[:, b]), np.arange(m * m))
    square = np.full((m, m), -1)
    square[c[:, 0], c[:, 1]] = c[:, 2]
    for r in range(m):
        assert sorted(square[r]) == list(range(m)) and sorted(square[:, r]) == list(range(m))


def test_zaremba_values_and_lower_discrepancy_than_hammersley():
    n = 256
    z = stratum.points("zaremba", n, 2)
    i = np.arange(n)
    folded = i ^ 0b10101010
    y = sum(((folded >> r) & 1) * 2.0 ** -(r + 1) for r in range(8))
    assert np.array_equal(z[:, 0], i / n)
    assert np.array_equal(z[:, 1], y)
    h = stratum.points("hammersley", n, 2, randomize="none")
    assert qmc.discrepancy(z, method="L2-star") < 0.8 * qmc.discrepancy(h, method="L2-star")


@pytest.mark.parametrize("name, n, d, params, words", [
    ("grid", 10, 2, {}, ["n = 10", "9 = 3^2", "16 = 4^2"]),
    ("jittered", 30, 3, {}, ["n = 30", "27 = 3^3", "64 = 4^3"]),
    ("grid", 32, 2, {"strata": "4x4"}, ["n = 32", "strata=4x4"]),
    ("n-queens", 3, 2, {}, ["n = 3", "n = 1 or n >= 4"]),
    ("latin-square", 50, 3, {}, ["n = 50", "m^2", "49, 64"]),
    ("multi-jittered", 30, 2, {"strata": "4x8"}, ["n = 30", "strata=4x8"]),
    ("latin-square", 16, 3, {"method": "magic"}, ["method = magic"]),
    ("n-queens", 16, 2, {"method": "magic"}, ["method = magic", "must be one of random, formula"]),
    ("n-queens", 2 ** 24 + 1, 2, {}, ["n = 16777217", "method=formula"]),
])
def test_bad_counts_name_n_and_the_allowed_values(name, n, d, params, words):
    with pytest.raises(stratum.InvalidArgument) as error:
        stratum.points(name, n, d, **params)
    for word in words:
        assert word in str(error.value)


def test_unbiased_over_seeds():
    """Mean of 200 seeds' estimates of the integral of exp(x) (1 + y^2) = (e - 1) 4/3,
    two-sided z-test per sampler at Sidak level for family alpha = 0.001."""
    cases = [("jittered", 16, {}), ("n-rooks", 16, {}), ("multi-jittered", 12, {}), ("cmj", 12, {}),
             ("n-queens", 5, {"method": "formula"}),
             ("n-queens", 64, {"randomize": "cp"}), ("grid", 16, {"randomize": "cp"}), ("zaremba", 16, {"randomize": "cp"})]
    from scipy.stats import t as student
    alpha = 1 - (1 - 0.001) ** (1 / len(cases))
    truth = (np.e - 1) * 4 / 3
    for name, n, kwargs in cases:
        estimates = []
        for seed in range(200):
            x = stratum.points(name, n, 2, seed=seed, **kwargs)
            estimates.append(np.mean(np.exp(x[:, 0]) * (1 + x[:, 1] ** 2)))
        estimates = np.array(estimates)
        t = (estimates.mean() - truth) / (estimates.std(ddof=1) / np.sqrt(len(estimates)))
        assert abs(t) < student.ppf(1 - alpha / 2, len(estimates) - 1), (name, t)
