"""Fourier spectra and pair correlation of point sets (LECTURE.md §8, §12, §13).

>>> import stratum
>>> x = stratum.points("jittered", 256, 2)
>>> s = stratum.spectrum(x, max_frequency=32)
>>> s["power"].shape, s["power"][32, 32]        # P(0) = N
((65, 65), 256.0)

``spectrum`` returns the periodogram P(k) = |Σ_j exp(−2πi k·x_j)|² / N on
the integer frequencies k ∈ [−K, K]^d (d = 1 or 2; ``power[ky + K, kx + K]``),
averaged over realizations, with its radial average over rings one frequency
wide and the anisotropy in dB (Lagae & Dutré 2008), the effective Nyquist
frequency and the oscillation (Heck, Schlömer & Deussen 2013). Frequencies in
``frequencies``, ``radial["frequency"]`` and ``nyquist`` are divided by √N.
"""
from __future__ import annotations

import math
import numbers

import numpy as np

from . import _checks, _stratum
from ._stratum import InvalidArgument

__all__ = ["spectrum", "pair_correlation", "image_spectrum", "temporal_spectrum", "optimize_blue_noise"]


def _realizations(x) -> np.ndarray:
    """x as a C-ordered float64 array of shape (K, n, d)."""
    if isinstance(x, (list, tuple)) and x and all(np.ndim(item) == 2 for item in x):
        shapes = {np.shape(item) for item in x}
        if len(shapes) != 1:
            raise InvalidArgument(f"invalid x = realizations of shapes {sorted(shapes)}: all must have the same (n, d)")
    array = _checks.real_array("x", x, "an array of shape (n, d) or a list / array of K such arrays")
    if array.ndim == 1:
        array = array[None, :, None]
    elif array.ndim == 2:
        array = array[None]
    if array.ndim != 3 or array.shape[0] == 0:
        raise InvalidArgument(f"invalid x = array of shape {array.shape}: must have shape (n, d) or (K, n, d)")
    return np.ascontiguousarray(array)


def _positive_int(name, value):
    if isinstance(value, bool) or not isinstance(value, (numbers.Integral, np.integer)) or not 1 <= value < 2**31:
        raise InvalidArgument(f"invalid {name} = {value!r}: must be a positive integer below 2^31")
    return int(value)


def image_spectrum(image, reference=None) -> dict:
    """The power spectrum of an image (docs/render.md): of its luminance
    (Rec. 709 weights) when it has 3 channels, of ``image - reference`` when
    a reference is given (a render's error). Normalized so that white noise
    has power 1 at every frequency but 0 (the mean is removed): returns
    ``power`` (array (H, W), zero frequency at [H//2, W//2]),
    ``low_frequency_power`` (the mean below a quarter of Nyquist: 1 white,
    < 1 blue noise), ``variance`` and ``radial`` (frequency in cycles per
    pixel, power), as ``stratum spectrum --image``."""
    values = np.asarray(image, dtype=np.float64)
    if reference is not None:
        ref = np.asarray(reference, dtype=np.float64)
        if ref.shape != values.shape:
            raise InvalidArgument(f"invalid reference = an array of shape {ref.shape}: "
                                  f"must have the image's shape {values.shape}")
        values = values - ref
    if values.ndim == 3 and values.shape[2] == 3:
        values = values @ np.array([0.2126, 0.7152, 0.0722])
    result = _stratum._image_spectrum(np.ascontiguousarray(values))
    result["radial"] = {key: np.asarray(value) for key, value in result["radial"].items()}
    return result


def temporal_spectrum(frames) -> dict:
    """The temporal spectrum of an animation's frames (docs/blue-noise.md):
    where each pixel's value (its error) goes in time. ``frames`` has shape
    (F, H, W), or (F, H, W, 3) for the luminance (Rec. 709 weights), F >= 9,
    or is a list of F such images. Each pixel's series minus its mean is
    transformed over time and the pixels pooled, normalized so that frames
    independent in time have power 1 at every frequency but 0. Returns
    ``frequency`` (k / F cycles per frame, k = 1 .. F // 2), ``power``,
    ``low_frequency_power`` (mean below 1/8 cycle per frame: 1 white, < 1
    blue in time), ``lag1_correlation`` (of consecutive frames) and
    ``variance``, as ``stratum spectrum --frames``. A reference image is not
    needed: it would cancel with each pixel's mean."""
    if isinstance(frames, (list, tuple)):
        shapes = {np.shape(frame) for frame in frames}
        if len(shapes) > 1:
            raise InvalidArgument(f"invalid frames = images of shapes {sorted(shapes)}: all must have one shape")
    values = _checks.real_array("frames", frames, "an array of shape (F, H, W) or (F, H, W, 3), or a list of images")
    if values.ndim == 4 and values.shape[3] == 3:
        values = values @ np.array([0.2126, 0.7152, 0.0722])
    result = _stratum._temporal_spectrum(np.ascontiguousarray(values))
    for key in ("frequency", "power"):
        result[key] = np.asarray(result[key])
    return result


def _count(name, value, low, high):
    if isinstance(value, bool) or not isinstance(value, (numbers.Integral, np.integer)) or not low <= value <= high:
        raise InvalidArgument(f"invalid {name} = {value!r}: must be an integer in [{low}, {high}]")
    return int(value)


