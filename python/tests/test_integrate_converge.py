"""stratum.integrands / integrate / converge: exact integrals against scipy's
adaptive quadrature (an independent oracle), estimates against their standard
errors, the convergence rates of the lecture, and bad input."""
import math

import numpy as np
import pytest
from scipy import integrate as quad

import stratum


def _exact(name, d=None, **params):
    return stratum.integrate(name, "random", 2, d=d, **params)["exact"]


def test_integrands_registry():
    names = [e["name"] for e in stratum.integrands()]
    for expected in ("disk", "triangle", "step", "gaussian", "bilinear", "edge-random", "genz-oscillatory",
                     "genz-product-peak", "genz-corner-peak", "genz-gaussian", "genz-continuous",
                     "genz-discontinuous"):
        assert expected in names
    assert len(names) == len(set(names))
    genz = next(e for e in stratum.integrands() if e["name"] == "genz-gaussian")
    assert {p["name"] for p in genz["params"]} == {"a", "u"}
    assert genz["params"][0]["default"] == [5.0]


def test_planar_exact_against_scipy():
    assert _exact("disk") == 0.5 and _exact("triangle") == 0.5 and _exact("bilinear") == 0.25
    assert _exact("step") == pytest.approx(1 / math.pi, rel=1e-15)
    value, _ = quad.dblquad(lambda y, x: math.exp(-x * x - y * y), 0, 1, 0, 1, epsabs=1e-13, epsrel=1e-13)
    assert _exact("gaussian") == pytest.approx(value, rel=1e-12)
    # The quarter disk through scipy: ∫_0^r sqrt(r² − x²) dx with r² = 2/π.
    r = math.sqrt(2 / math.pi)
    value, _ = quad.quad(lambda x: math.sqrt(max(r * r - x * x, 0.0)), 0, r, epsabs=1e-13)
    assert value == pytest.approx(0.5, rel=1e-10)


GENZ = {
    "genz-oscillatory": lambda x, a, u: math.cos(2 * math.pi * u[0] + sum(ai * xi for ai, xi in zip(a, x))),
    "genz-product-peak": lambda x, a, u: math.prod(1 / (ai ** -2 + (xi - ui) ** 2) for ai, xi, ui in zip(a, x, u)),
    "genz-corner-peak": lambda x, a, u: (1 + sum(ai * xi for ai, xi in zip(a, x))) ** (-len(x) - 1),
    "genz-gaussian": lambda x, a, u: math.exp(-sum(ai * ai * (xi - ui) ** 2 for ai, xi, ui in zip(a, x, u))),
    "genz-continuous": lambda x, a, u: math.exp(-sum(ai * abs(xi - ui) for ai, xi, ui in zip(a, x, u))),
    "genz-discontinuous": lambda x, a, u: 0.0 if x[0] > u[0] or x[1] > u[1] else math.exp(sum(
        ai * xi for ai, xi in zip(a, x))),
}


@pytest.mark.parametrize("name", sorted(GENZ))
def test_genz_exact_against_scipy(name):
    # Our own definitions (Genz 1984, as on sfu.ca/~ssurjano) integrated by
    # scipy's nquad, split at u where the integrand has a kink or a jump.
    a, u = [3.0, 6.0], [0.3, 0.7]
    f = GENZ[name]
    opts = [{"points": [u[0]], "epsabs": 1e-13, "epsrel": 1e-12}, {"points": [u[1]], "epsabs": 1e-13, "epsrel": 1e-12}]
    value, _ = quad.nquad(lambda y, x: f((x, y), a, u), [[0, 1], [0, 1]], opts=opts)
    assert _exact(name, d=2, a=a, u=u) == pytest.approx(value, rel=1e-9, abs=1e-12)


def test_integrate_error_within_standard_error():
    r = stratum.integrate("genz-gaussian", "random", 20000, d=3, seed=11, a=np.array([2.0, 3.0, 4.0]), u=0.2)
    assert r["standard_error_kind"] == "iid" and r["d"] == 3
    assert abs(r["error"]) < 4 * r["standard_error"]  # z-test at α = 6e-5
    q = stratum.integrate("gaussian", "sobol:owen", 1024, runs=8, seed=2)
    assert q["standard_error_kind"] == "replicates" and q["randomize"] == "owen"
    assert isinstance(q["run_estimates"], np.ndarray) and q["run_estimates"].shape == (8,)
    assert q["estimate"] == pytest.approx(q["run_estimates"].mean(), rel=1e-15)
    assert abs(q["error"]) < 5.4 * q["standard_error"]  # t_7 at α = 2e-4
    assert stratum.integrate("gaussian", "sobol:owen", 1024, runs=8, seed=2, threads=2)["estimate"] == q["estimate"]


