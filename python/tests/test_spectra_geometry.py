"""stratum.spectrum, stratum.pair_correlation and the geometry measures
(t-value, latin, min-distance, poisson-radius) through stratum.measure:
closed forms, brute force with numpy, and bad input."""
import math

import numpy as np
import pytest

import stratum


def grid(m):
    c = (np.arange(m) + 0.5) / m
    return np.array([(x, y) for x in c for y in c])


def numpy_periodogram(x, k):
    """Direct sum with numpy: P(k) = |Σ_j exp(−2πi k·x_j)|² / N on [−K, K]²."""
    f = np.arange(-k, k + 1)
    ex = np.exp(-2j * np.pi * np.outer(x[:, 0], f))  # (n, 2K+1)
    ey = np.exp(-2j * np.pi * np.outer(x[:, 1], f))
    s = ey.T @ ex  # s[ky, kx] = Σ_j ey[j, ky] ex[j, kx]
    return np.abs(s) ** 2 / len(x)


def test_spectrum_matches_numpy_direct_sum():
    rng = np.random.default_rng(4)
    x = rng.random((200, 2))
    s = stratum.spectrum(x, max_frequency=20, threads=2)
    np.testing.assert_allclose(s["power"], numpy_periodogram(x, 20), rtol=1e-9, atol=1e-9)
    assert s["power"][20, 20] == pytest.approx(200, rel=1e-12)
    np.testing.assert_allclose(s["frequencies"], np.arange(-20, 21) / math.sqrt(200))
    # Several realizations: the mean of the periodograms.
    xs = [rng.random((50, 2)) for _ in range(3)]
    mean = sum(numpy_periodogram(a, 8) for a in xs) / 3
    np.testing.assert_allclose(stratum.spectrum(xs, max_frequency=8)["power"], mean, rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(stratum.spectrum(np.stack(xs), max_frequency=8)["power"], mean, rtol=1e-9, atol=1e-9)


def test_grid_spectrum_closed_form():
    s = stratum.spectrum(grid(8), max_frequency=20)
    k = np.arange(-20, 21)
    peak = (k[:, None] % 8 == 0) & (k[None, :] % 8 == 0)
    np.testing.assert_allclose(s["power"], np.where(peak, 64.0, 0.0), atol=1e-9 * 64)
    assert s["nyquist"] == pytest.approx(7 / 16)
    assert s["radial"]["frequency"][7] == 1.0


def test_uniform_random_mean_power_is_one():
    # E P(k) = 1 for k ≠ 0, Var = 1 − 1/N, uncorrelated across k ≠ ±l: the mean
    # over h = 544 distinct frequencies and R = 20 realizations has sd ≈ 0.0096;
    # 4.89 sd is a two-sided test at α = 1e-6.
    rng = np.random.default_rng(8)
    xs = rng.random((20, 64, 2))
    p = stratum.spectrum(xs, max_frequency=16)["power"]
    half = np.concatenate([p[17:, :].ravel(), p[16, 17:]])  # ky > 0, or ky = 0 and kx > 0
    assert len(half) == 544
    sd = math.sqrt((1 - 1 / 64) / (544 * 20))
    assert abs(half.mean() - 1) < 4.89 * sd


def test_spectrum_1d_and_bad_input():
    x = (np.arange(10) + 0.5) / 10
    s = stratum.spectrum(x, max_frequency=25)
    assert s["power"].shape == (51,)
    expected = np.where(np.arange(-25, 26) % 10 == 0, 10.0, 0.0)
    np.testing.assert_allclose(s["power"], expected, atol=1e-9)
    with pytest.raises(stratum.InvalidArgument, match="invalid max_frequency = 0"):
        stratum.spectrum(grid(4), max_frequency=0)
    with pytest.raises(stratum.InvalidArgument, match="at most 2\\^25"):
        stratum.spectrum(grid(4), max_frequency=5000)
    with pytest.raises(stratum.InvalidArgument, match="invalid d = 3"):
        stratum.spectrum(np.full((10, 3), 0.5), max_frequency=4)
    with pytest.raises(stratum.InvalidArgument, match="same"):
        stratum.spectrum([np.full((10, 2), 0.5), np.full((9, 2), 0.5)], max_frequency=4)
    with pytest.raises(stratum.InvalidArgument, match=r"point\[1\]\[0\]"):
        stratum.spectrum(np.array([[0.1, 0.2], [np.nan, 0.3]]), max_frequency=4)
    with pytest.raises(stratum.InvalidArgument, match="invalid threads"):
        stratum.spectrum(grid(4), max_frequency=4, threads=-1)


def test_pair_correlation():
    # Two points at toroidal distance 0.15: g(r) = 2 k_σ(r − 0.15) / (N(N−1) D(r)),
    # D(r) = ∫ k_σ(r − t) 2πt dt over t ≥ 0, |r − t| < 4σ (what white noise puts
    # under the kernel), here by scipy's quad.
    from scipy.integrate import quad

    x = np.array([[0.1, 0.2], [0.95, 0.2]])
    r = np.array([0.005, 0.13, 0.15, 0.17])
    sigma = 0.01
    g = stratum.pair_correlation(x, radii=r, sigma=sigma)
    kernel = np.exp(-0.5 * ((r - 0.15) / sigma) ** 2) / (math.sqrt(2 * math.pi) * sigma)
    kernel[np.abs(r - 0.15) >= 4 * sigma] = 0
    shell = [quad(lambda t: math.exp(-0.5 * ((q - t) / sigma) ** 2) / (math.sqrt(2 * math.pi) * sigma) * 2 * math.pi * t,
                  max(0, q - 4 * sigma), q + 4 * sigma, epsabs=0, epsrel=1e-13)[0] for q in r]
    np.testing.assert_allclose(g["g"], 2 * kernel / (2 * np.array(shell)), rtol=1e-9, atol=1e-300)
    # A uniform random set: g ≈ 1 away from r = 0 (see geometry_test.cpp for the tolerance).
    y = np.random.default_rng(2).random((2000, 2))
    h = stratum.pair_correlation(y, radii=[0.03, 0.06, 0.09], sigma=0.002)
    np.testing.assert_allclose(h["g"], 1.0, atol=0.15)
    d = stratum.pair_correlation(y)
    assert len(d["r"]) == 100 and d["sigma"] > 0
    with pytest.raises(stratum.InvalidArgument, match="invalid sigma"):
        stratum.pair_correlation(y, radii=[0.1], sigma=-1)


def test_geometry_measures_against_brute_force():
    rng = np.random.default_rng(3)
    x = rng.random((300, 3))
    diff = np.abs(x[:, None, :] - x[None, :, :])
    for toroidal in (False, True):
        dd = np.minimum(diff, 1 - diff) if toroidal else diff
        dist = np.sqrt((dd ** 2).sum(-1))
        np.fill_diagonal(dist, np.inf)
        value = stratum.measure(x, "min-distance", toroidal=toroidal)["value"]
        assert value == pytest.approx(dist.min(), rel=1e-14)
    rho = stratum.measure(grid(8), "poisson-radius")
    assert rho["value"] == pytest.approx(math.sqrt(math.sqrt(3) / 2), rel=1e-13)
    sobol = stratum.points("sobol", 1024, 2, randomize="none")
    t = stratum.measure(sobol, "t-value")
    assert t["value"] == 0 and t["extras"]["m"] == 10
    assert stratum.measure(stratum.points("sobol", 1024, 3, randomize="none"), "t-value")["value"] == 1
    assert stratum.measure(stratum.points("n-rooks", 100, 2), "latin")["value"] == 1
    assert stratum.measure(rng.random((100, 2)), "latin")["value"] == 0
    with pytest.raises(stratum.InvalidArgument, match="invalid n = 1000"):
        stratum.measure(rng.random((1000, 2)), "t-value")
    with pytest.raises(stratum.InvalidArgument, match="invalid base = 1"):
        stratum.measure(sobol, "t-value", base=1)
