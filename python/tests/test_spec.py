"""The sampler spec NAME[(KEY=VALUE,...)][:RANDOMIZER] on the Python face:
the same parser as the CLI (docs/samplers.md), the same errors, the seed and
thread rules."""
import os
import re

import numpy as np
import pytest

import stratum

from build_parts import NO_RENDERER, RENDERER


def test_points_take_specs_and_their_parts_alike():
    a = stratum.points("sobol:owen", 64, 2, seed=3)
    b = stratum.points("sobol", 64, 2, seed=3, randomize="owen")
    np.testing.assert_array_equal(a, b)
    a = stratum.points("poisson-disk(periodic=1)", 32, 2, seed=1)
    b = stratum.points("poisson-disk", 32, 2, seed=1, periodic=1)
    c = stratum.points("poisson-disk", 32, 2, seed=1)
    np.testing.assert_array_equal(a, b)
    assert not np.array_equal(a, c)
    a = stratum.points("jittered(strata=4x8)", 32, 2, seed=2)
    b = stratum.points("jittered", 32, 2, seed=2, strata="4x8")
    np.testing.assert_array_equal(a, b)
    # 4 columns x 8 rows: one point in each cell.
    cells = {(int(x * 4), int(y * 8)) for x, y in a}
    assert len(cells) == 32
    a = stratum.points("lattice(generator=1,5):none", 8, 2)
    b = stratum.points("lattice", 8, 2, randomize="none", generator=[1, 5])
    np.testing.assert_array_equal(a, b)
    np.testing.assert_allclose(a[1], [1 / 8, 5 / 8])


def test_parse_and_format_round_trip():
    spec = stratum.parse_spec("lattice(generator=1,55,133):cp")
    assert spec == {"name": "lattice", "params": {"generator": "1,55,133"}, "randomize": "cp"}
    assert stratum.format_spec(**spec) == "lattice(generator=1,55,133):cp"
    assert stratum.format_spec("poisson-disk", {"periodic": 1, "candidates": 10}) == "poisson-disk(candidates=10,periodic=1)"
    for text in ["sobol", "sobol:owen", "jittered(strata=4x8)", "lattice(a=76,gamma=0.5)", "kronecker(alpha=0.25,0.5):cp"]:
        assert stratum.format_spec(**stratum.parse_spec(text)) == text


@pytest.mark.parametrize("spec, words", [
    ("sobl:owen", "invalid sampler = sobl:owen: unknown sampler 'sobl' at position 1; did you mean sobol"),
    ("nosuch", "unknown sampler 'nosuch' at position 1; valid samplers are"),
    ("poisson-disk(periodc=1)", "unknown key 'periodc' at position 14; poisson-disk takes candidates, periodic"),
    ("halton:owen-hash", "randomizer 'owen-hash' at position 8 is not one halton accepts"),
    ("lattice(generator=1,55", "'(' at position 8 is never closed"),
    ("sobol)", "')' at position 6 has no '('"),
    ("jittered(=4x8)", "empty key at position 10"),
    ("jittered(strata=)", "empty value for key 'strata' at position 17"),
    ("poisson-disk(periodic=1,periodic=0)", "duplicate key 'periodic' at position 25 (first at position 14)"),
    ("sobol:", "empty randomizer after ':' at position 6"),
])
def test_bad_specs_give_the_messages_of_the_cli(spec, words):
    for call in (lambda: stratum.points(spec, 32, 2), lambda: stratum.parse_spec(spec),
                 lambda: stratum.integrate("disk", spec, n=32)):
        with pytest.raises(stratum.InvalidArgument) as error:
            call()
        assert words in str(error.value)
        assert str(error.value).startswith(f"invalid sampler = {spec}: ")


def test_both_forms_at_once_is_an_error_naming_both():
    with pytest.raises(stratum.InvalidArgument, match="invalid randomize = xor: conflicts with the randomizer of the "
                                                      "sampler spec sobol:owen"):
        stratum.points("sobol:owen", 8, 2, randomize="xor")
    with pytest.raises(stratum.InvalidArgument, match=r"invalid param = periodic=0: conflicts with periodic=1"):
        stratum.points("poisson-disk(periodic=1)", 8, 2, periodic=0)
    with pytest.raises(stratum.InvalidArgument, match="invalid param = bogus=1: poisson-disk takes candidates, periodic"):
        stratum.points("poisson-disk", 8, 2, bogus=1)
    with pytest.raises(stratum.InvalidArgument, match="invalid randomize = xor: conflicts"):
        stratum.integrate("disk", "sobol:owen", n=8, randomize="xor")


def test_converge_takes_a_list_of_specs():
    result = stratum.converge("disk", "jittered(strata=4x8),lattice(generator=1,7):cp,sobol:owen", n=[32], runs=2)
    assert len(result["samplers"]) == 3
    with pytest.raises(stratum.InvalidArgument, match="invalid samplers = sobol,,random: empty item at position 7"):
        stratum.converge("disk", "sobol,,random", n=[32], runs=2)


