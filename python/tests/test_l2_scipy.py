"""stratum.qmc.discrepancy / update_discrepancy against scipy.stats.qmc (an
independent implementation of the same definitions), scipy's own published
test values and error contract, and an exactly summed reference."""
import math
import os

import numpy as np
import pytest
from scipy.stats import qmc as scipy_qmc

import stratum
from stratum import qmc

METHODS = ("CD", "WD", "MD", "L2-star")


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("iterative", [False, True])
def test_equals_scipy_on_small_random_sets(method, iterative):
    # Small n: scipy's own rounding stays far below 1e-12 relative, so the values must agree to that.
    rng = np.random.default_rng(20240607)
    for n in (1, 2, 5, 16, 40):
        for d in (1, 2, 3, 6, 10):
            x = rng.random((n, d))
            ours = qmc.discrepancy(x, method=method, iterative=iterative)
            theirs = scipy_qmc.discrepancy(x, method=method, iterative=iterative)
            assert ours == pytest.approx(theirs, rel=1e-12, abs=1e-15), (method, n, d)


def _cd_reference(x):
    """CD² with every term summed exactly (math.fsum) after numpy computes them."""
    n, d = x.shape
    c = np.abs(x - 0.5)
    single = np.prod(1 + 0.5 * c - 0.5 * c**2, axis=1)
    pairs = np.prod(1 + 0.5 * c[:, None, :] + 0.5 * c[None, :, :] - 0.5 * np.abs(x[:, None, :] - x[None, :, :]), axis=2)
    return math.fsum([(13 / 12) ** d, *(-2 / n * single), *(pairs.ravel() / n**2)])


def test_larger_sets_are_as_accurate_as_an_exact_sum():
    # At n = 1000 scipy's plain summation drifts by about 1e-10 relative (measured: 8e-11 at d = 2);
    # stratum's compensated and long-double sums stay within 1e-11 of the exactly summed terms.
    rng = np.random.default_rng(7)
    for n, d in ((1000, 2), (500, 3), (300, 5)):
        x = rng.random((n, d))
        reference = _cd_reference(x)
        assert qmc.discrepancy(x, method="CD") == pytest.approx(reference, rel=1e-11)
        assert qmc.discrepancy(x, method="CD") == pytest.approx(scipy_qmc.discrepancy(x, method="CD"), rel=1e-8)


def test_on_scrambled_sobol_points_stratum_is_the_accurate_one():
    """The docstring's claim: on a set with a small discrepancy (CD² = 7.7e-7
    here) stratum stays within 2e-15 absolute of the exactly summed terms,
    while scipy's plain double sum is off by more than 10x that (measured:
    stratum 1.6e-16 from this reference, 2e-17 from the long-double one of
    bench/qmc_discrepancy_accuracy.py; scipy 1.5e-13)."""
    x = qmc.Sobol(2, seed=1).random(1024)
    reference = _cd_reference(x)
    ours, theirs = qmc.discrepancy(x, method="CD"), scipy_qmc.discrepancy(x, method="CD")
    assert abs(ours - reference) <= 2e-15
    assert abs(theirs - reference) > 10 * max(abs(ours - reference), 1e-17)


def test_scipy_published_values():
    # Fang et al. 2006, "Design and modeling for computer experiments" (as in scipy's test_qmc.py).
    space_1 = (2.0 * np.array([[1, 3], [2, 6], [3, 2], [4, 5], [5, 1], [6, 4]]) - 1.0) / 12.0
    space_2 = (2.0 * np.array([[1, 5], [2, 4], [3, 3], [4, 2], [5, 1], [6, 6]]) - 1.0) / 12.0
    assert qmc.discrepancy(space_1) == pytest.approx(0.0081, abs=1e-4)
    assert qmc.discrepancy(space_2) == pytest.approx(0.0105, abs=1e-4)
    # Zhou, Fang, Ning 2013, "Mixture discrepancy for quasi-random point sets", Example 4.
    sample = np.array([[2, 1, 1, 2, 2, 2], [1, 2, 2, 2, 2, 2], [2, 1, 1, 1, 1, 1], [1, 1, 1, 1, 2, 2],
                       [1, 2, 2, 2, 1, 1], [2, 2, 2, 2, 1, 1], [2, 2, 2, 1, 2, 2]])
    sample = (2.0 * sample - 1.0) / 4.0
    for workers in (1, 8):
        assert qmc.discrepancy(sample, method="MD", workers=workers) == pytest.approx(2.5000, abs=1e-4)
        assert qmc.discrepancy(sample, method="WD", workers=workers) == pytest.approx(1.3680, abs=1e-4)
        assert qmc.discrepancy(sample, method="CD", workers=workers) == pytest.approx(0.3172, abs=1e-4)
    # Pillards et al. 2005: one point at (1, ..., 1) has L2-star discrepancy 3^(-d/2).
    for dim in (2, 4, 8, 16, 32, 64):
        for workers in (1, -1):
            assert qmc.discrepancy(np.ones((1, dim)), method="L2-star", workers=workers) == pytest.approx(
                np.sqrt(3.0**-dim), rel=1e-14)