def test_converge_default_counts_work_for_every_integrand():
    for info in stratum.integrands():
        r = stratum.converge(info["name"], "random,jittered", runs=2)
        rand, jit = r["samplers"]["random:none"], r["samplers"]["jittered:none"]
        assert list(r["n"]) == [2**k for k in range(4, 17)]
        assert list(rand["n"]) == list(r["n"]) and rand["skipped"] == []
        assert list(jit["n"]) == [4**k for k in range(2, 9)], info["name"]
        assert [s["n"] for s in jit["skipped"]] == [2**k for k in range(5, 16, 2)]
        assert "invalid n = 32" in jit["skipped"][0]["reason"]
        assert len(jit["variance"]) == 7 and np.isfinite(jit["slope"])
    with pytest.raises(stratum.InvalidArgument, match="n = 32"):
        stratum.converge("disk", "jittered", "16:65536", runs=2)  # given explicitly: every count must work


def test_integrate_never_reports_a_false_zero_standard_error():
    r = stratum.integrate("step", "hammersley:owen", 64, runs=16)
    assert r["standard_error_kind"] == "replicates" and r["standard_error"] > 0
    assert abs(r["error"]) < 4.07 * r["standard_error"]  # t_15 at 0.001
    for spec in ("grid", "zaremba", "hammersley:none", "fibonacci"):
        r = stratum.integrate("step", spec, 64, runs=16)
        assert r["standard_error_kind"] == "identical-runs" and math.isnan(r["standard_error"]), spec


def test_integrate_interval_covers_at_its_level():
    """400 seeds of random on gaussian (n = 64, 8 runs): the 95% Student-t
    intervals cover the exact value a number of times inside the
    binomial(400, 0.95) band of probability 0.999."""
    from scipy import stats
    covered = 0
    for seed in range(400):
        r = stratum.integrate("gaussian", "random", 64, runs=8, seed=seed)
        low, high = r["interval"]
        assert high - r["estimate"] == pytest.approx(r["half_width"], abs=1e-15)
        covered += low <= r["exact"] <= high
    band = stats.binom(400, 0.95)
    assert band.ppf(0.0005) <= covered <= band.isf(0.0005), covered
    r = stratum.integrate("gaussian", "random", 64, runs=8, seed=1, confidence=0.9)
    assert r["confidence"] == 0.9
    # t_{7, 0.95} = 1.8945786050900074 (mpmath, 30 digits; scipy's t.ppf is off by 1e-11 here)
    assert r["half_width"] == pytest.approx(1.8945786050900074 * r["standard_error"], rel=1e-12)
    assert r["efficiency"] == pytest.approx(1 / (r["standard_error"] ** 2 * 8 * r["seconds_per_run"]), rel=1e-9)
    for level in (0, 1, 1.5, True, "0.9"):
        with pytest.raises(stratum.InvalidArgument, match="confidence"):
            stratum.integrate("gaussian", "random", 64, runs=8, confidence=level)


def test_converge_rates_and_thread_invariance():
    one = stratum.converge("gaussian", "random,jittered", "16:4096:4", runs=64, seed=3)
    two = stratum.converge("gaussian", ["random", "jittered"], [16, 64, 256, 1024, 4096], runs=64, seed=3, threads=2)
    assert list(one["n"]) == [16, 64, 256, 1024, 4096]
    for key in ("random:none", "jittered:none"):
        assert np.array_equal(one["samplers"][key]["variance"], two["samplers"][key]["variance"])
        s = one["samplers"][key]
        expected = -1.0 if key == "random:none" else -2.0
        # 4 standard errors: the fit's own or the sampling SE of a log variance, sqrt(2/(R-1))/sqrt(Sxx).
        logn = np.log(one["n"])
        sampling = math.sqrt(2 / 63) / math.sqrt(((logn - logn.mean()) ** 2).sum())
        assert abs(s["slope"] - expected) < 4 * max(s["slope_standard_error"], sampling), (key, s["slope"])
        assert np.allclose(s["efficiency"], 1 / (s["variance"] * s["seconds"]))
        # Cross-check the slope with numpy's least squares.
        assert s["slope"] == pytest.approx(np.polyfit(logn, np.log(s["variance"]), 1)[0], rel=1e-10)


