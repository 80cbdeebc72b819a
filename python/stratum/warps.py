"""Warps: maps from uniform points in [0,1)^k to a domain, with exact densities
and inverses (the same registry as ``stratum warp`` on the command line).

>>> import numpy as np, stratum
>>> u = stratum.points("sobol", 256, 2)
>>> d = stratum.warp("hemisphere-cosine", u)          # (256, 3) unit vectors around +z
>>> bool(np.allclose(stratum.warp_pdf("hemisphere-cosine", d), d[:, 2] / np.pi))
True
>>> bool(np.allclose(stratum.warp_invert("hemisphere-cosine", d), u))
True

Parameters are keyword arguments, numbers or array-likes (flattened):
``stratum.warp("cone", u, cos_theta_max=0.9)``, ``stratum.warp("triangle", u,
vertices=[[0, 0, 0], [1, 0, 0], [0, 1, 0]])``. When a warp takes ``width``
(and ``height``) and they are left out, they come from the shape of
``values``. 1-D warps take u of shape (n,) or (n, 1); given (n,) they return
(n,). See ``warps()`` for every name, its domain, pdf measure and parameters.
"""
from __future__ import annotations

import numpy as np

from . import _checks, _stratum
from ._stratum import InvalidArgument

__all__ = ["warps", "warp", "warp_pdf", "warp_invert"]


def warps() -> list[dict]:
    """Every warp: name, description, domain, measure (of the pdf), area_preserving, params."""
    return _stratum._warps()


def _params(name: str, given: dict) -> dict:
    """Flattened float lists; width/height filled from the shape of ``values``."""
    known = {w["name"]: w for w in _stratum._warps()}
    spec = {p["name"] for p in known[name]["params"]} if name in known else set()
    params = {}
    for key, value in given.items():
        params[key] = _checks.real_array(key, value, "a number or an array of numbers").ravel().tolist()
    if "values" in given and "width" in spec and "width" not in given:
        shape = np.shape(given["values"])
        if len(shape) == 1:
            params["width"] = [float(shape[0])]
        elif len(shape) == 2 and "height" in spec and "height" not in given:
            params["height"], params["width"] = [float(shape[0])], [float(shape[1])]
    return params


def warp(name: str, u, **params) -> np.ndarray:
    """Warped points of u (n, input_dim) in [0,1): an (n, output_dim) array."""
    return _stratum._warp_sample(_checks.text("name", name), _checks.real_array("u", u), _params(name, params))


def warp_pdf(name: str, p, **params) -> np.ndarray:
    """Density at points p (n, output_dim), per area, solid angle or length: an (n,) array."""
    return _stratum._warp_pdf(_checks.text("name", name), _checks.real_array("p", p), _params(name, params))


def warp_invert(name: str, p, **params) -> np.ndarray:
    """The u in [0,1)^input_dim that warp maps to p: an (n, input_dim) array."""
    return _stratum._warp_invert(_checks.text("name", name), _checks.real_array("p", p), _params(name, params))
