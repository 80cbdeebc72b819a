"""Rendering: the camera integral, area lights and path tracing (LECTURE.md §1–3, 8, 9).

The same renderer as `stratum render` and `stratum compare` (docs/render.md);
present only when the compiled module was built with the renderer.
"""
from __future__ import annotations

import json

from . import _stratum

__all__ = ["render", "compare", "comparisons"] if hasattr(_stratum, "comparisons") else []


def _shown(value):
    """repr(value) for a message: cut to 80 characters, and never a RecursionError."""
    try:
        text = repr(value)
    except RecursionError:
        return "(a value nested too deeply to show)"
    return text if len(text) <= 80 else text[:77] + "..."


def _error(name, value, allowed):
    return _stratum.InvalidArgument(f"invalid {name} = {_shown(value)}: {allowed}")


def render(scene=None, width: int | None = None, height: int | None = None, spp: int = 16, integrator: str = "direct",
           light_samples: int = 1, light_strategy: str = "area", hemisphere: str = "cosine", sampler: str = "sobol",
           randomize: str | None = None, time_pattern: str | None = None, seed: int = 0, threads: int = 1,
           pixel_centers: bool = False, max_depth: int = 5, passes: int = 4, with_variance: bool = False,
           reference: bool = False, reference_spp: int = 1024, cache=".stratum-cache", frame: int = 0):
    """Renders `scene` (a JSON scene file, docs/scenes.md; None: the built-in
    Cornell box) and returns the linear image as float64 of shape
    (height, width, 3), top row first.

    The options are those of `stratum render`; sampler is a spec
    (docs/samplers.md), e.g. "sobol:owen" or "cmj(aspect=2)", whose
    parameters hold for every set it draws. with_variance=True returns
    (image, variance): the variance of each pixel's mean per channel (the
    samples taken as independent). reference=True returns the converged
    reference of this estimand instead (reference_spp Owen-scrambled Sobol'
    samples), loaded from or stored in the folder `cache`. frame=K renders
    frame K of an animation: a progressive sampler (sobol, halton, pmj02,
    random, ...) continues each pixel's sequence (samples K*spp onwards, so
    frames 0..K-1 together are one frame at K*spp); others take a fresh seed.
    Raises stratum.InvalidArgument naming the argument at fault."""
    # Every check is the library's (stratum/render/render_job.hpp), as for `stratum render`.
    image, variance, _, _, _ = _stratum.render(
        scene=scene, width=width, height=height, spp=spp, integrator=integrator, light_samples=light_samples,
        light_strategy=light_strategy, hemisphere=hemisphere, max_depth=max_depth, sampler=sampler,
        randomize=randomize, time_pattern=time_pattern, seed=seed, threads=threads, passes=passes,
        pixel_centers=pixel_centers, reference=reference, reference_spp=reference_spp, cache=cache, frame=frame,
        with_variance=with_variance)
    if with_variance:
        return image, variance
    return image


def comparisons() -> list[dict]:
    """The built-in comparisons: name and description (LECTURE.md section)."""
    return _stratum.comparisons()


def compare(scene=None, builtin: str | None = None, configs: list[dict] | None = None, reference_spp: int = 1024,
            cache=".stratum-cache", equal_time: float | None = None, variance_dir=None, width: int = 64,
            height: int = 64, threads: int = 1, seed: int = 0, repeats: int = 1,
            confidence: float | None = None) -> list[dict]:
    """Renders each configuration and measures it against its converged
    reference, as `stratum compare`: one dict per configuration with label,
    spp (samples taken), passes, mse, relative_mse, seconds, efficiency
    (1 / (mse × seconds)), mse_ratio and efficiency_ratio (against the
    first), variance (the file) with variance_dir, and scene_note: what
    the comparison's scene leaves out ("" when nothing; without a scene, the
    built-in Cornell box loses its lens and, but for "time-pattern", its motion).

    builtin: a name from comparisons() (default "shadow-rays"); configs: a
    list of dicts with the keys of a configuration file (docs/render.md).
    equal_time: seconds per configuration (independent passes until then);
    None compares at equal samples.

    repeats: render every configuration with this many seeds (repeat k > 0
    with hash(seed, k)), paired: then mse and relative_mse are the means over
    the seeds, seconds the median, mse_ratio and efficiency_ratio the
    geometric means of the per-seed ratios, and each dict adds
    mse_per_seed, seconds_per_seed, mse_standard_error, mse_ratio_interval,
    time_ratio, time_ratio_interval, efficiency_ratio_interval ((low, high),
    Student-t on the logs at level `confidence`, default 0.95) and
    time_resolved (the time ratio's interval excludes 1: only then does the
    efficiency ratio say more than the MSE ratio)."""
    text = None
    if configs is not None:  # the library reads the JSON text, as the CLI's file
        try:
            text = json.dumps(configs)
        except RecursionError:
            raise _error("configs", configs, "must not nest lists and dicts deeper than 256 levels") from None
        except (TypeError, ValueError) as e:
            raise _error("configs", configs, f"must be a list of JSON-serializable dicts ({e})") from None
    # Every other check is the library's (stratum/render/render_job.hpp), as for `stratum compare`.
    return _stratum.compare(scene=scene, builtin=builtin, configs=text, reference_spp=reference_spp, cache=cache,
                            equal_time=equal_time, variance_dir=variance_dir, width=width, height=height,
                            threads=threads, seed=seed, repeats=repeats, confidence=confidence)
