"""stratum.warps: the registry's warps from Python, against closed forms and scipy."""
import numpy as np
import pytest
import scipy.stats

import stratum

# Example parameters for warps whose parameters have no defaults.
EXAMPLES = {
    "piecewise-1d": {"values": [1, 3, 0.5, 2]},
    "piecewise-2d": {"values": [[1, 2, 3], [4, 5, 6]]},
    "alias": {"values": [1, 3, 0.5, 2]},
}


def uniforms(n, d, seed=1):
    return np.random.default_rng(seed).random((n, d))


def test_lists_every_warp():
    names = [w["name"] for w in stratum.warps()]
    for name in ["disk-polar", "disk-concentric", "hemisphere-uniform", "hemisphere-cosine", "sphere-uniform",
                 "cone", "triangle", "linear", "tent", "exponential", "normal", "bilinear"]:
        assert name in names
    cone = next(w for w in stratum.warps() if w["name"] == "cone")
    assert cone["measure"] == "solid angle" and cone["params"][0]["name"] == "cos_theta_max"


@pytest.mark.parametrize("name", [w["name"] for w in stratum.warps()])
def test_every_warp_round_trips(name):
    params = EXAMPLES.get(name, {})
    in_dim = 1 if name in ("linear", "tent", "exponential", "normal", "piecewise-1d", "alias") else 2
    u = uniforms(500, in_dim)
    p = stratum.warp(name, u, **params)
    assert p.shape[0] == 500 and np.all(np.isfinite(p))
    assert np.all(stratum.warp_pdf(name, p, **params) > 0)
    again = stratum.warp(name, stratum.warp_invert(name, p, **params), **params)
    assert np.allclose(again, p, atol=1e-9)


def test_closed_forms():
    u = uniforms(1000, 2)
    d = stratum.warp("hemisphere-cosine", u)
    assert d.shape == (1000, 3)
    assert np.allclose(np.linalg.norm(d, axis=1), 1)
    assert np.allclose(stratum.warp_pdf("hemisphere-cosine", d), d[:, 2] / np.pi)
    assert np.allclose(stratum.warp_invert("hemisphere-cosine", d), u, atol=1e-12)
    assert np.allclose(stratum.warp("disk-concentric", [[0.5, 0.5]]), 0)
    assert stratum.warp_pdf("hemisphere-cosine", [[0, 0, 1]])[0] == pytest.approx(1 / np.pi)
    c = stratum.warp("cone", u, cos_theta_max=0.9)
    assert np.all(c[:, 2] >= 0.9 - 1e-12)
    assert np.allclose(stratum.warp_pdf("cone", c, cos_theta_max=0.9), 1 / (2 * np.pi * 0.1))
    t = stratum.warp("triangle", u, vertices=[[0, 0, 1], [2, 0, 1], [0, 1, 1]])
    assert t.shape == (1000, 3) and np.all(t[:, 2] == 1)
    assert np.allclose(stratum.warp_pdf("triangle", t, vertices=np.array([[0, 0, 1], [2, 0, 1], [0, 1, 1]])), 1.0)


def test_one_dimensional_warps_match_scipy():
    u = np.linspace(0.001, 0.999, 999)
    x = stratum.warp("normal", u, mu=2, sigma=0.5)
    assert x.shape == (999,)
    assert np.allclose(x, scipy.stats.norm.ppf(u, loc=2, scale=0.5), rtol=1e-13, atol=1e-13)
    assert np.allclose(stratum.warp_pdf("normal", x, mu=2, sigma=0.5), scipy.stats.norm.pdf(x, 2, 0.5))
    assert np.allclose(stratum.warp("exponential", u, rate=3), scipy.stats.expon.ppf(u, scale=1 / 3))
    assert np.allclose(stratum.warp("tent", u, radius=2), scipy.stats.triang.ppf(u, 0.5, loc=-2, scale=4))
    # linear a=1, b=3: density (1 + 2x)/2, CDF (x + x^2)/2
    lin = stratum.warp("linear", u, a=1, b=3)
    assert np.allclose((lin + lin ** 2) / 2, u)
    assert stratum.warp("normal", u[:, None]).shape == (999, 1)


# Kolmogorov–Smirnov against scipy's distributions, Šidák over 3 tests at α = 0.01.
def test_one_dimensional_warps_ks():
    alpha = 1 - (1 - 0.01) ** (1 / 3)
    u = uniforms(20000, 1, seed=5)[:, 0]
    assert scipy.stats.kstest(stratum.warp("normal", u, mu=-1, sigma=2), scipy.stats.norm(-1, 2).cdf).pvalue > alpha
    assert scipy.stats.kstest(stratum.warp("exponential", u, rate=0.5), scipy.stats.expon(scale=2).cdf).pvalue > alpha
    assert scipy.stats.kstest(stratum.warp("tent", u, radius=1), scipy.stats.triang(0.5, -1, 2).cdf).pvalue > alpha


def test_width_and_height_come_from_the_values_shape():
    assert "piecewise-2d" in [w["name"] for w in stratum.warps()]  # renamed or lost: fail, not skip
    u = uniforms(200, 2)
    a = stratum.warp("piecewise-2d", u, values=[[1, 2, 3], [4, 5, 6]])
    b = stratum.warp("piecewise-2d", u, values=[1, 2, 3, 4, 5, 6], width=3, height=2)
    assert np.array_equal(a, b)


def test_bad_input():
    u = uniforms(5, 2)
    with pytest.raises(stratum.InvalidArgument, match="invalid map = nosuch"):
        stratum.warp("nosuch", u)
    with pytest.raises(ValueError, match=r"invalid cos_theta_max = 1\.5"):
        stratum.warp("cone", u, cos_theta_max=1.5)
    with pytest.raises(ValueError, match="invalid vertices"):
        stratum.warp("triangle", u, vertices=[0, 0, 1, 1, 2, 2])
    with pytest.raises(ValueError, match="invalid radius = 0"):
        stratum.warp("tent", u[:, 0], radius=0)
    with pytest.raises(ValueError, match="invalid rate = -1"):
        stratum.warp("exponential", u[:, 0], rate=-1)
    with pytest.raises(ValueError, match="invalid sigma = 0"):
        stratum.warp("normal", u[:, 0], sigma=0)
    with pytest.raises(ValueError, match="invalid weights"):
        stratum.warp("bilinear", u, weights=[0, 0, 0, 0])
    bad = u.copy()
    bad[3, 1] = 1.0
    with pytest.raises(ValueError, match=r"invalid u\[3\]\[1\] = 1: must be in \[0, 1\)"):
        stratum.warp("disk-polar", bad)
    bad[3, 1] = np.nan
    with pytest.raises(ValueError, match=r"invalid u\[3\]\[1\] = nan"):
        stratum.warp("disk-polar", bad)
    with pytest.raises(ValueError, match=r"invalid u = array of shape \(5, 3\): disk-polar takes shape \(n, 2\)"):
        stratum.warp("disk-polar", uniforms(5, 3))
    with pytest.raises(ValueError, match=r"invalid p\[0\]\[2\] = inf"):
        stratum.warp_pdf("sphere-uniform", [[0, 0, np.inf]])
    with pytest.raises(ValueError, match="invalid warp-param = radius=2: disk-polar takes no parameters"):
        stratum.warp("disk-polar", u, radius=2)
    with pytest.raises(ValueError, match="invalid cos_theta_max"):
        stratum.warp("cone", u, cos_theta_max="wide")