@pytest.mark.parametrize("call, word", [
    (lambda: stratum.integrate("disk", n=0), "n = 0"),
    (lambda: stratum.integrate("disk", n=-3), "n = -3"),
    (lambda: stratum.integrate("nosuch", n=4), "integrand = nosuch"),
    (lambda: stratum.integrate("disk", "nosuch", 4), "sampler = nosuch"),
    (lambda: stratum.integrate("disk", n=4, d=3), "d = 3"),
    (lambda: stratum.integrate("genz-gaussian", n=4, a=[1, 2, 3]), "a = 3 numbers"),
    (lambda: stratum.integrate("genz-gaussian", n=4, a="x"), "a = 'x'"),
    (lambda: stratum.integrate("genz-gaussian", n=4, bogus=1), "integrand-param = bogus=1: genz-gaussian takes a, u"),
    (lambda: stratum.integrate("disk", n=4, runs=0), "runs = 0"),
    (lambda: stratum.converge("disk", "random", "16:100"), "powers of two"),
    (lambda: stratum.converge("disk", "random", [64, 16]), "n = 16"),
    (lambda: stratum.converge("disk", "random", [0, 16]), "n = 0"),
    (lambda: stratum.converge("disk", "jittered", "16:64"), "n = 32"),
    (lambda: stratum.converge("disk", "random", runs=1), "runs = 1"),
    (lambda: stratum.converge("disk", [], "16:64"), "samplers"),
    (lambda: stratum.converge("disk", "random:owen", "16:64"), "randomizer 'owen' at position 8 is not one random accepts"),
])
def test_bad_input(call, word):
    with pytest.raises(stratum.InvalidArgument, match=None) as info:
        call()
    assert word in str(info.value)


def test_converge_slope_interval():
    """The slope's interval: the jackknife over runs, t_{R-1} (coverage over
    200 seeds is tested in C++); it holds the true rate -1 of random sampling
    here, where the residual standard error (0.078) is no interval."""
    from scipy import stats
    r = stratum.converge("genz-gaussian", "random", "64:16384:4", runs=32, d=4, seed=1)["samplers"]["random:none"]
    low, high = r["slope_interval"]
    assert low <= -1 <= high and r["slope_confidence"] == 0.95
    t = stats.t.ppf(0.975, 31)
    assert high - r["slope"] == pytest.approx(t * r["slope_sampling_standard_error"], rel=1e-9)
    assert r["slope"] - low == pytest.approx(t * r["slope_sampling_standard_error"], rel=1e-9)
    narrow = stratum.converge("genz-gaussian", "random", "64:16384:4", runs=32, d=4, seed=1, confidence=0.5)
    lo50, hi50 = narrow["samplers"]["random:none"]["slope_interval"]
    assert (hi50 - lo50) / (high - low) == pytest.approx(stats.t.ppf(0.75, 31) / t, rel=1e-8)  # scipy t.ppf: ~1e-9
    fixed = stratum.converge("gaussian", "halton:none", [64, 256], runs=3)["samplers"]["halton:none"]
    assert fixed["fitted"] == "mse" and all(math.isnan(v) for v in fixed["slope_interval"])
    for level in (0, 1, True, "0.9"):
        with pytest.raises(stratum.InvalidArgument, match="confidence"):
            stratum.converge("gaussian", "random", [16, 64], runs=4, confidence=level)


def test_integrate_to_a_tolerance():
    r = stratum.integrate("genz-gaussian", "sobol:owen", n=16, d=3, runs=8, seed=5, abs_tol=1e-4)
    t = r["tolerance"]
    assert t["met"] and t["target"] == 1e-4 and t["rel_tol"] == 0
    ns = [s["n"] for s in t["steps"]]
    assert ns == [16 << k for k in range(len(ns))] and r["n"] == ns[-1]
    assert all(s["half_width"] > 1e-4 for s in t["steps"][:-1]) and r["half_width"] <= 1e-4
    # The last step is the plain call at that n, bit for bit.
    plain = stratum.integrate("genz-gaussian", "sobol:owen", n=ns[-1], d=3, runs=8, seed=5)
    assert plain["estimate"] == r["estimate"] and "tolerance" not in plain
    unmet = stratum.integrate("gaussian", "random", n=16, runs=4, rel_tol=1e-6, max_n=64)["tolerance"]
    assert not unmet["met"] and [s["n"] for s in unmet["steps"]] == [16, 32, 64]


@pytest.mark.parametrize("kwargs, match", [
    ({"abs_tol": 0}, "give --abs-tol or --rel-tol greater than 0"),
    ({"abs_tol": "1e-3"}, "invalid abs_tol = '1e-3': must be a real number"),
    ({"rel_tol": 1.5}, r"invalid rel-tol = 1.5: must be a real in \[0, 1\)"),
    ({"max_n": 64}, "invalid max-n = 64: applies only with a tolerance, abs-tol or rel-tol"),
    ({"abs_tol": 1e-3, "max_n": 8}, "invalid max-n = 8: must be at least n = 16"),
])
def test_integrate_tolerance_refusals(kwargs, match):
    with pytest.raises(stratum.InvalidArgument, match=match):
        stratum.integrate("gaussian", "random", n=16, runs=4, **kwargs)
