"""The "sobol" and "zero-two" registry entries from Python, against scipy.

What holds exactly: scipy.stats.qmc.Sobol(d, scramble=False, bits=b) returns
point i as floor(x_i * 2^b) / 2^b, where x_i is stratum's 64-bit word (the
same Joe-Kuo generator matrices and the same Gray-code order, point 0 the
origin). For i < 2^k every coordinate is a multiple of 2^-k, so for any
index below 2^b (scipy's own limit, 2^30 by default) the two float64 arrays
are identical, not merely close. Past 2^32 scipy 1.10 cannot follow
(fast_forward fails for bits > 32); the C++ tests compare with
boost::random::sobol there.
"""
import pathlib
import subprocess
import sys
import warnings

import numpy as np
import pytest
from scipy.stats import qmc

import stratum

RANDOMIZERS = ["owen-hash", "none", "owen", "xor", "lms", "cp"]


def scipy_sobol(d, n, skip=0, bits=None):
    engine = qmc.Sobol(d, scramble=False, bits=bits)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # scipy warns when n is not a power of two
        if skip:
            engine.fast_forward(skip)
        return engine.random(n)


def test_registry_entries():
    info = {s["name"]: s for s in stratum.samplers()}
    assert info["sobol"]["randomizers"] == RANDOMIZERS
    assert (info["sobol"]["min_dim"], info["sobol"]["max_dim"]) == (1, 21201)
    assert qmc.Sobol.MAXDIM == 21201  # scipy's own
    from stratum import qmc as stratum_qmc
    assert stratum_qmc.Sobol.MAXDIM == 21201
    assert info["zero-two"]["randomizers"] == RANDOMIZERS  # the base-2 family's, as sobol
    assert (info["zero-two"]["min_dim"], info["zero-two"]["max_dim"]) == (2, 2)


def test_unscrambled_equals_scipy_exactly():
    ours = stratum.points("sobol", 1024, 8, randomize="none")
    assert np.array_equal(ours, scipy_sobol(8, 1024))
    assert np.array_equal(ours, scipy_sobol(8, 1024, bits=53))
    # Deep into scipy's default 30-bit range, with a start that is not aligned.
    skip = 2**29 + 12345
    ours = stratum.points("sobol", 1000, 8, randomize="none", start=skip)
    theirs = scipy_sobol(8, 1000, skip=skip)
    assert np.array_equal(ours, theirs)
    assert np.array_equal(np.floor(ours * 2**30) / 2**30, theirs)  # the general relation, trivially here


def test_all_joe_kuo_dimensions_equal_scipy():
    # All 21201 dimensions: the first 3667 are Boost's table (compared bit
    # for bit in the C++ tests), the 17534 beyond come from scipy's copy.
    ours = stratum.points("sobol", 64, 21201, randomize="none")
    assert np.array_equal(ours, scipy_sobol(21201, 64))
    # Deeper columns, where the initial numbers m_7..m_18 and then the
    # polynomial's recursion enter: in natural order point 2^c is column c of
    # every generator matrix; scipy's engine keeps its columns, 64 bits wide
    # with bits=64, in _sv (its fast_forward to 2^18 would take 10 s here).
    columns = qmc.Sobol(21201, scramble=False, bits=64)._sv
    for c in (6, 10, 13, 15, 17, 18, 25, 31, 52, 63):
        ours = stratum.points("sobol", 1, 21201, randomize="none", order="natural", start=2**c)[0]
        assert np.array_equal(ours, (columns[:, c] >> np.uint64(11)).astype(np.float64) * 2.0**-53), c


def test_generated_table_is_what_its_generator_writes(tmp_path):
    """include/stratum/sequences/sobol_joe_kuo_table.hpp is regenerated from
    scipy's direction numbers, byte for byte."""
    root = pathlib.Path(__file__).resolve().parents[2]
    out = tmp_path / "table.hpp"
    subprocess.run([sys.executable, str(root / "scripts/generate_sobol_table.py"), "-o", str(out)], check=True,
                   capture_output=True)
    assert out.read_bytes() == (root / "include/stratum/sequences/sobol_joe_kuo_table.hpp").read_bytes()


def test_too_many_dimensions_is_an_error():
    with pytest.raises(stratum.InvalidArgument, match="d = 21202"):
        stratum.points("sobol", 16, 21202)
    with pytest.raises(stratum.InvalidArgument, match="d = 3"):
        stratum.points("zero-two", 16, 3)
    with pytest.raises(stratum.InvalidArgument, match="order"):
        stratum.points("sobol", 16, 2, order="random")


def test_natural_order_option():
    natural = stratum.points("sobol", 8, 2, randomize="none", order="natural")
    assert natural[:, 1].tolist() == [0.0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875]
    gray = stratum.points("sobol", 64, 4, randomize="none")
    assert np.array_equal(np.sort(gray, axis=0), np.sort(stratum.points("sobol", 64, 4, randomize="none",
                                                                        order="natural"), axis=0))


