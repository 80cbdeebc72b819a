"""One default across the package (docs/cli.md): every function that takes a
seed defaults to seed 0, as every CLI subcommand does, and every function
that takes threads defaults to 1 (scipy's habit, workers=1; the CLI's
default is every core). The scipy drop-in stratum.qmc keeps scipy's
seed=None."""
import inspect

import stratum


def _public_functions():
    for name in dir(stratum):
        value = getattr(stratum, name)
        if not name.startswith("_") and inspect.isfunction(value):
            yield name, inspect.signature(value)


def test_every_seed_defaults_to_zero_and_every_threads_to_one():
    seeded = threaded = 0
    for name, signature in _public_functions():
        parameters = signature.parameters
        if "seed" in parameters:
            assert parameters["seed"].default == 0, name
            seeded += 1
        if "threads" in parameters:
            assert parameters["threads"].default == 1, name
            threaded += 1
    # Not vacuous: points, integrate, converge, render, compare, report, the
    # studies and the optimizer take a seed; the measures take threads too.
    assert seeded >= 11 and threaded >= 16, (seeded, threaded)


def test_no_seed_is_seed_zero():
    assert (stratum.points("sobol:owen", 64, 3) == stratum.points("sobol:owen", 64, 3, seed=0)).all()
    assert not (stratum.points("sobol:owen", 64, 3) == stratum.points("sobol:owen", 64, 3, seed=1)).all()
