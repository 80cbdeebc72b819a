"""scipy's own test suite for scipy.stats.qmc, run against stratum.qmc.

The installed scipy test module (scipy/stats/tests/test_qmc.py, shipped by
Debian's python3-scipy) is imported with its `from scipy.stats import qmc`
bound to stratum.qmc, so every class attribute and parametrization it builds
at import time (TestSobol.qmce = qmc.Sobol, ...) already names stratum's
engines; its module-level `update_discrepancy` (imported from scipy's private
module) is rebound to stratum's too. Its test classes and functions are then
collected from here.

Skipped, by name, are only the tests that pin scipy's own pseudo-random values
for a seed: stratum's streams are counter-based hashes, not numpy's PCG64, so
the same seed gives other (equally valid) points. PINNED lists each with the
reason; test_pinned_names_exist fails when a listed name no longer exists in
the installed suite, so a rename cannot skip a test silently.
"""
import importlib.util
import inspect
import os

import pytest
import scipy.stats

from stratum import qmc as stratum_qmc

SUITE_PATH = os.path.join(os.path.dirname(scipy.stats.__file__), "tests", "test_qmc.py")

if not os.path.exists(SUITE_PATH):
    pytest.skip(f"scipy's qmc tests are not installed ({SUITE_PATH}); Debian's python3-scipy ships them",
                allow_module_level=True)


def _load_suite():
    """scipy's test module with its `qmc` (and `update_discrepancy`) bound to stratum's."""
    spec = importlib.util.spec_from_file_location("scipy_qmc_suite_on_stratum", SUITE_PATH)
    module = importlib.util.module_from_spec(spec)
    scipy_qmc = scipy.stats.qmc
    scipy.stats.qmc = stratum_qmc  # what `from scipy.stats import qmc` reads while the module runs
    try:
        spec.loader.exec_module(module)
    finally:
        scipy.stats.qmc = scipy_qmc
    assert module.qmc is stratum_qmc and module.TestSobol.qmce is stratum_qmc.Sobol
    module.update_discrepancy = stratum_qmc.update_discrepancy
    return module


SUITE = _load_suite()

_STREAM = ("pins scipy's pseudo-random values for this seed (numpy PCG64 stream); stratum's counter-based "
           "streams give other points for the same seed")

# "Class::test" skips every parametrization; "Class::test[id]" only that one.
PINNED = {
    "TestHalton::test_sample[Scrambled]": _STREAM + " (scrambled Halton reference points, atol 0.1)",
    "TestHalton::test_workers": _STREAM + " (scrambled Halton reference points, atol 1e-3)",
    "TestSobol::test_sample[Scrambled]": _STREAM + " (LMS-scrambled Sobol' reference points, atol 0.1)",
    "TestNormalQMC::test_NormalQMCSeeded": _STREAM + " (second half: scrambled Sobol' engine seeded like scipy's)",
    "TestMultinomialQMC::test_other_engine": _STREAM + " (multinomial counts from a seeded scrambled Sobol' engine)",
}

for _name, _object in vars(SUITE).items():
    if (_name.startswith("Test") and inspect.isclass(_object)) or (_name.startswith("test_") and callable(_object)):
        globals()[_name] = _object


def _pinned_reason(item):
    cls = item.cls.__name__ + "::" if item.cls is not None else ""
    base = item.originalname if hasattr(item, "originalname") else item.name
    return PINNED.get(cls + item.name) or PINNED.get(cls + base)


@pytest.fixture(autouse=True)
def _skip_pinned(request):
    reason = _pinned_reason(request.node)
    if reason:
        pytest.skip(reason)


def _parametrize_ids(function):
    """The ids pytest gives the parametrizations of `function` (explicit ids= only, else None)."""
    marks = [m for m in getattr(function, "pytestmark", []) if m.name == "parametrize"]
    if len(marks) != 1 or "ids" not in marks[0].kwargs:
        return None
    return set(marks[0].kwargs["ids"])


@pytest.mark.parametrize("name", sorted(PINNED))
def test_pinned_names_exist(name):
    """Every skipped name is a test of the installed suite (a rename must not skip silently)."""
    path, _, param = name.partition("[")
    class_name, _, test_name = path.rpartition("::")
    owner = getattr(SUITE, class_name, None) if class_name else SUITE
    assert owner is not None, f"{class_name} is not in {SUITE_PATH}"
    function = getattr(owner, test_name, None)
    assert callable(function), f"{path} is not in {SUITE_PATH}"
    if param:
        ids = _parametrize_ids(function)
        assert ids is not None and param.rstrip("]") in ids, f"{name}: no parametrization {param.rstrip(']')!r}"
