"""Halton and Hammersley points and their base-b randomizers, checked against
scipy.stats.qmc.Halton and exact rational arithmetic."""
from fractions import Fraction

import numpy as np
import pytest
from scipy import stats
from scipy.stats import qmc

import stratum

PRIMES = [2, 3, 5, 7, 11, 13, 17, 19, 23, 29]
RANDOMIZERS = ["permute", "none", "owen", "xor", "cp"]


def exact_radical_inverse(base, index):
    value, scale = Fraction(0), Fraction(1, base)
    while index:
        value += (index % base) * scale
        index //= base
        scale /= base
    return value


def test_randomizers_and_default():
    info = {s["name"]: s for s in stratum.samplers()}
    assert info["halton"]["randomizers"] == RANDOMIZERS
    assert info["hammersley"]["randomizers"] == RANDOMIZERS
    assert np.array_equal(stratum.points("halton", 500, 4, seed=3), stratum.points("halton", 500, 4, seed=3, randomize="permute"))


def test_unscrambled_is_correctly_rounded():
    # stratum's radical inverse is the exact value rounded once (Fraction ->
    # float rounds correctly), so equality is exact.
    x = stratum.points("halton", 3000, 10, randomize="none")
    rng = np.random.default_rng(1)
    for _ in range(400):
        i, j = int(rng.integers(3000)), int(rng.integers(10))
        assert x[i, j] == float(exact_radical_inverse(PRIMES[j], i)), (i, j)


@pytest.mark.parametrize("start", [0, 12345])
def test_unscrambled_matches_scipy(start):
    # scipy sums digits in floating point, so it is off the correctly rounded
    # value by up to ~2.3 ulp: the two agree exactly in base 2 and to within
    # 4 ulp elsewhere (about 60% of the values agree exactly).
    n, d = 20000, 10
    ours = stratum.points("halton", n, d, randomize="none", start=start)
    engine = qmc.Halton(d, scramble=False)
    engine.fast_forward(start)
    theirs = engine.random(n)
    assert np.array_equal(ours[:, 0], theirs[:, 0])
    ulps = np.abs(ours - theirs) / np.spacing(np.maximum(ours, theirs).clip(np.finfo(float).tiny))
    assert ulps.max() <= 4
    assert np.mean(ours == theirs) > 0.4


@pytest.mark.parametrize("randomize", ["none", "permute", "owen", "xor"])
def test_mixed_base_elementary_intervals(randomize):
    # The first 2^i 3^j points: one point in each 2^-i x 3^-j box of
    # dimensions (0, 1); the first 2^i 5^j, in each 2^-i x 5^-j box of (0, 2).
    x = stratum.points("halton", 1000, 3, seed=11, randomize=randomize)
    nudge = 1e-9 if randomize == "none" else 0.0  # unscrambled points sit on box corners
    for dim, base, top in ((1, 3, 3), (2, 5, 2)):
        for i in range(6):
            for j in range(top + 1):
                nx, ny = 2**i, base**j
                n = nx * ny
                bx = np.floor(x[:n, 0] * nx + nudge).astype(int)
                by = np.floor(x[:n, dim] * ny + nudge).astype(int)
                assert np.array_equal(np.bincount(by * nx + bx, minlength=n), np.ones(n, dtype=int)), (dim, i, j)


def test_cranley_patterson_keeps_one_dimensional_strata():
    x = stratum.points("halton", 3125, 3, seed=2, randomize="cp")
    for dim, base in enumerate(PRIMES[:3]):
        n = base
        while n <= 3125:
            assert np.array_equal(np.bincount(np.floor(x[:n, dim] * n).astype(int), minlength=n), np.ones(n, dtype=int))
            n *= base


def _f(x):
    return np.prod(1 + (x - 0.5) * np.array([1.0, 0.8, 0.6, 0.4])[: x.shape[1]], axis=1) + x[:, 0] ** 2


def _estimates(make, seeds):
    return np.array([_f(make(seed)).mean() for seed in seeds])


def test_scrambled_estimates_are_unbiased_like_scipy():
    # f(x) = prod(1 + c_j (x_j - 1/2)) + x_0^2, integral 1 + 1/3. Over 300
    # seeds: a two-sided t-test of the mean estimate for stratum's four
    # randomizers and scipy's scramble=True, and an F-test that stratum's
    # permute and scipy's scramble (the same random digit permutations) have
    # the same variance. 6 tests at family-wise alpha = 1e-3 (Sidak).
    n, d, seeds = 64, 4, range(300)
    level = 1 - (1 - 1e-3) ** (1 / 6)
    exact = 1 + 1 / 3
    runs = {r: _estimates(lambda s, r=r: stratum.points("halton", n, d, seed=s, randomize=r), seeds)
            for r in ["permute", "owen", "xor", "cp"]}
    runs["scipy"] = _estimates(lambda s: qmc.Halton(d, scramble=True, seed=s).random(n), seeds)
    for name, q in runs.items():
        assert q.std() > 0, name
        assert stats.ttest_1samp(q, exact).pvalue > level, name
    ratio = runs["permute"].var(ddof=1) / runs["scipy"].var(ddof=1)
    dof = len(seeds) - 1
    p = 2 * min(stats.f.cdf(ratio, dof, dof), stats.f.sf(ratio, dof, dof))
    assert p > level, ratio


