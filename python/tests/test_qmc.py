"""stratum.qmc: scipy-compatible engines over the registry, checked against
scipy.stats.qmc itself (the oracle for every unrandomized value and for the
engines' state semantics) and against the defining properties of the
randomized constructions."""
import warnings

import numpy as np
import pytest
from scipy import integrate
from scipy.stats import qmc as scipy_qmc

import stratum
from stratum import qmc


def quiet(function, *args, **kwargs):
    """Calls without the non-power-of-2 balance warning of Sobol."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        return function(*args, **kwargs)


ENGINES = {
    "sobol": lambda **kw: qmc.Sobol(3, **kw),
    "halton": lambda **kw: qmc.Halton(3, **kw),
    "lhs": lambda **kw: qmc.LatinHypercube(3, **kw),
    "poisson": lambda **kw: qmc.PoissonDisk(2, radius=0.1, **kw),
}


def test_registry_has_what_the_engines_need():
    info = {s["name"]: s for s in stratum.samplers()}
    assert {"lms", "none"} <= set(info["sobol"]["randomizers"])
    assert {"permute", "none"} <= set(info["halton"]["randomizers"])
    assert "centered" in [p["name"] for p in info["n-rooks"]["params"]]
    assert "candidates" in [p["name"] for p in info["poisson-disk"]["params"]]


@pytest.mark.parametrize("kind", ENGINES)
def test_engines_are_scipy_engines(kind):
    engine = ENGINES[kind](seed=1)
    assert isinstance(engine, scipy_qmc.QMCEngine)
    x = quiet(engine.random, 8)
    assert x.shape == (8, engine.d) and x.dtype == np.float64
    assert np.all((x >= 0) & (x < 1))
    assert engine.num_generated == 8


def test_scipy_names_are_reexported():
    assert qmc.scale is scipy_qmc.scale and qmc.discrepancy is not scipy_qmc.discrepancy  # stratum's own (issue 4)
    assert qmc.QMCEngine is scipy_qmc.QMCEngine
    assert qmc.Sobol is not scipy_qmc.Sobol


def test_unscrambled_sobol_equals_scipy():
    # scipy's default bits=30 and ours give the same dyadic rationals: for
    # index i < 2^30 the unscrambled point has at most 30 binary digits, so
    # the comparison is exact (array_equal), over 64 dimensions of Joe-Kuo.
    ours = qmc.Sobol(64, scramble=False).random_base2(10)
    theirs = scipy_qmc.Sobol(64, scramble=False).random_base2(10)
    assert np.array_equal(ours, theirs)
    # continuity across calls and far into the sequence (scipy 1.10's
    # fast_forward fails for bits > 32, so the oracle stays at bits=30)
    ours = qmc.Sobol(5, scramble=False).fast_forward(1_000_003)
    theirs = scipy_qmc.Sobol(5, scramble=False).fast_forward(1_000_003)
    assert np.array_equal(quiet(ours.random, 10), quiet(theirs.random, 10))
    assert np.array_equal(quiet(ours.random, 7), quiet(theirs.random, 7))


def test_unscrambled_sobol_past_two_to_the_32():
    # Gray order: point 2^32 + k is point 2^32 XOR point k (digit-wise), and
    # point 2^32 = v_32 XOR v_33; scipy's bits=64 direction numbers are the
    # oracle for v_32, v_33 (a private attribute: skipped if scipy drops it).
    d, k = 6, 1000
    far = qmc.Sobol(d, scramble=False, bits=64).fast_forward(2**32)
    x = quiet(far.random, k + 1)
    near = quiet(qmc.Sobol(d, scramble=False, bits=64).random, k + 1)
    as_int = lambda u: (u * 2.0**53).astype(np.uint64)
    assert np.all(x[0] > 0)
    assert np.array_equal(as_int(x), as_int(x[0])[None, :] ^ as_int(near))
    sv = getattr(scipy_qmc.Sobol(d, scramble=False, bits=64), "_sv", None)
    if sv is not None:
        expected = (sv[:, 31] ^ sv[:, 32]) >> np.uint64(11)
        assert np.array_equal(as_int(x[0]), expected)


def test_unscrambled_halton_equals_scipy():
    ours = qmc.Halton(12, scramble=False)
    theirs = scipy_qmc.Halton(12, scramble=False)
    for n in (1, 99, 900):
        np.testing.assert_allclose(ours.random(n), theirs.random(n), rtol=0, atol=1e-15)
    theirs.fast_forward(1234), ours.fast_forward(1234)
    np.testing.assert_allclose(ours.random(50), theirs.random(50), rtol=0, atol=1e-15)


@pytest.mark.parametrize("kind", ["sobol", "halton"])
@pytest.mark.parametrize("scramble", [False, True])
def test_sequence_state_like_scipy(kind, scramble):
    engine = ENGINES[kind](scramble=scramble, seed=7)
    whole = ENGINES[kind](scramble=scramble, seed=7).random(32)
    parts = np.vstack([quiet(engine.random, 10), quiet(engine.random, 6), quiet(engine.random, 16)])
    assert np.array_equal(parts, whole) and engine.num_generated == 32
    engine.reset()
    assert engine.num_generated == 0 and np.array_equal(engine.random(32), whole)
    engine.reset().fast_forward(10)
    assert engine.num_generated == 10 and np.array_equal(quiet(engine.random, 6), whole[10:16])
    assert np.array_equal(engine.fast_forward(0).random(0), np.empty((0, 3)))


def test_sobol_random_base2_and_power_of_two_rules():
    engine = qmc.Sobol(2, scramble=False)
    assert np.array_equal(engine.random_base2(3), scipy_qmc.Sobol(2, scramble=False).random_base2(3))
    assert engine.random_base2(3).shape == (8, 2)  # 8 + 8 = 16 points: allowed
    with pytest.raises(ValueError, match="m = 2.*power of 2"):
        engine.random_base2(2)  # 16 + 4 = 20
    with pytest.warns(UserWarning, match="balance properties of Sobol' points require n to be a power of 2"):
        qmc.Sobol(2).random(10)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        qmc.Sobol(2).random(16)  # no warning for a power of 2
    small = qmc.Sobol(2, scramble=False, bits=4)
    small.random(16)
    with pytest.raises(ValueError, match=r"n = 1: At most 2\*\*4=16 distinct points can be generated"):
        small.random(1)


def test_sobol_bits_sets_the_resolution():
    for bits in (10, 30):
        x = qmc.Sobol(4, bits=bits, seed=3).random_base2(8)
        assert np.array_equal(x * 2**bits, np.floor(x * 2**bits))
        assert len(np.unique(x[:, 0])) == 256


def elementary_intervals_each_hold_one(x, m):
    """Every 2^-k x 2^-(m-k) box of the unit square holds exactly one of the
    2^m points: the (0, m, 2)-net property of Sobol dims 0, 1."""
    for k in range(m + 1):
        cells = np.floor(x[:, 0] * 2**k).astype(np.int64) * 2 ** (m - k) + np.floor(x[:, 1] * 2 ** (m - k)).astype(np.int64)
        if not np.array_equal(np.sort(cells), np.arange(2**m)):
            return False
    return True


def test_scrambled_sobol_is_a_net_and_differs_by_seed():
    m = 9
    nets = [qmc.Sobol(2, seed=seed).random_base2(m) for seed in (1, 2, 3)]
    for x in nets:
        assert elementary_intervals_each_hold_one(x, m)
    assert not np.array_equal(nets[0], nets[1])
    assert elementary_intervals_each_hold_one(qmc.Sobol(2, scramble=False).random_base2(m), m)
    randomizers = [r for s in stratum.samplers() if s["name"] == "sobol" for r in s["randomizers"]]
    assert {"owen", "owen-hash"} <= set(randomizers), randomizers  # a renamed one fails rather than goes untested
    for randomize in ("owen", "owen-hash"):
        assert elementary_intervals_each_hold_one(qmc.Sobol(2, seed=4, randomize=randomize).random_base2(m), m)


def test_scrambled_halton_keeps_van_der_corput_strata():
    # Random digit permutations keep the first b^k points of the base-b
    # coordinate one per interval [i/b^k, (i+1)/b^k).
    x = qmc.Halton(3, seed=11).random(5**3)
    plain = qmc.Halton(3, scramble=False).random(5**3)
    assert not np.allclose(x, plain)
    for j, (b, k) in enumerate(((2, 6), (3, 4), (5, 3))):
        cells = np.floor(x[: b**k, j] * b**k).astype(int)
        assert np.array_equal(np.sort(cells), np.arange(b**k)), (j, b)


def test_randomized_points_are_uniform():
    # Point 7 of Sobol (LMS + shift) and Halton (digit permutations) over 300
    # seeds, each coordinate against U(0,1) by Kolmogorov-Smirnov: 6 tests at
    # a family-wise level of 1e-3 (Sidak: 1.7e-4 each). A scramble without a
    # shift, or one that leaves trailing zero digits alone, fails this.
    from scipy.stats import kstest

    alpha = 1 - (1 - 1e-3) ** (1 / 6)
    for make in (lambda s: qmc.Sobol(3, seed=s), lambda s: qmc.Halton(3, seed=s)):
        x = np.vstack([make(seed).fast_forward(7).random(1) for seed in range(300)])
        for j in range(3):
            assert kstest(x[:, j], "uniform").pvalue > alpha


def test_seeds():
    def first(engine):
        return quiet(engine.random, 8)

    assert np.array_equal(first(qmc.Sobol(3, seed=5)), first(qmc.Sobol(3, seed=5)))
    assert np.array_equal(first(qmc.Sobol(3, seed=5)), first(qmc.Sobol(3, rng=5)))
    assert not np.array_equal(first(qmc.Sobol(3, seed=5)), first(qmc.Sobol(3, seed=6)))
    assert not np.array_equal(first(qmc.Halton(3)), first(qmc.Halton(3)))  # None: fresh entropy
    # an integer seed is the registry seed itself
    assert np.array_equal(first(qmc.Halton(3, seed=5)), stratum.points("halton", 8, 3, seed=5, randomize="permute"))
    assert np.array_equal(qmc.LatinHypercube(3, seed=9).random(8), stratum.points("n-rooks", 8, 3, seed=9))
    # a Generator gives one draw: same state, same points; the generator moves on
    a, b = np.random.default_rng(1), np.random.default_rng(1)
    assert np.array_equal(first(qmc.Halton(3, seed=a)), first(qmc.Halton(3, seed=b)))
    assert not np.array_equal(first(qmc.Halton(3, seed=a)), first(qmc.Halton(3, seed=np.random.default_rng(1))))
    assert qmc.Sobol(2, seed=2**70).stratum_seed < 2**64


def test_integers_like_scipy():
    ours = qmc.Sobol(2, scramble=False).integers([0, 5], u_bounds=[10, 8], n=16)
    theirs = scipy_qmc.Sobol(2, scramble=False).integers([0, 5], u_bounds=[10, 8], n=16)
    assert ours.dtype == np.int64 and np.array_equal(ours, theirs)
    ends = qmc.Halton(1, scramble=False).integers(3, n=64, endpoint=True)
    assert set(ends.ravel()) == {0, 1, 2, 3}
    with pytest.raises(ValueError, match="l_bounds"):
        qmc.Halton(2).integers([0.5, 1], u_bounds=[2, 3])
    with pytest.raises(ValueError, match="u_bounds"):
        qmc.Halton(2).integers([3, 1], u_bounds=[2, 3])


def test_latin_hypercube():
    n, d = 50, 4
    engine = qmc.LatinHypercube(d, seed=3)
    x = engine.random(n)
    for j in range(d):
        assert np.array_equal(np.sort(np.floor(x[:, j] * n)), np.arange(n))
    assert not np.array_equal(engine.random(n), x)  # a fresh design per call
    assert np.array_equal(engine.reset().random(n), x)
    engine.reset().fast_forward(n)  # fast_forward(n) == draw n and drop them
    second = qmc.LatinHypercube(d, seed=3)
    second.random(n)
    assert np.array_equal(engine.random(7), second.random(7))
    for centered in (qmc.LatinHypercube(d, scramble=False, seed=3), qmc.LatinHypercube(d, centered=True, seed=3)):
        c = centered.random(n)
        np.testing.assert_allclose(np.sort(c, axis=0), np.tile((np.arange(n) + 0.5)[:, None] / n, (1, d)),
                                   rtol=0, atol=1e-15)
    optimized = qmc.LatinHypercube(2, optimization="random-cd", seed=4).random(16)  # scipy's optimizer on our points
    for j in range(2):
        assert np.array_equal(np.sort(np.floor(optimized[:, j] * 16)), np.arange(16))


def test_poisson_disk():
    radius = 0.05
    engine = qmc.PoissonDisk(2, radius=radius, seed=2)
    head = engine.random(30)
    rest = engine.fill_space()
    everything = np.vstack([head, rest])
    gaps = np.sqrt(((everything[:, None, :] - everything[None, :, :]) ** 2).sum(-1))
    assert gaps[np.triu_indices(len(everything), 1)].min() >= radius
    assert engine.num_generated == len(everything)
    # the engine hands out the registry's maximal set in its order
    assert np.array_equal(everything, stratum.points("poisson-disk", None, 2, seed=2, radius=radius))
    assert engine.random(5).shape == (0, 2)  # exhausted, like scipy
    assert np.array_equal(engine.reset().random(30), head)
    scipy_count = len(scipy_qmc.PoissonDisk(2, radius=radius, seed=2).fill_space())
    assert len(everything) >= scipy_count, (len(everything), scipy_count)
    fresh = qmc.PoissonDisk(2, radius=radius, seed=2).fast_forward(10)
    assert np.array_equal(fresh.random(20), head[10:])


def test_discrepancy_and_qmc_quad_accept_our_engines():
    x = qmc.Sobol(3, scramble=False).random_base2(8)
    assert qmc.discrepancy(x) == pytest.approx(scipy_qmc.discrepancy(scipy_qmc.Sobol(3, scramble=False).random_base2(8)), rel=1e-9)
    scrambled = qmc.discrepancy(qmc.Sobol(3, seed=1).random_base2(8))
    assert 0 < scrambled < scipy_qmc.discrepancy(np.random.default_rng(1).random((256, 3)))



def test_qmc_quad_accepts_our_engines():
    # scipy.integrate.qmc_quad re-creates the engine from its _init_quad and
    # a spawned Generator; scipy 1.10 has it only as a private function.
    qmc_quad = getattr(integrate, "qmc_quad", None) or getattr(integrate._quadrature, "_qmc_quad", None)
    if qmc_quad is None:
        pytest.skip("this scipy has no qmc_quad")
    def product(x):  # scipy 1.10 passes points as rows, later versions as columns
        return np.prod(x, axis=-1 if x.shape[-1] == 2 else 0)

    result = qmc_quad(product, [0, 0], [1, 1], n_points=256, n_estimates=4, qrng=qmc.Halton(2, seed=1))
    assert result.integral == pytest.approx(0.25, abs=5 * result.standard_error + 1e-6)


@pytest.mark.parametrize(
    "make, error, word",
    [
        (lambda: qmc.Sobol(-1), ValueError, "d = -1"),
        (lambda: qmc.Sobol(21202), ValueError, "Maximum supported dimensionality is 21201"),
        (lambda: qmc.Sobol(2.5), ValueError, "d = 2.5"),
        (lambda: qmc.Sobol(2, bits=65), ValueError, "bits = 65"),
        (lambda: qmc.Sobol(2, seed=-1), ValueError, "seed = -1"),
        (lambda: qmc.Sobol(2, seed="x"), ValueError, "seed = 'x'"),
        (lambda: qmc.Sobol(2, seed=1, rng=2), ValueError, "rng"),
        (lambda: qmc.Sobol(2, scramble="yes"), ValueError, "scramble"),
        (lambda: qmc.Sobol(2, randomize="shuffle"), ValueError, "randomize = 'shuffle'"),
        (lambda: qmc.Sobol(2).random(-1), ValueError, "n = -1"),
        (lambda: qmc.Sobol(2).random(1.5), ValueError, "n = 1.5"),
        (lambda: qmc.Sobol(2).random_base2(-1), ValueError, "m = -1"),
        (lambda: qmc.Sobol(2).random(4, workers=0), ValueError, "workers = 0"),
        (lambda: qmc.Sobol(2).fast_forward(-3), ValueError, "n = -3"),
        (lambda: qmc.Halton(2, optimization="best"), ValueError, "optimization = 'best'"),
        (lambda: qmc.Halton(10**6), ValueError, "d = 1000000"),
        (lambda: qmc.LatinHypercube(2, strength=3), ValueError, "strength = 3"),
        (lambda: qmc.LatinHypercube(2, strength=2).random(16), ValueError, "n is not the square of a prime"),
        (lambda: qmc.LatinHypercube(5, strength=2).random(9), ValueError, "n is too small for d"),
        (lambda: qmc.LatinHypercube(2, centered="no"), ValueError, "centered"),
        (lambda: qmc.PoissonDisk(2, radius=0), ValueError, "radius = 0"),
        (lambda: qmc.PoissonDisk(2, radius=-0.1), ValueError, "radius = -0.1"),
        (lambda: qmc.PoissonDisk(2, ncandidates=0), ValueError, "ncandidates = 0"),
        (lambda: qmc.PoissonDisk(2, hypersphere="ball"), ValueError, "hypersphere = 'ball'"),
    ],
)
def test_errors_name_the_argument(make, error, word):
    with pytest.raises(error, match=word):
        make()


def test_zero_dimensions_give_empty_samples():
    for engine in (qmc.Sobol(0), qmc.Halton(0), qmc.LatinHypercube(0), qmc.PoissonDisk(0)):
        assert quiet(engine.random, 4).shape == (4, 0)
    normal = scipy_qmc.MultivariateNormalQMC(mean=np.zeros(0), engine=qmc.Sobol(0, scramble=False))
    assert normal.random(3).shape == (3, 0)


@pytest.mark.parametrize("scramble", [True, False])
def test_orthogonal_array_lhs_is_strength_two(scramble):
    # Tang (1993): n = 7^2 points in d = 8 = p + 1 dimensions; every coordinate
    # a Latin hypercube, every pair of coordinates one point per 7 x 7 cell.
    x = qmc.LatinHypercube(8, strength=2, scramble=scramble, seed=4).random(49)
    assert np.array_equal(np.sort(np.floor(x * 49), axis=0), np.tile(np.arange(49.0)[:, None], (1, 8)))
    cells = np.floor(x * 7).astype(int)
    for i in range(8):
        for j in range(i + 1, 8):
            assert len(set(zip(cells[:, i], cells[:, j]))) == 49
    if not scramble:
        assert np.allclose((x * 49) % 1, 0.5)


def test_centered_warns_as_scipy_does():
    with pytest.warns(DeprecationWarning, match="'centered' is deprecated"):
        qmc.LatinHypercube(2, centered=True)
    with pytest.warns(UserWarning, match="'centered' is deprecated"):
        qmc.LatinHypercube(2, centered=True)


@pytest.mark.parametrize("d", [1, 2, 3])
def test_surface_poisson_disk_keeps_the_radius(d):
    engine = qmc.PoissonDisk(d, radius=0.15, hypersphere="surface", seed=2)
    x = engine.fill_space()
    gaps = np.sqrt(((x[:, None, :] - x[None, :, :]) ** 2).sum(-1))[np.triu_indices(len(x), 1)]
    assert len(x) > 1 and gaps.min() >= 0.15 and np.all((x >= 0) & (x < 1))
    assert np.array_equal(qmc.PoissonDisk(d, radius=0.15, hypersphere="surface", seed=2).fill_space(), x)