def test_update_discrepancy_matches_scipys_docstring_and_recomputation():
    space = np.array([[1, 3], [2, 6], [3, 2], [4, 5], [5, 1], [6, 4]])
    space = scipy_qmc.scale(space, [0.5, 0.5], [6.5, 6.5], reverse=True)
    disc_init = qmc.discrepancy(space[:-1], iterative=True)
    assert disc_init == pytest.approx(0.04769081147119336, rel=1e-12)
    assert qmc.update_discrepancy(space[-1], space[:-1], disc_init) == pytest.approx(0.008142039609053513, rel=1e-12)
    rng = np.random.default_rng(241557431858162136881731220526394276199)
    x = rng.random((4, 10))  # n < d, as in scipy's test
    init = qmc.discrepancy(x[:-1], iterative=True)
    assert qmc.update_discrepancy(x[-1], x[:-1], init) == pytest.approx(qmc.discrepancy(x), rel=1e-12)
    assert qmc.update_discrepancy(x[-1], x[:-1], init) == pytest.approx(
        scipy_qmc.update_discrepancy(x[-1], x[:-1], init), rel=1e-12)


def test_thread_count_does_not_change_the_value():
    x = np.random.default_rng(3).random((700, 4))
    for method in METHODS:
        assert qmc.discrepancy(x, method=method, workers=1) == qmc.discrepancy(x, method=method, workers=2)


def test_errors_follow_scipys_messages_and_name_the_coordinate():
    sample = np.array([[1, 3], [2, 6], [3, 2], [4, 5], [5, 1], [6, 4]])
    with pytest.raises(ValueError, match=r"Sample is not in unit hypercube") as error:
        qmc.discrepancy(sample)
    assert "sample[0][0] = 1.0" not in str(error.value) and "sample[0][1]" in str(error.value)
    with pytest.raises(ValueError, match=r"Sample is not a 2D array"):
        qmc.discrepancy([1, 3])
    with pytest.raises(ValueError, match=r"'toto' is not a valid ..."):
        qmc.discrepancy([[0, 0], [1, 1], [0.5, 0.5]], method="toto")
    with pytest.raises(ValueError, match="Invalid number of workers..."):
        qmc.discrepancy([[0.1, 0.2]], workers=-2)
    with pytest.raises(ValueError, match=r"sample\[1\]\[0\] = nan"):
        qmc.discrepancy([[0.1, 0.2], [np.nan, 0.3]])  # scipy would return nan
    with pytest.raises(ValueError, match=r"Sample is empty"):
        qmc.discrepancy(np.zeros((0, 2)))
    x = np.random.default_rng(1).random((4, 3))
    init = qmc.discrepancy(x[:-1], iterative=True)
    with pytest.raises(ValueError, match=r"Sample is not in unit hypercube"):
        qmc.update_discrepancy(x[-1], x[:-1] + 1, init)
    with pytest.raises(ValueError, match=r"Sample is not a 2D array"):
        qmc.update_discrepancy(x[-1], x[0], init)
    with pytest.raises(ValueError, match=r"x_new is not in unit hypercube"):
        qmc.update_discrepancy([1, 3, 0], x[:-1], init)
    with pytest.raises(ValueError, match=r"x_new is not a 1D array"):
        qmc.update_discrepancy([[0.5, 0.5, 0.5]], x[:-1], init)
    with pytest.raises(ValueError, match=r"x_new and sample must be broadcastable"):
        qmc.update_discrepancy([0.3, 0.1], x[:-1], init)
    assert isinstance(pytest.raises(stratum.InvalidArgument, qmc.discrepancy, [1, 3]).value, ValueError)


def test_workers_minus_one_without_a_cpu_count(monkeypatch):
    monkeypatch.setattr(os, "cpu_count", lambda: None)
    with pytest.raises(NotImplementedError, match="Cannot determine the"):
        qmc.discrepancy([[0.1, 0.2], [0.3, 0.4]], workers=-1)


def test_same_signatures_as_scipy():
    import inspect

    for name in ("discrepancy", "update_discrepancy"):
        ours = inspect.signature(getattr(qmc, name))
        theirs = inspect.signature(getattr(scipy_qmc, name))
        assert [(p.name, p.kind, p.default) for p in ours.parameters.values()] == [
            (p.name, p.kind, p.default) for p in theirs.parameters.values()], name
    assert qmc.discrepancy is not scipy_qmc.discrepancy and "discrepancy" in qmc.__all__
