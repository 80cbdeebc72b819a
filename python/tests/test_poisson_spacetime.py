"""Poisson-disk, best-candidate and space-time patterns through stratum.points."""
import numpy as np
import pytest
from scipy.spatial import cKDTree, distance

import stratum


def toroidal_min_distance(x):
    d = np.abs(x[:, None, :] - x[None, :, :])
    d = np.minimum(d, 1 - d)
    dist = np.sqrt((d**2).sum(-1))
    np.fill_diagonal(dist, np.inf)
    return dist.min()


@pytest.mark.parametrize("d, radius", [(1, 0.003), (2, 0.03), (3, 0.12), (4, 0.25)])
def test_maximal_poisson_disk_radius_and_coverage(d, radius):
    x = stratum.points("poisson-disk", None, d, seed=2, radius=radius)
    assert x.ndim == 2 and x.shape[1] == d and np.all((x >= 0) & (x < 1))
    assert distance.pdist(x).min() >= radius
    # Maximal: every probe point of the cube is within r of a sample (probes
    # are points of the cube, so the check is exact per probe; 20000 random
    # probes would catch any hole containing a ball of radius ~ (1/20000)^(1/d)).
    probes = np.random.default_rng(0).random((20000, d))
    gap, _ = cKDTree(x).query(probes)
    assert gap.max() <= radius * (1 + 1e-12)


def test_periodic_poisson_disk_uses_toroidal_distance():
    x = stratum.points("poisson-disk", None, 2, seed=4, radius=0.05, periodic=True)
    assert toroidal_min_distance(x) >= 0.05
    flat = stratum.points("poisson-disk", None, 2, seed=4, radius=0.05)
    assert toroidal_min_distance(flat) < 0.05  # the plain cube's points meet across faces


def test_poisson_disk_count_modes_and_determinism():
    a = stratum.points("poisson-disk", 1000, 2, seed=7)
    assert a.shape == (1000, 2)
    assert np.array_equal(a, stratum.points("poisson-disk", 1000, 2, seed=7, threads=2))
    assert not np.array_equal(a, stratum.points("poisson-disk", 1000, 2, seed=8))
    b = stratum.points("poisson-disk", 300, 2, seed=7, radius=0.03)
    assert b.shape == (300, 2) and distance.pdist(b).min() >= 0.03
    c = stratum.points("poisson-disk", 50, 3, seed=1, candidates=5)
    assert c.shape == (50, 3)


@pytest.mark.parametrize(
    "kwargs, words",
    [
        (dict(n=100000, d=2, radius=0.05), ["n = 100000", "packing bound"]),
        (dict(n=None, d=4, radius=1e-4), ["radius", "MiB"]),
        (dict(n=10, d=5), ["d = 5"]),
        (dict(n=None, d=2), ["n"]),
        (dict(n=10, d=2, candidates=0), ["candidates = 0"]),
    ],
)
def test_poisson_disk_errors(kwargs, words):
    with pytest.raises(ValueError) as error:
        stratum.points("poisson-disk", **kwargs)
    for word in words:
        assert word in str(error.value)


def test_best_candidate_is_progressive_and_blue():
    x = stratum.points("best-candidate", 1024, 2, seed=3)
    assert x.shape == (1024, 2) and np.all((x >= 0) & (x < 1))
    assert np.array_equal(stratum.points("best-candidate", 100, 2, seed=3), x[:100])
    # Mitchell's patterns keep about 0.8/sqrt(n) between points (toroidal);
    # 1024 uniform points have a minimum distance near 0.0007.
    assert toroidal_min_distance(x) > 0.5 / np.sqrt(1024)
    with pytest.raises(ValueError, match="at most 5181"):
        stratum.points("best-candidate", 6000, 2)
    flat = stratum.points("best-candidate", 200, 3, seed=1, periodic=False, candidates=3)
    assert flat.shape == (200, 3)


SLIDE_MAGIC = np.array([[15, 8, 5, 2], [4, 3, 14, 9], [10, 13, 0, 7], [1, 6, 11, 12]])
SLIDE_COOK = np.array([[6, 10, 2, 13], [3, 14, 12, 8], [15, 0, 7, 11], [5, 9, 4, 1]])


def slots_of(x, m):
    """Slot table (rows = y strata, top row first) recovered from the points."""
    table = np.full((m, m), -1)
    table[np.floor(x[:, 1] * m).astype(int), np.floor(x[:, 0] * m).astype(int)] = np.floor(x[:, 2] * m * m)
    return table


@pytest.mark.parametrize("name, table", [("spacetime-magic", SLIDE_MAGIC), ("spacetime-cook", SLIDE_COOK)])
def test_spacetime_slide_tables(name, table):
    x = stratum.points(name, 16, 3, seed=5)
    assert x.shape == (16, 3)
    assert np.array_equal(slots_of(x, 4), table)


@pytest.mark.parametrize("m", [5, 8, 9, 12, 16, 21])
def test_spacetime_magic_is_pandiagonal(m):
    t = slots_of(stratum.points("spacetime-magic", m * m, 3, seed=1), m)
    assert sorted(t.ravel()) == list(range(m * m))
    s = m * (m * m - 1) // 2
    rows = np.arange(m)
    assert np.all(t.sum(0) == s) and np.all(t.sum(1) == s)
    for k in range(m):
        assert t[rows, (rows + k) % m].sum() == s
        assert t[rows, (k - rows) % m].sum() == s


def test_spacetime_cook_and_random():
    m = 10
    t = slots_of(stratum.points("spacetime-cook", m * m, 3), m)
    assert sorted(t.ravel()) == list(range(m * m))
    assert np.abs(np.diff(t, axis=0, append=t[:1])).min() >= m  # edge neighbours, on the torus
    assert np.abs(np.diff(t, axis=1, append=t[:, :1])).min() >= m
    r = stratum.points("spacetime-random", 64, 3, seed=3)
    assert sorted(slots_of(r, 8).ravel()) == list(range(64))
    assert np.array_equal(r, stratum.points("spacetime-random", 64, 3, seed=3, threads=2))


@pytest.mark.parametrize(
    "name, n, word",
    [("spacetime-random", 15, "m^2"), ("spacetime-cook", 10, "m^2"), ("spacetime-magic", 36, "m mod 4 != 2"),
     ("spacetime-magic", 9, "m mod 4 != 2")],
)
def test_spacetime_counts(name, n, word):
    with pytest.raises(ValueError, match=f"n = {n}") as error:
        stratum.points(name, n, 3)
    assert word in str(error.value)
