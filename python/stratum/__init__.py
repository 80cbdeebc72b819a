"""stratum: Monte Carlo and quasi-Monte Carlo sampling.

The registry of samplers lives in C++; this package is a thin face over it:

>>> import stratum
>>> x = stratum.points("halton", 256, 2)          # numpy float64, shape (256, 2)
>>> [s["name"] for s in stratum.samplers()][:2]
['halton', 'hammersley']
"""
from __future__ import annotations

import numbers

from . import _checks, _stratum
from ._stratum import InvalidArgument

from . import measures as _measures, mitchell as _mitchell, render as _render, report as _report, spectra as _spectra
from . import studies as _studies, warps as _warps
from .measures import *  # noqa: F401,F403  discrepancy and the other measures of point sets
from .mitchell import *  # noqa: F401,F403  study_mitchell
from .render import *  # noqa: F401,F403  render, compare (when the renderer is built)
from .report import *  # noqa: F401,F403  report, report_sections (when the renderer is built)
from .spectra import *  # noqa: F401,F403  spectrum
from .studies import *  # noqa: F401,F403  integrands, integrate, converge, studies
from .warps import *  # noqa: F401,F403  warp, warp_pdf, warp_invert

__all__ = ["samplers", "randomizers", "describe", "points", "parse_spec", "format_spec", "InvalidArgument", "qmc"] + (
    _measures.__all__ + _mitchell.__all__ + _render.__all__ + _report.__all__ + _spectra.__all__ + _studies.__all__ + _warps.__all__)


def __getattr__(name):
    # stratum.qmc imports scipy: load it on first use, not with the package.
    if name == "qmc":
        import importlib

        return importlib.import_module(".qmc", __name__)
    raise AttributeError(f"module 'stratum' has no attribute {name!r}")


def samplers() -> list[dict]:
    """Every sampler: name, kind, description, min_dim, max_dim, flags
    (index_addressable, progressive, frames_continue, self_randomized,
    zero_two_net, space_time: booleans; prefix_unbiased: the randomizers under which each
    point is uniform on its own), properties (the flags and the rest in
    words), randomizers (default first), counts (which n it takes) and params."""
    return _stratum.samplers()


def describe(name: str, kind: str | None = None) -> dict | list[dict]:
    """The parameters of a sampler, measure, warp or integrand, from the one
    schema the CLI and the docs use: a dict with kind, name, description and
    params (each with name, type, description, default, and range, choices,
    length, separator where they apply). A name in two registries (a warp and
    an integrand, say) gives a list unless `kind` picks one.

    >>> stratum.describe("poisson-disk")["params"][0]["range"]
    {'min': 1.0, 'max': 100000.0, 'min_open': False, 'max_open': False}
    """
    if not isinstance(name, str):
        raise InvalidArgument(f"invalid name = {name!r}: must be a string (a sampler, measure, warp or integrand)")
    if kind is not None and not isinstance(kind, str):
        raise InvalidArgument(f"invalid kind = {kind!r}: must be sampler, measure, warp or integrand")
    found = _stratum._describe(name, kind or "")
    return found[0] if len(found) == 1 else found


def randomizers() -> list[tuple[str, str]]:
    """Every randomizer name with a one-line description."""
    return _stratum.randomizers()


def parse_spec(spec: str) -> dict:
    """A sampler spec NAME[(KEY=VALUE,...)][:RANDOMIZER] (docs/samplers.md) as
    a dict with name, params (text values) and randomize ("" = the sampler's
    default), checked against the registry by the same parser as the CLI:

    >>> stratum.parse_spec("lattice(generator=1,55,133):cp")
    {'name': 'lattice', 'params': {'generator': '1,55,133'}, 'randomize': 'cp'}
    """
    if not isinstance(spec, str):
        raise InvalidArgument(f"invalid sampler = {spec!r}: must be a spec string, e.g. 'sobol:owen'")
    return _stratum.parse_spec(spec)


def format_spec(name: str, params: dict | None = None, randomize: str | None = None) -> str:
    """The canonical text of a spec: parse_spec(format_spec(**parse_spec(s))) == parse_spec(s)."""
    text = {str(key): _param_text(key, value) for key, value in (params or {}).items()}
    return _stratum.format_spec(str(name), text, randomize or "")


def _param_text(name, value) -> str:
    if isinstance(value, bool):
        return "1" if value else "0"
    if isinstance(value, (str, numbers.Number)):
        return str(value)
    try:
        # Integers as integers, other numbers in round-trip form (alpha=[0.3, 0.7]).
        return ",".join(str(int(v)) if isinstance(v, numbers.Integral) else repr(float(v)) for v in value)
    except TypeError:
        raise InvalidArgument(f"invalid {name} = {value!r}: must be a number, a string or a list of numbers") from None


def _positive_int(name, value, allowed):
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise InvalidArgument(f"invalid {name} = {value!r}: {allowed}")
    if value < 1 or value >= 2**64:
        raise InvalidArgument(f"invalid {name} = {value}: {allowed}")
    return int(value)


def points(name: str, n: int | None, d: int = 2, seed: int = 0, randomize: str | None = None,
           radius: float | None = None, threads: int = 1, start: int = 0, **params):
    """Points of sampler `name` as a float64 array of shape (n, d).

    `name` is a sampler spec NAME[(KEY=VALUE,...)][:RANDOMIZER] as on the
    command line ("sobol:owen", "poisson-disk(periodic=1)",
    "jittered(strata=4x8)"; docs/samplers.md); `randomize=` and keyword
    parameters add to it, and giving a key or the randomizer both ways is an
    error naming both. threads=0 uses every core.

    randomize=None uses the sampler's documented default (first in its
    `randomizers` list); "none" asks for the unrandomized construction.
    start is the index of the first point (sequences and random, like scipy's
    fast_forward). n=None is allowed only with radius= for a maximal Poisson-disk set.
    Extra keyword arguments are the sampler's parameters (see samplers()).
    """
    name = _checks.text("name", name)
    randomize = _checks.text("randomize", randomize, optional=True)
    if n is not None:
        n = _positive_int("n", n, "must be a positive integer below 2^64")
    d = _positive_int("d", d, "must be a positive integer")
    threads = _checks.threads(threads)
    seed = _checks.seed(seed)
    if d > 2**32 - 1:
        raise InvalidArgument(f"invalid d = {d}: must be below 2^32")
    if radius is not None:
        radius = _checks.real("radius", radius)
    text = {key: _param_text(key, value) for key, value in params.items()}
    if isinstance(start, bool) or not isinstance(start, numbers.Integral) or not 0 <= start < 2**64:
        raise InvalidArgument(f"invalid start = {start!r}: must be an integer in [0, 2^64)")
    return _stratum.points(name, n, d, int(seed), int(start), randomize or "", radius, threads, text)
