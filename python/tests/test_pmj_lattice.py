"""pmj02, fibonacci and lattice through stratum.points."""
from fractions import Fraction
from math import gcd

import numpy as np
import pytest

import stratum


def _elementary_interval_counts(points, k, a):
    """Occupancy of the 2^a x 2^(k-a) elementary intervals."""
    bx = np.floor(points[:, 0] * 2**a).astype(np.int64)
    by = np.floor(points[:, 1] * 2 ** (k - a)).astype(np.int64)
    return np.bincount(by * 2**a + bx, minlength=2**k)


@pytest.mark.parametrize("seed", [0, 1, 12345])
def test_pmj02_prefixes_are_zero_k_two_nets(seed):
    x = stratum.points("pmj02", 4096, 2, seed=seed)
    for k in range(13):
        prefix = x[: 2**k]
        for a in range(k + 1):
            assert np.all(_elementary_interval_counts(prefix, k, a) == 1), (seed, k, a)


def test_pmj02_aligned_blocks_and_start():
    full = stratum.points("pmj02", 2048, 4, seed=9)
    block = stratum.points("pmj02", 1024, 4, seed=9, start=1024)
    assert np.array_equal(full[1024:], block)
    for a in range(11):
        assert np.all(_elementary_interval_counts(block[:, :2], 10, a) == 1)
    # Pair (2, 3) is a net at every power-of-two prefix too.
    for k in (4, 8, 11):
        for a in range(k + 1):
            assert np.all(_elementary_interval_counts(full[: 2**k, 2:], k, a) == 1)


def test_pmj02_seeds_differ_and_replay():
    a = stratum.points("pmj02", 256, 2, seed=1)
    assert np.array_equal(a, stratum.points("pmj02", 256, 2, seed=1, threads=2))
    assert not np.any(a == stratum.points("pmj02", 256, 2, seed=2))


def test_pmj02_unbiased_over_seeds():
    # 200 independent 16-point estimates of the integral of x*y (= 1/4);
    # |z| < 3.89 is a two-sided test at p = 1e-4.
    estimates = np.array([np.mean(np.prod(stratum.points("pmj02", 16, 2, seed=s), axis=1)) for s in range(200)])
    z = (estimates.mean() - 0.25) / (estimates.std(ddof=1) / np.sqrt(200))
    assert abs(z) < 3.89


def test_pmj02_rejects_cp():
    with pytest.raises(ValueError, match="randomize"):
        stratum.points("pmj02", 16, 2, randomize="cp")


def test_fibonacci_exact_and_latin():
    n, g = 987, 610
    x = stratum.points("fibonacci", n, 2)
    i = np.arange(n)
    assert np.array_equal(x[:, 0], i / n)
    assert np.array_equal(x[:, 1], (i * g % n) / n)
    # Exact rational check of one point, independent of floating point.
    assert Fraction(x[123, 1]).limit_denominator(n) == Fraction(123 * g % n, n)
    for randomize in ("none", "cp"):
        y = stratum.points("fibonacci", n, 2, seed=4, randomize=randomize)
        cells = np.rint(y * n) if randomize == "none" else np.floor(y * n)
        for column in range(2):
            assert np.array_equal(np.sort(cells[:, column]), np.arange(n)), randomize


def test_fibonacci_any_n_and_strict():
    x = stratum.points("fibonacci", 100, 2)
    assert x[1, 1] == 0.61  # nearest integer to 100/phi coprime to 100 is 61
    with pytest.raises(ValueError, match=r"invalid n = 100.*89 or 144"):
        stratum.points("fibonacci", 100, 2, strict=True)
    assert stratum.points("fibonacci", 144, 2, strict=True).shape == (144, 2)


def test_lattice_generator_and_korobov_values():
    n = 1021
    x = stratum.points("lattice", n, 3, generator=[1, 306, 542])
    i = np.arange(n)
    for j, z in enumerate([1, 306, 542]):
        assert np.array_equal(x[:, j], (i * z % n) / n)
    y = stratum.points("lattice", n, 4, a=76)
    for j in range(4):
        assert np.array_equal(y[:, j], (i * pow(76, j, n) % n) / n)


def _error2(n, z):
    """Squared worst-case error in the Korobov space (alpha = 2, weights 1)."""
    x = (np.arange(n)[:, None] * np.asarray(z)[None, :] % n) / n
    return np.mean(np.prod(1 + 2 * np.pi**2 * (x * x - x + 1 / 6), axis=1)) - 1


def test_lattice_search_beats_random_vectors():
    n, d = 1009, 4
    x = stratum.points("lattice", n, d)
    a = int(round(x[1, 1] * n))
    assert gcd(a, n) == 1
    z = [pow(a, j, n) for j in range(d)]
    assert np.array_equal(x, (np.arange(n)[:, None] * np.array(z)[None, :] % n) / n)
    rng = np.random.default_rng(3)
    random_scores = [_error2(n, rng.integers(1, n, size=d)) for _ in range(101)]
    assert _error2(n, z) < np.median(random_scores)
    # Brute force over every Korobov parameter: the search found the minimum.
    assert _error2(n, z) <= min(_error2(n, [pow(b, j, n) for j in range(d)]) for b in range(1, n)) + 1e-12
    # cp rotates each coordinate by one shift.
    shifted = stratum.points("lattice", n, d, seed=8, randomize="cp")
    shift = (shifted - x) % 1.0
    assert np.allclose(shift, shift[0], atol=1e-12)


@pytest.mark.parametrize(
    "kwargs, word",
    [
        (dict(generator=[1, 55]), "invalid generator"),
        (dict(generator=[1, 0, 3]), r"invalid generator\[1\] = 0: must be an integer in \[1, inf\)"),
        (dict(generator=[1, 89, 3]), r"\[1, 89\)"),
        (dict(a=0), "invalid a"),
        (dict(a=55, generator=[1, 2, 3]), "not both"),
        (dict(gamma=0), "invalid gamma"),
    ],
)
def test_lattice_bad_parameters(kwargs, word):
    with pytest.raises(ValueError, match=word):
        stratum.points("lattice", 89, 3, **kwargs)


def test_pmj02bn_nets_start_and_spread():
    x = stratum.points("pmj02bn", 1024, 2, seed=4)
    for k in range(11):
        for a in range(k + 1):
            assert np.all(_elementary_interval_counts(x[: 2**k], k, a) == 1), (k, a)
    assert np.array_equal(stratum.points("pmj02bn", 512, 2, seed=4, start=512), x[512:])
    assert np.array_equal(stratum.points("pmj02bn", 100, 1, seed=4), x[:100, :1])

    def nearest(p):
        d = p[:, None, :] - p[None, :, :]
        d -= np.round(d)
        r = np.sqrt((d**2).sum(-1))
        np.fill_diagonal(r, 9)
        return r.min(1).mean()

    # more candidates, points further apart: one-sided paired t-test over 20 seeds at level 0.001
    # (measured gain ~6% of the mean nearest-neighbour distance, t ~ 5)
    from scipy import stats
    gains = [nearest(stratum.points("pmj02bn", 128, 2, seed=s))
             - nearest(stratum.points("pmj02bn", 128, 2, seed=s, candidates=1)) for s in range(20)]
    assert stats.ttest_1samp(gains, 0.0, alternative="greater").pvalue < 0.001, gains
    with pytest.raises(stratum.InvalidArgument, match="candidates"):
        stratum.points("pmj02bn", 8, 2, candidates=0)
    with pytest.raises(stratum.InvalidArgument, match="d"):
        stratum.points("pmj02bn", 8, 3)
