import numpy as np
import pytest

import stratum


def test_samplers_lists_registry_entries():
    names = [s["name"] for s in stratum.samplers()]
    assert "halton" in names and "random" in names
    assert len(names) == len(set(names))
    for s in stratum.samplers():
        assert s["min_dim"] <= s["max_dim"]
        assert s["randomizers"], s["name"]


def test_samplers_flags_are_typed_and_hold():
    # The typed flags (docs/samplers.md): booleans and a list of randomizers,
    # the same as `stratum samplers --json`; progressive samplers continue
    # their sequence at start, the others refuse a start unless they are
    # sequences or pixel samplers.
    keys = {"index_addressable", "progressive", "frames_continue", "self_randomized", "zero_two_net", "space_time"}
    progressive = 0
    for s in stratum.samplers():
        flags = s["flags"]
        assert keys <= set(flags), s["name"]
        assert all(isinstance(flags[k], bool) for k in keys), s["name"]
        assert set(flags["prefix_unbiased"]) <= set(s["randomizers"]), s["name"]
        if flags["progressive"]:
            assert "progressive" in s["properties"], s["name"]
            d = min(max(2, s["min_dim"]), s["max_dim"])
            whole = stratum.points(s["name"], 32, d, seed=4)
            assert np.array_equal(stratum.points(s["name"], 16, d, seed=4, start=16), whole[16:]), s["name"]
            progressive += 1
    assert progressive >= 8
    assert stratum.samplers()[[s["name"] for s in stratum.samplers()].index("sobol")]["flags"]["prefix_unbiased"]


def test_points_shape_dtype_and_values():
    x = stratum.points("halton", 6, 3, randomize="none")
    assert x.shape == (6, 3) and x.dtype == np.float64
    assert x[5, 0] == 0.625
    assert x[5, 1] == pytest.approx(2 / 3 + 1 / 9, abs=1e-15)


def test_every_sampler_in_unit_cube_and_thread_invariant():
    for s in stratum.samplers():
        d = min(max(2, s["min_dim"]), s["max_dim"])
        for n in (256, 1024, 4096):
            try:
                a = stratum.points(s["name"], n, d, seed=5)
            except stratum.InvalidArgument:
                continue
            assert np.all((a >= 0) & (a < 1)), s["name"]
            b = stratum.points(s["name"], n, d, seed=5, threads=2)
            assert np.array_equal(a, b), s["name"]
            break
        else:
            pytest.fail(f"{s['name']} accepted none of the counts tried")


@pytest.mark.parametrize(
    "kwargs, word",
    [
        (dict(name="nosuch", n=4), "sampler"),
        (dict(name="halton", n=0), "n = 0"),
        (dict(name="halton", n=-1), "n = -1"),
        (dict(name="halton", n="ten"), "n = 'ten'"),
        (dict(name="halton", n=4, d=0), "d = 0"),
        (dict(name="halton", n=4, d=5000), "d = 5000"),
        (dict(name="halton", n=4, randomize="shuffle"), "randomize"),
        (dict(name="halton", n=4, bogus=1), "bogus"),
        (dict(name="halton", n=None), "n"),
    ],
)
def test_bad_input_names_the_argument(kwargs, word):
    with pytest.raises(ValueError, match=word):
        stratum.points(**kwargs)


def test_a_huge_request_is_refused_before_allocating():
    with pytest.raises(MemoryError, match=r"needs 21\.3 PiB for 1000000000000000 x 3 points of random, .* available"):
        stratum.points("random", 10**15, 3)


def test_random_takes_start():
    """random is index-addressable: point i of start=K is point K + i of a longer run (also past 2^32)."""
    longer = stratum.points("random", 30, 3, seed=4, start=2**32 - 7)
    assert np.array_equal(stratum.points("random", 20, 3, seed=4, start=2**32 + 3), longer[10:])
    assert np.array_equal(stratum.points("random", 6, 3, seed=4, start=4), stratum.points("random", 10, 3, seed=4)[4:])
    with pytest.raises(stratum.InvalidArgument, match="start = 1: jittered is a finite pattern"):
        stratum.points("jittered", 16, 2, start=1)