def test_start_past_two_to_the_32_does_not_wrap():
    near = stratum.points("sobol", 64, 4, randomize="none")
    far = stratum.points("sobol", 64, 4, randomize="none", start=2**32)
    assert np.all((far >= 0) & (far < 1))
    assert not np.any(np.all(far == near, axis=1))
    # Blocks of 64 starting at 2^32 are still (t,6,s)-nets: dims 0 and 1 stratify.
    assert sorted((far[:, 0] * 64).astype(int)) == list(range(64))


@pytest.mark.parametrize("randomize", ["owen-hash", "none", "owen", "xor", "lms"])
def test_zero_two_is_a_zero_m_two_net_at_powers_of_two(randomize):
    x = stratum.points("zero-two", 256, 2, seed=3, randomize=randomize)
    assert np.array_equal(x, stratum.points("sobol", 256, 2, seed=3, randomize=randomize))
    for i in range(9):
        cells = (np.floor(x[:, 0] * 2**i) * 2 ** (8 - i) + np.floor(x[:, 1] * 2 ** (8 - i))).astype(int)
        assert sorted(cells) == list(range(256)), (randomize, i)


@pytest.mark.parametrize("randomize", [r for r in RANDOMIZERS if r != "none"])
def test_randomizers_are_seeded_and_reproducible(randomize):
    a = stratum.points("sobol", 128, 5, seed=1, randomize=randomize)
    assert np.array_equal(a, stratum.points("sobol", 128, 5, seed=1, randomize=randomize, threads=2))
    assert not np.array_equal(a, stratum.points("sobol", 128, 5, seed=2, randomize=randomize))
    assert not np.array_equal(a, stratum.points("sobol", 128, 5, randomize="none"))
    assert np.all((a >= 0) & (a < 1))
    # Every randomizer keeps the 1D stratification of 128 = 2^7 points.
    for j in range(5):
        assert sorted((a[:, j] * 128).astype(int)) == list(range(128))


def test_default_randomizer_is_owen_hash_with_53_random_digits():
    a = stratum.points("sobol", 64, 3, seed=9)
    assert np.array_equal(a, stratum.points("sobol", 64, 3, seed=9, randomize="owen-hash"))
    # All 53 digits are scrambled: the low digits are not zero.
    assert np.mean((a * 2**53) % 2**21 != 0) > 0.99


@pytest.mark.parametrize("d", [1, 3, 17, 257])
def test_unscrambled_equals_scipy_across_block_layouts(d):
    # The bulk generator works in aligned blocks of rows whose size depends
    # on d; unaligned starts and counts cross their edges.
    n, skip = 4099, 2053
    ours = stratum.points("sobol", n, d, randomize="none", start=skip)
    assert np.array_equal(ours, scipy_sobol(d, n, skip=skip))


@pytest.mark.parametrize("randomize", ["owen-hash", "xor", "lms", "cp"])
@pytest.mark.parametrize("d", [2, 5, 16, 300])
def test_any_start_and_thread_count_give_the_same_rows(randomize, d):
    n = 9000 if d < 300 else 800
    whole = stratum.points("sobol", n, d, seed=4, randomize=randomize)
    for start in [1, 333, 777] + ([4096] if d < 300 else []):
        part = stratum.points("sobol", n - start, d, seed=4, randomize=randomize, start=start, threads=2)
        assert np.array_equal(part, whole[start:]), start


def test_bits_parameter_keeps_the_first_digits():
    """bits=b (scipy's Sobol bits, done in the generator): floor(x 2^b) / 2^b
    of the full points, for every randomizer; qmc.Sobol(bits=b) uses it."""
    for randomize in RANDOMIZERS:
        full = stratum.points("sobol", 512, 5, seed=3, randomize=randomize)
        kept = stratum.points("sobol", 512, 5, seed=3, randomize=randomize, bits=9)
        assert np.array_equal(kept, np.floor(full * 2**9) / 2**9), randomize
    from stratum import qmc as stratum_qmc
    engine = stratum_qmc.Sobol(4, bits=12, seed=7)
    sample = engine.random(1024)
    raw = stratum.points("sobol", 1024, 4, seed=engine.stratum_seed, randomize="lms")
    assert np.array_equal(sample, np.floor(raw * 2**12) / 2**12)
    assert np.array_equal(stratum_qmc.Sobol(6, scramble=False, bits=10).random(1024), scipy_sobol(6, 1024, bits=10))
    for bad in (0, 65):
        with pytest.raises(stratum.InvalidArgument, match=f"bits = {bad}"):
            stratum.points("sobol", 4, 2, bits=bad)
