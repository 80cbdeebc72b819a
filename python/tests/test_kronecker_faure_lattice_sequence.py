"""kronecker, faure and lattice-sequence through stratum.points."""
from fractions import Fraction
from itertools import product
from math import floor

import numpy as np
import pytest

import stratum


def test_kronecker_is_r_d_and_takes_alpha():
    x = stratum.points("kronecker", 1000, 2, randomize="none")
    rho = np.polynomial.polynomial.polyroots([-1, -1, 0, 1]).real.max()  # plastic number: x^3 = x + 1
    assert x[1] == pytest.approx([1 / rho, 1 / rho**2], abs=1e-15)
    i = np.arange(1000)
    assert np.allclose(x, (i[:, None] * np.array([1 / rho, 1 / rho**2])) % 1.0, atol=1e-12)
    # A user's alpha and offset, as a list of reals; exact for dyadic alpha.
    y = stratum.points("kronecker", 8, 2, alpha=[0.25, 0.375], offset=0.5)
    assert np.array_equal(y[:, 0], (0.5 + 0.25 * np.arange(8)) % 1.0)
    assert np.array_equal(y[:, 1], (0.5 + 0.375 * np.arange(8)) % 1.0)
    # cp rotates each coordinate by one shift.
    z = stratum.points("kronecker", 1000, 2, randomize="cp", seed=4)
    shift = (z - x) % 1.0
    assert np.allclose(shift, shift[0], atol=1e-12)


@pytest.mark.parametrize(
    "kwargs, word",
    [(dict(alpha=[0.5]), "invalid alpha"), (dict(alpha=[0.5, 1.5]), r"invalid alpha\[1\] = 1.5: must be a finite real in \(0, 1\)"), (dict(offset=1), "invalid offset")],
)
def test_kronecker_bad_parameters(kwargs, word):
    with pytest.raises(ValueError, match=word):
        stratum.points("kronecker", 4, 2, **kwargs)


def _faure_oracle(i, j, b):
    """Coordinate j of Faure point i by definition, as an exact fraction."""
    digits = []
    while i:
        digits.append(i % b)
        i //= b
    from math import comb

    x = Fraction(0)
    for r in range(len(digits)):
        y = sum(comb(c, r) * j ** (c - r) * digits[c] for c in range(r, len(digits))) % b
        x += Fraction(y, b ** (r + 1))
    return x


def test_faure_matches_the_definition_and_is_a_net():
    b, s = 5, 4  # base: the smallest prime >= 4
    x = stratum.points("faure", 625, s, randomize="none", start=625)
    for i in range(0, 625, 37):
        for j in range(s):
            assert x[i, j] == pytest.approx(float(_faure_oracle(625 + i, j, b)), abs=1e-16)
    # (0, 4, 4)-net in base 5 under owen: one point per elementary interval.
    y = stratum.points("faure", 625, s, randomize="owen", seed=3)
    for k in product(range(5), repeat=s):
        if sum(k) != 4:
            continue
        cells = np.zeros(len(y), dtype=np.int64)
        for j in range(s):
            cells = cells * b ** k[j] + np.floor(y[:, j] * b ** k[j]).astype(np.int64)
        assert np.array_equal(np.sort(cells), np.arange(625)), k
    assert stratum.points("faure", 4, 3, seed=1).shape == (4, 3)
    with pytest.raises(ValueError, match="randomize"):
        stratum.points("faure", 4, 3, randomize="owen-hash")


def test_lattice_sequence_prefixes_are_lattices():
    x = stratum.points("lattice-sequence", 1024, 4, randomize="none")
    g = [1, 182667, 469891, 498753]
    for m in (3, 7, 10):
        n = 2**m
        lattice = (np.arange(n)[:, None] * (np.array(g) % n)[None, :] % n) / n
        assert np.array_equal(np.unique(x[:n], axis=0), np.unique(lattice, axis=0)), m
    y = stratum.points("lattice-sequence", 4, 2, generator=[1, 3], randomize="none")
    assert np.array_equal(y, [[0, 0], [0.5, 0.5], [0.25, 0.75], [0.75, 0.25]])
    with pytest.raises(ValueError, match="invalid d"):
        stratum.points("lattice-sequence", 4, 33)
    with pytest.raises(ValueError, match="invalid generator"):
        stratum.points("lattice-sequence", 4, 2, generator=[1, 0])


@pytest.mark.parametrize("name", ["kronecker", "lattice-sequence", "faure"])
def test_randomized_estimates_are_unbiased(name):
    """Mean over 200 seeds of a 64-point estimate of the integral of x0 x1^2 exp(x2), (e - 1)/6:
    a two-sided z-test at alpha = 1e-3 per sampler (3 samplers: family-wise < 3e-3)."""
    randomize = "owen" if name == "faure" else "cp"
    estimates = []
    for seed in range(200):
        p = stratum.points(name, 64, 3, seed=seed + 11, randomize=randomize)
        estimates.append(np.mean(p[:, 0] * p[:, 1] ** 2 * np.exp(p[:, 2])))
    estimates = np.array(estimates)
    z = (estimates.mean() - (np.e - 1) / 6) / (estimates.std(ddof=1) / np.sqrt(len(estimates)))
    assert abs(z) < 3.29, z