def test_seeds_are_exactly_the_integers_below_two_to_the_64():
    top = stratum.points("random", 2, 2, seed=2**64 - 1)
    assert not np.array_equal(top, stratum.points("random", 2, 2, seed=2**64 - 2))
    for bad in (-1, 2**64, 10**23, 1e3, "5", True, None):
        with pytest.raises(stratum.InvalidArgument, match="invalid seed = .*: must be an integer in \\[0, 2\\^64\\)"):
            stratum.points("random", 2, 2, seed=bad)
    assert stratum._stratum.parse_seed("18446744073709551615") == 2**64 - 1


def test_one_thread_rule_zero_is_every_core():
    every = stratum._stratum.resolve_threads(0)
    assert every in {min(os.cpu_count() or 1, 1024), min(len(os.sched_getaffinity(0)), 1024)}
    np.testing.assert_array_equal(stratum.points("sobol:owen", 10000, 2, threads=0),
                                  stratum.points("sobol:owen", 10000, 2, threads=1))
    x = stratum.points("halton", 64, 2)
    stratum.discrepancy(x, threads=0)
    stratum.spectrum(x, max_frequency=4, threads=0)
    stratum.integrate("disk", "random", n=16, threads=0)
    for bad in (-1, 1025, 2.0, True):
        for call in (lambda: stratum.points("random", 4, 2, threads=bad), lambda: stratum.discrepancy(x, threads=bad),
                     lambda: stratum.integrate("disk", "random", n=16, threads=bad)):
            with pytest.raises(stratum.InvalidArgument,
                               match=r"invalid threads = .*: must be an integer in \[0, 1024\] \(0: every core\)"):
                call()


def test_render_takes_the_same_specs():
    if not RENDERER:
        pytest.skip(NO_RENDERER)
    a = stratum.render(width=8, height=8, spp=4, sampler="sobol:owen", seed=1, passes=1)
    b = stratum.render(width=8, height=8, spp=4, sampler="sobol", randomize="owen", seed=1, passes=1)
    np.testing.assert_array_equal(a, b)
    c = stratum.render(width=8, height=8, spp=4, sampler="sobol:xor", seed=1, passes=1)
    assert not np.array_equal(a, c)
    # Parameters reach every set the sampler draws (pixel sets and shadow-ray arrays).
    aspect = stratum.render(width=8, height=8, spp=16, sampler="cmj(aspect=2)", seed=1, passes=1)
    plain = stratum.render(width=8, height=8, spp=16, sampler="cmj", seed=1, passes=1)
    assert not np.array_equal(aspect, plain)
    strata = stratum.render(width=8, height=8, spp=4, light_samples=4, sampler="jittered(strata=2x2)", seed=1)
    np.testing.assert_array_equal(strata, stratum.render(width=8, height=8, spp=4, light_samples=4,
                                                         sampler="jittered", seed=1))
    with pytest.raises(stratum.InvalidArgument,
                       match=r"invalid light-samples = 1: the sampler jittered\(strata=2x2\) cannot draw"):
        stratum.render(width=8, height=8, spp=4, sampler="jittered(strata=2x2)")
    with pytest.raises(stratum.InvalidArgument, match="pixel is the renderer's own for an image sampler"):
        stratum.render(width=8, height=8, spp=4, sampler="sobol-bn(pixel=1,1)")
    with pytest.raises(stratum.InvalidArgument, match="invalid sampler = sobl: unknown sampler 'sobl'"):
        stratum.render(width=8, height=8, spp=4, sampler="sobl")


def test_randomizer_families_in_the_docs_are_the_registrys():
    # docs/samplers.md's family table names every sampler of each family and
    # the randomizers the family accepts: a change of family fails here.
    root = os.path.join(os.path.dirname(__file__), os.pardir, os.pardir)
    with open(os.path.join(root, "docs", "samplers.md"), encoding="utf-8") as f:
        # A family's row: its name alone in the first cell (not a SamplerInfo member such as `seeded(request)`).
        family_row = re.compile(r"^\| `(base[a-z0-9-]*|rotation|seeded[a-z0-9-]*)` \|")
        rows = [line.split("|")[1:-1] for line in f if family_row.match(line)]
    assert len(rows) == 5
    samplers = stratum.samplers()
    for family, names, accepts, _ in rows:
        family = family.strip().strip("`")
        members = [s for s in samplers if s["randomizer_family"] == family]
        expected = {s["name"] for s in members}
        listed = {n.strip() for n in names.split(",")}
        if "spacetime-*" in listed:
            listed = (listed - {"spacetime-*"}) | {s["name"] for s in samplers if s["name"].startswith("spacetime-")}
        assert listed == expected, family
        accepted = [a.strip() for a in accepts.split(",")]
        for s in members:
            assert sorted(s["randomizers"]) == sorted(accepted), s["name"]