def optimize_blue_noise(size: int = 128, dims: int = 8, seed: int = 0, max_spp: int = 16, integrands: int = 32,
                        sweeps: int = 256, output=None, base: str = "sobol",
                        structure: str = "morton") -> dict:
    """The rank tile of sobol-bn, pmj02-bn or lattice-bn (``base`` "sobol",
    "pmj02" or "lattice"; docs/blue-noise.md), as ``stratum optimize
    blue-noise``; ``structure`` "morton" (ZSobol-like Morton-structured ranks,
    the default) or "free": per-pixel ranks (which block of the shared randomized base
    sequence a pixel takes) swapped between pixels so that the
    blurred error of test heavisides at spp = 1, 2, ..., max_spp is small.
    Deterministic: the same arguments give the same bytes as the CLI. Returns
    ``ranks`` (uint16 array (size, size, dims // 2)), ``bytes`` (the file) and
    ``pairs`` (per dimension pair: initial and final energy, white = 1, and
    the swaps accepted and proposed); with ``output`` the file is written
    there (whole or not at all), for ``stratum.points("sobol-bn", ...,
    table=output)`` (or pmj02-bn, lattice-bn)."""
    if not isinstance(base, str):
        raise InvalidArgument(f"invalid base = {base!r}: allowed: sobol, pmj02, lattice")
    if not isinstance(structure, str):
        raise InvalidArgument(f"invalid structure = {structure!r}: allowed: morton, free")
    data, pairs = _stratum._optimize_blue_noise(
        base, structure,
        _count("size", size, 0, 1 << 20), _count("dims", dims, 0, 1 << 20),
        _count("seed", seed, 0, (1 << 64) - 1), _count("max_spp", max_spp, 0, 1 << 20),
        _count("integrands", integrands, 0, 1 << 20), _count("sweeps", sweeps, 0, 1 << 20))
    if output is not None:
        import os
        import tempfile
        target = os.fspath(output)
        folder = os.path.dirname(os.path.abspath(target))
        handle, staging = tempfile.mkstemp(dir=folder, prefix=".stratum-")
        try:
            with os.fdopen(handle, "wb") as f:
                f.write(data)
            os.replace(staging, target)
        except BaseException:
            if os.path.exists(staging):
                os.remove(staging)
            raise
    ranks = np.frombuffer(data, dtype="<u2", offset=44).reshape(size, size, dims // 2)
    return {"ranks": ranks, "bytes": data, "pairs": pairs}


def spectrum(x, max_frequency: int | None = None, threads: int = 1) -> dict:
    """The mean periodogram of one point set (array (n, d)) or of K
    realizations (a list of (n, d) arrays, or an array (K, n, d)), d = 1 or 2.

    max_frequency K defaults to 2.5 √N (at least 16, at most 1024), as in the
    CLI. Returns a dict: ``power`` (array (2K+1, 2K+1), or (2K+1,) for d = 1),
    ``frequencies`` (the integer frequencies −K..K divided by √N), ``radial``
    (dict: frequency, radius, power, anisotropy_db, count; ring r = 1..K),
    ``anisotropy_db`` (same as radial["anisotropy_db"]), ``nyquist`` (effective
    Nyquist / √N), ``nyquist_is_lower_bound``, ``oscillation``,
    ``oscillation_window``, ``max_frequency``, ``realizations``.
    The result does not depend on ``threads``."""
    array = _realizations(x)
    n = array.shape[1]
    if max_frequency is None:
        max_frequency = min(1024, max(16, math.ceil(2.5 * math.sqrt(max(n, 1)))))
    k = _positive_int("max_frequency", max_frequency)
    result = _stratum._spectrum(array, k, _checks.threads(threads))
    result["frequencies"] = np.arange(-k, k + 1) / result["frequency_scale"]
    result["radial"] = {key: np.asarray(value) for key, value in result["radial"].items()}
    result["anisotropy_db"] = result["radial"]["anisotropy_db"]
    return result


def pair_correlation(x, radii=None, sigma: float | None = None, threads: int = 1) -> dict:
    """The pair correlation function g(r) of a point set (array (n, d), d ≤ 8),
    with toroidal distances and a Gaussian kernel of standard deviation sigma
    (Öztireli & Gross 2012). Defaults: 100 radii up to 2.5 times the densest
    packing distance of N points, sigma a tenth of that distance. g ≈ 1 for a
    uniform random set. Returns a dict: r, g (numpy arrays), sigma."""
    array = _checks.real_array("x", x, "an array of shape (n, d)")
    if array.ndim == 1:
        array = array[:, None]
    if array.ndim != 2:
        raise InvalidArgument(f"invalid x = array of shape {array.shape}: must have shape (n, d)")
    array = np.ascontiguousarray(array)
    if radii is None or sigma is None:
        if not 1 <= array.shape[1] <= 8:
            raise InvalidArgument(f"invalid d = {array.shape[1]}: the pair correlation is computed for d = 1..8")
        default_radii, default_sigma = _stratum._default_pair_correlation_grid(max(array.shape[0], 1), array.shape[1], 100)
        radii = default_radii if radii is None else radii
        sigma = default_sigma if sigma is None else sigma
    radii = np.atleast_1d(np.asarray(radii, dtype=np.float64)).ravel().tolist()
    result = _stratum._pair_correlation(array, radii, float(sigma), _checks.threads(threads))
    return {"r": np.asarray(result["r"]), "g": np.asarray(result["g"]), "sigma": result["sigma"]}