def test_scrambled_coordinates_are_uniform_over_seeds():
    # For a fixed index (start=index, n=1) each coordinate is uniform over
    # 400 seeds: Kolmogorov-Smirnov for 3 randomizers x 2 indices x 3
    # dimensions = 18 tests at family-wise alpha = 1e-3 (Sidak).
    level = 1 - (1 - 1e-3) ** (1 / 18)
    for randomize in ["permute", "owen", "xor"]:
        for index in [0, 2**33 + 7]:
            x = np.array([stratum.points("halton", 1, 3, seed=s, randomize=randomize, start=index)[0]
                          for s in range(400)])
            for dim in range(3):
                assert stats.kstest(x[:, dim], "uniform").pvalue > level, (randomize, index, dim)


def test_seeds_and_start_past_two_to_the_32():
    a = stratum.points("halton", 100, 5, seed=1)
    b = stratum.points("halton", 100, 5, seed=2)
    assert not np.any(a == b)
    far = stratum.points("halton", 50, 5, seed=1, start=2**32 + 50)
    longer = stratum.points("halton", 100, 5, seed=1, start=2**32)
    assert np.array_equal(far, longer[50:])
    assert not np.array_equal(far, stratum.points("halton", 50, 5, seed=1, start=50))


@pytest.mark.parametrize("randomize", RANDOMIZERS)
def test_hammersley_first_dimension(randomize):
    """i/N is kept only by none; cp keeps it Latin at any n, the base-2 digit
    randomizers (permute = xor, owen) at n = 2^k; the other coordinates are Halton's."""
    for n in (243, 256):
        x = stratum.points("hammersley", n, 3, seed=4, randomize=randomize)
        assert np.all((x >= 0) & (x < 1))
        nudge = 1e-9 if randomize == "none" else 0  # i/N sits on the stratum edges
        latin = np.array_equal(np.bincount(np.floor(x[:, 0] * n + nudge).astype(int), minlength=n), np.ones(n, dtype=int))
        if randomize == "none":
            assert np.array_equal(x[:, 0], np.arange(n) / n)
        else:
            assert not np.array_equal(x[:, 0], np.arange(n) / n)
            assert not np.array_equal(x[:, 0], stratum.points("hammersley", n, 3, seed=5, randomize=randomize)[:, 0])
        assert latin or (n == 243 and randomize in ("permute", "xor", "owen"))
        if randomize != "cp":
            halton = stratum.points("hammersley", n, 2, seed=4, randomize=randomize)
            assert np.array_equal(x[:, :2], halton)
            assert np.array_equal(x[:, 1:], stratum.points("halton", n, 2, seed=4, randomize=randomize))


def test_hammersley_estimates_are_unbiased():
    """x_0 < 0.3 among n = 4 points: 1/2 for i/N, 0.3 in expectation once x_0 is uniform (z-test, 3000 seeds)."""
    for randomize in ("permute", "owen"):
        f = np.array([np.mean(stratum.points("hammersley", 4, 2, seed=s, randomize=randomize)[:, 0] < 0.3)
                      for s in range(3000)])
        assert abs(f.mean() - 0.3) < 3.9 * f.std(ddof=1) / np.sqrt(len(f)), (randomize, f.mean())


def test_radical_inverse_in_any_base():
    """halton(bases=...): φ_b(i) in the given bases, the slide's radical inverse in any base."""
    i = np.arange(200)

    def phi(b, k):
        x, f = 0.0, 1.0 / b
        while k:
            x += (k % b) * f
            k //= b
            f /= b
        return x

    for b in (3, 10, 12):
        x = stratum.points("halton", 200, 1, randomize="none", bases=[b])[:, 0]
        np.testing.assert_allclose(x, [phi(b, k) for k in i], rtol=0, atol=1e-15)
    two = stratum.points("halton(bases=6,7)", 64, 2, randomize="none")
    np.testing.assert_allclose(two[:, 1], [phi(7, k) for k in range(64)], rtol=0, atol=1e-15)
    with pytest.raises(stratum.InvalidArgument, match=r"invalid bases = \(1 value\): give one base per dimension"):
        stratum.points("halton", 4, 2, bases=[3])
