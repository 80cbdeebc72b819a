"""The generic faces over the measure registry: stratum.measures(),
stratum.measure(), stratum.discrepancy(), and their bad-input contract."""
import warnings

import numpy as np
import pytest
from scipy.stats import qmc as scipy_qmc

import stratum


def _random(n, d, seed=0):
    return np.random.default_rng(seed).random((n, d))


def test_measures_lists_the_registry():
    listed = stratum.measures()
    names = [m["name"] for m in listed]
    assert len(names) == len(set(names))
    for name in ("l2-star", "cd", "wd", "md"):
        assert name in names
    for m in listed:
        assert m["description"] and m["min_dim"] >= 1
        assert m["max_dim"] == 0 or m["max_dim"] >= m["min_dim"]
        for p in m["params"]:
            assert {"name", "type", "description", "default"} <= set(p)
            assert p["type"] in ("integer", "real", "integers", "reals", "choice", "flag", "text")


def test_measure_result_shape_and_l2_convention():
    x = _random(50, 3)
    r = stratum.measure(x, "cd")
    assert set(r) == {"value", "kind", "lower", "upper", "extras"}
    assert r["kind"] == "exact" and r["lower"] is None and r["upper"] is None
    # value = CD, extras squared = CD^2 = what scipy returns (an independent implementation)
    assert r["extras"]["squared"] == pytest.approx(scipy_qmc.discrepancy(x, method="CD"), rel=1e-12)
    assert r["value"] == pytest.approx(np.sqrt(r["extras"]["squared"]), rel=1e-15)


@pytest.mark.parametrize("method", ["CD", "WD", "MD", "L2-star"])
def test_discrepancy_scipy_names_return_scipys_values(method):
    x = _random(40, 4, seed=1)
    assert stratum.discrepancy(x, method) == pytest.approx(scipy_qmc.discrepancy(x, method=method), rel=1e-12)


def test_discrepancy_registry_names_return_the_registry_value():
    x = _random(64, 2, seed=2)
    for m in stratum.measures():
        if m["min_dim"] <= 2 and (m["max_dim"] == 0 or m["max_dim"] >= 2):
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")  # a "bounds" result warns
                value = stratum.discrepancy(x, m["name"])
            assert value == stratum.measure(x, m["name"])["value"], m["name"]
    # lowercase names: the discrepancy itself, uppercase (scipy's): the square
    assert stratum.discrepancy(x, "cd") ** 2 == pytest.approx(stratum.discrepancy(x, "CD"), rel=1e-14)
    assert stratum.discrepancy(x, "l2-star") == stratum.discrepancy(x, "L2-star")


def test_default_method_is_scipys_cd():
    x = _random(30, 2, seed=3)
    assert stratum.discrepancy(x) == stratum.discrepancy(x, "CD")


def test_params_and_threads_pass_through():
    x = _random(3000, 2, seed=4)
    fast = stratum.measure(x, "l2-star", algorithm="fast")["value"]
    slow = stratum.measure(x, "l2-star", algorithm="warnock", threads=2)["value"]
    assert fast == pytest.approx(slow, rel=1e-10)
    assert stratum.measure(x, "md", threads=1) == stratum.measure(x, "md", threads=2)


def test_one_dimensional_array_is_n_points_in_1d():
    x = np.array([0.1, 0.5, 0.8])
    assert stratum.measure(x, "l2-star") == stratum.measure(x[:, None], "l2-star")


def test_non_contiguous_and_integer_input():
    x = _random(20, 6, seed=5)
    view = x[:, ::2]
    assert stratum.measure(view, "wd") == stratum.measure(np.ascontiguousarray(view), "wd")
    corners = [[0, 0], [1, 1], [0, 1]]
    assert stratum.measure(corners, "cd")["value"] == stratum.measure(np.array(corners, float), "cd")["value"]


@pytest.mark.parametrize(
    "x, kwargs, words",
    [
        ([[0.1, 0.2], [0.3, 1.5]], dict(name="cd"), ["point[1][1]", "1.5", "[0, 1]"]),
        ([[0.1, 0.2], [-0.25, 0.5]], dict(name="l2-star"), ["point[1][0]", "-0.25"]),
        ([[0.1, np.nan], [0.3, 0.4]], dict(name="wd"), ["point[0][1]", "nan"]),
        ([[0.1, 0.2], [np.inf, 0.4]], dict(name="md"), ["point[1][0]", "inf"]),
        ([[0.1, 0.2]], dict(name="cd"), ["n = 1", "at least 2"]),
        ([[0.1, 0.2], [0.3, 0.4]], dict(name="nosuch"), ["measure = nosuch", "l2-star"]),
        ([[0.1, 0.2, 0.3], [0.3, 0.4, 0.5]], dict(name="edge"), ["d = 3", "edge"]),
        (np.full((4, 5), 0.5), dict(name="l2-star", algorithm="fast"), ["algorithm = fast", "warnock"]),
        ([[0.1, 0.2], [0.3, 0.4]], dict(name="l2-star", algorithm="quick"), ["algorithm = quick", "auto"]),
        ([[0.1, 0.2], [0.3, 0.4]], dict(name="cd", lines=5), ["measure-param = lines=5", "cd takes no parameters"]),
        ([[0.1, 0.2], [0.3, 0.4]], dict(name="cd", threads=-1), ["threads = -1"]),
        ([[0.1, 0.2], [0.3, 0.4]], dict(name=3), ["measure = 3"]),
        (np.zeros((2, 2, 2)), dict(name="cd"), ["shape (2, 2, 2)"]),
        ([["a", "b"], ["c", "d"]], dict(name="cd"), ["invalid x"]),
        ([[0.1, 0.2], [0.3]], dict(name="cd"), ["invalid x"]),
        (np.zeros((0, 2)), dict(name="cd"), ["n = 0"]),
    ],
)
def test_measure_bad_input(x, kwargs, words):
    with pytest.raises(stratum.InvalidArgument) as error:
        stratum.measure(x, **kwargs)
    for word in words:
        assert word in str(error.value), (word, str(error.value))
    assert isinstance(error.value, ValueError)


def test_discrepancy_bad_method_lists_both_spellings():
    with pytest.raises(stratum.InvalidArgument, match=r"method = 'toto'.*CD.*L2-star.*l2-star"):
        stratum.discrepancy([[0.1, 0.2], [0.3, 0.4]], "toto")
    with pytest.raises(stratum.InvalidArgument, match=r"point\[0\]\[0\]"):
        stratum.discrepancy([[1.1, 0.2], [0.3, 0.4]], "CD")
