"""stratum.render / compare / comparisons: the renderer from Python (docs/render.md)."""
import json
import os
import subprocess

import numpy as np
import pytest
from scipy import stats

import stratum

from build_parts import NO_RENDERER, RENDERER

# Whether the renderer is built comes from the build (build_parts.py), not from
# a name: a renamed function fails test_build_parts instead of skipping these.
pytestmark = pytest.mark.skipif(not RENDERER, reason=NO_RENDERER)


def scene_file(tmp_path, name, shape, rho, camera):
    scene = {"camera": camera, "materials": {"grey": {"reflectance": [rho] * 3}},
             "shapes": [dict(shape, material="grey")], "lights": [{"type": "environment", "radiance": [1, 1, 1]}]}
    path = tmp_path / f"{name}.json"
    path.write_text(json.dumps(scene))
    return path


def furnace(tmp_path, rho):
    """A diffuse sphere under a constant sky of radiance 1: a convex surface
    never sees itself, so it reflects exactly rho (the white furnace)."""
    return scene_file(tmp_path, "furnace", {"type": "sphere", "center": [0, 0, 0], "radius": 1}, rho,
                      {"position": [0, 0, -4], "look_at": [0, 0, 0], "fov": 40, "resolution": [16, 16]})


def uniform_plane(tmp_path, rho):
    """A plane filling the view under the sky: every pixel sees the same integrand."""
    return scene_file(tmp_path, "plane", {"type": "quad", "corner": [-100, 0, 100], "edge_u": [200, 0, 0],
                                          "edge_v": [0, 0, -200]}, rho,
                      {"position": [0, 1, 0], "look_at": [0, 0, 0], "up": [0, 0, 1], "fov": 40, "resolution": [8, 8]})


def test_comparisons_are_listed():
    names = [c["name"] for c in stratum.comparisons()]
    assert {"shadow-rays", "light-strategy", "hemisphere", "time-pattern", "path", "pixel-samplers"} <= set(names)
    assert all(c["description"] for c in stratum.comparisons())


def test_furnace_is_exact_with_cosine_irradiance(tmp_path):
    # With cosine-weighted directions every sample is rho exactly (p ∝ f: zero variance, LECTURE.md §3).
    image, variance = stratum.render(furnace(tmp_path, 0.6), spp=4, integrator="irradiance", light_samples=2,
                                     hemisphere="cosine", sampler="random", with_variance=True)
    assert image.shape == (16, 16, 3) and image.dtype == np.float64 and variance.shape == (16, 16, 3)
    np.testing.assert_allclose(image[7:9, 7:9], 0.6, atol=1e-9)  # the sphere's centre
    np.testing.assert_allclose(image[[0, 0, -1, -1], [0, -1, 0, -1]], 1.0, atol=1e-12)  # the sky in the corners
    np.testing.assert_allclose(variance[7:9, 7:9], 0.0, atol=1e-15)


def test_uniform_hemisphere_mean_and_variance_have_their_closed_forms(tmp_path):
    # Y = 2 rho cos θ, cos θ ~ U[0, 1): E = rho, V = rho²/3; the pixel mean of
    # N eye rays × M directions has variance rho²/(3NM). 64 i.i.d. pixels,
    # two t-tests, Šidák: α = 0.001 overall, two-sided.
    rho, n, m = 0.5, 4, 2
    image, variance = stratum.render(uniform_plane(tmp_path, rho), spp=n, integrator="irradiance", light_samples=m,
                                     hemisphere="uniform", sampler="random", seed=11, with_variance=True)
    alpha = 1 - (1 - 0.001) ** 0.5
    assert stats.ttest_1samp(image[..., 0].ravel(), rho).pvalue > alpha
    assert stats.ttest_1samp(variance[..., 0].ravel(), rho**2 / (3 * n * m)).pvalue > alpha
    # power: the variance of one sample (no 1/NM) is rejected
    assert stats.ttest_1samp(variance[..., 0].ravel(), rho**2 / 3).pvalue < alpha


def test_same_seed_same_image_for_any_thread_count():
    a = stratum.render(width=12, height=8, spp=4, seed=5)
    b = stratum.render(width=12, height=8, spp=4, seed=5, threads=2)
    c = stratum.render(width=12, height=8, spp=4, seed=6)
    assert a.shape == (8, 12, 3)
    np.testing.assert_array_equal(a, b)
    assert not np.array_equal(a, c)


def test_frames_of_a_progressive_sampler_together_are_one_frame_at_k_times_spp():
    frames = [stratum.render(width=8, height=8, spp=2, sampler="halton", passes=1, frame=k) for k in range(3)]
    whole = stratum.render(width=8, height=8, spp=6, sampler="halton", passes=1)
    np.testing.assert_allclose(np.mean(frames, axis=0), whole, rtol=1e-12, atol=1e-12)
    np.testing.assert_array_equal(frames[0], stratum.render(width=8, height=8, spp=2, sampler="halton", passes=1))
    assert not np.array_equal(frames[0], frames[1])
    # Not progressive: a fresh seed per frame.
    jittered = [stratum.render(width=8, height=8, spp=4, sampler="jittered", frame=k) for k in range(2)]
    assert not np.array_equal(*jittered)


def test_reference_is_cached(tmp_path):
    first = stratum.render(width=10, height=8, reference=True, reference_spp=16, cache=tmp_path / "cache")
    second = stratum.render(width=10, height=8, reference=True, reference_spp=16, cache=tmp_path / "cache")
    np.testing.assert_array_equal(first.astype(np.float32), second)  # cached as 32-bit EXR
    assert len(list((tmp_path / "cache").glob("*.exr"))) == 2  # the reference and its variance


def test_compare_at_equal_samples_and_equal_time(tmp_path):
    rows = stratum.compare(builtin="shadow-rays", width=8, height=8, reference_spp=32, cache=tmp_path / "cache")
    assert [r["label"] for r in rows] == ["1 shadow ray", "16 shadow rays"]
    assert rows[0]["mse_ratio"] == 1 and all(r["mse"] > 0 and r["spp"] == 4 and r["passes"] == 1 for r in rows)
    configs = [{"label": "random", "spp": 4, "sampler": "random"}, {"label": "sobol", "spp": 4, "sampler": "sobol"}]
    timed = stratum.compare(configs=configs, width=8, height=8, reference_spp=32, cache=tmp_path / "cache",
                            equal_time=0.05, variance_dir=tmp_path / "var")
    assert [r["label"] for r in timed] == ["random", "sobol"]
    for r in timed:
        assert r["seconds"] >= 0.05 and r["spp"] == 4 * r["passes"]
        assert (tmp_path / "var").is_dir() and r["variance"].startswith(str(tmp_path / "var"))


def test_compare_repeated_over_paired_seeds(tmp_path):
    one = stratum.compare(builtin="shadow-rays", width=8, height=8, reference_spp=32, cache=tmp_path / "cache")
    rows = stratum.compare(builtin="shadow-rays", width=8, height=8, reference_spp=32, cache=tmp_path / "cache",
                           repeats=3, confidence=0.9)
    for r, first in zip(rows, one):
        assert r["mse_per_seed"][0] == first["mse"] and len(set(r["mse_per_seed"])) == 3
        assert r["mse"] == pytest.approx(np.mean(r["mse_per_seed"]), rel=1e-12)
        assert r["seconds"] == np.median(r["seconds_per_seed"])
    low, high = rows[1]["mse_ratio_interval"]
    assert 1 < low < rows[1]["mse_ratio"] < high
    assert "mse_per_seed" not in one[1]  # one repeat: the plain comparison's dicts


@pytest.mark.parametrize("call, word", [
    (lambda: stratum.render(spp=0), "spp"),
    (lambda: stratum.render(width=0), "width"),
    (lambda: stratum.render(integrator="bdpt", width=4, height=4), "integrator"),
    (lambda: stratum.render(light_strategy="cone", width=4, height=4), "light-strategy"),
    (lambda: stratum.render(sampler="no-such", width=4, height=4), "sampler"),
    (lambda: stratum.render(seed=-1), "seed"),
    (lambda: stratum.render(frame=-1), "frame"),
    (lambda: stratum.render(frame=1.5), "frame"),
    (lambda: stratum.render(spp=16, frame=2**28, width=4, height=4), "frame"),
    (lambda: stratum.render("/no/such/scene.json"), "scene"),
    (lambda: stratum.compare(builtin="nope"), "comparison"),
    (lambda: stratum.compare(configs=[{"colour": 1}], width=4, height=4), "colour"),
    (lambda: stratum.compare(configs=[{"spp": 1}], builtin="path"), "configs"),
    (lambda: stratum.compare(equal_time=-1), "equal-time"),
    (lambda: stratum.compare(equal_time="1"), "equal_time"),
    (lambda: stratum.compare(builtin="path", configs=[{"spp": 1}]), "not both"),
    (lambda: stratum.compare(repeats=0), "repeats"),
    (lambda: stratum.compare(confidence=0.9), "confidence"),
    (lambda: stratum.compare(repeats=2, confidence=1.5), "confidence"),
])
def test_bad_input_names_the_argument(call, word):
    with pytest.raises(stratum.InvalidArgument, match=word):
        call()


def test_exact_disk_light_covers_exactly_its_closed_form_footprint(tmp_path):
    # A pinhole at the origin looks up (+y) at a lamp disk of radius 1 at
    # height 2 (fov 90°: the film spans [-1, 1]² at unit distance). The ray
    # through film point (sx, sy) meets the disk iff 4 (sx² + sy²) <= 1, and
    # then sees its emission 2; otherwise black. The 16-gon misses the rim.
    def scene(extra):
        path = tmp_path / f"disk{len(extra)}.json"
        path.write_text(json.dumps({
            "camera": {"position": [0, 0, 0], "look_at": [0, 1, 0], "up": [0, 0, 1], "fov": 90, "resolution": [64, 64]},
            "materials": {"lamp": {"reflectance": [0, 0, 0], "emission": [2, 2, 2]}},
            "shapes": [dict({"type": "disk", "center": [0, 2, 0], "normal": [0, -1, 0], "radius": 1,
                             "material": "lamp"}, **extra)]}))
        return str(path)
    s = (2 * (np.arange(64) + 0.5) / 64 - 1)
    r2 = 4 * (s[None, :] ** 2 + s[:, None] ** 2)
    clear = np.abs(r2 - 1) > 1e-3  # away from the rim, where float rays could round either way
    exact = stratum.render(scene({}), spp=1, pixel_centers=True, passes=1)[:, :, 0]
    assert np.array_equal(exact[clear], np.where(r2 <= 1, 2.0, 0.0)[clear])
    polygon = stratum.render(scene({"segments": 16}), spp=1, pixel_centers=True, passes=1)[:, :, 0]
    assert np.sum(polygon[clear] != exact[clear]) > 0


# The CLI of the same build: <build>/python/stratum/ beside <build>/bin/stratum.
STRATUM_EXE = os.path.join(os.path.dirname(stratum.__file__), os.pardir, os.pardir, "bin", "stratum")


@pytest.mark.parametrize("keywords, flags", [
    ({"spp": 0}, ["--spp", "0"]),
    ({"spp": 2**24 + 1}, ["--spp", "16777217"]),
    ({"width": 0}, ["--width", "0"]),
    ({"height": 16385}, ["--height", "16385"]),
    ({"frame": 2**28, "spp": 16}, ["--frame", "268435456", "--spp", "16"]),
    ({"passes": 0}, ["--passes", "0"]),
    ({"light_samples": 0}, ["--light-samples", "0"]),
    ({"max_depth": 2000}, ["--max-depth", "2000"]),
    ({"reference_spp": 0}, ["--reference-spp", "0"]),
    ({"sampler": "sobol:permute"}, ["--sampler", "sobol:permute"]),
    ({"sampler": "jittered", "spp": 8}, ["--sampler", "jittered", "--spp", "8"]),
    ({"time_pattern": "cook", "spp": 8}, ["--time-pattern", "cook", "--spp", "8"]),
    ({"seed": -1}, ["--seed", "-1"]),
    ({"threads": 5000}, ["--threads", "5000"]),
])
def test_render_refuses_what_the_cli_refuses_with_the_same_words(keywords, flags, tmp_path):
    # One check for both faces (stratum/render/render_job.hpp): the message
    # after the argument's name is the CLI's, word for word.
    if not os.access(STRATUM_EXE, os.X_OK):
        pytest.skip("no stratum executable beside the package")
    size = {key: 4 for key in ("width", "height") if key not in keywords}
    with pytest.raises(stratum.InvalidArgument) as python:
        stratum.render(**dict(size, **keywords))
    size_flags = [text for key in size for text in (f"--{key}", "4")]
    cli = subprocess.run([STRATUM_EXE, "render", "-q", "-o", str(tmp_path / "x.png"), *size_flags, *flags],
                         capture_output=True, text=True)
    assert cli.returncode != 0 and not (tmp_path / "x.png").exists()
    allowed = str(python.value).split(": ", 1)[1]
    assert allowed in cli.stderr, (str(python.value), cli.stderr)


@pytest.mark.parametrize("keywords, word", [
    ({"spp": True}, "spp"),            # a bool is not a count
    ({"spp": 4.0}, "spp"),             # nor is a float
    ({"spp": 2**70}, "spp"),           # beyond 64 bits: refused, not wrapped
    ({"light_samples": 2**33}, "light_samples"),  # beyond the setting's 32 bits
    ({"threads": 2**70}, "threads"),
    ({"seed": 2**64}, "seed"),
    ({"seed": "1"}, "seed"),
    ({"pixel_centers": 1}, "pixel_centers"),
    ({"cache": 3}, "cache"),
    ({"sampler": None}, "sampler"),
])
def test_render_keywords_are_typed(keywords, word):
    with pytest.raises(stratum.InvalidArgument, match=f"invalid {word} = "):
        stratum.render(**dict({"width": 4, "height": 4}, **keywords))


def test_the_binding_takes_keywords_only_and_names_an_unknown_one():
    from stratum import _stratum
    with pytest.raises(TypeError):
        _stratum.render("scene.json", 4, 4)  # no positional arguments
    with pytest.raises(stratum.InvalidArgument, match="invalid keyword = colour: is not an argument"):
        _stratum.render(width=4, height=4, spp=1, colour=1)
    image, variance, samples, _, cached = _stratum.render(width=np.int64(4), height=np.int32(3), spp=np.uint8(2),
                                                          passes=1)
    assert image.shape == (3, 4, 3) and variance.shape == (3, 4, 3) and samples == 2 and cached is False


@pytest.mark.parametrize("keywords, flags", [
    ({"width": 0}, ["--width", "0"]),
    ({"height": 20000}, ["--height", "20000"]),
    ({"reference_spp": 0}, ["--reference-spp", "0"]),
    ({"repeats": 1001}, ["--repeats", "1001"]),
    ({"confidence": 0.9}, ["--confidence", "0.9"]),
    ({"repeats": 2, "confidence": 1.5}, ["--repeats", "2", "--confidence", "1.5"]),
    ({"equal_time": -1}, ["--equal-time", "-1"]),
    ({"builtin": "nope"}, ["--builtin", "nope"]),
])
def test_compare_refuses_what_the_cli_refuses_with_the_same_words(keywords, flags):
    if not os.access(STRATUM_EXE, os.X_OK):
        pytest.skip("no stratum executable beside the package")
    with pytest.raises(stratum.InvalidArgument) as python:
        stratum.compare(**keywords)
    cli = subprocess.run([STRATUM_EXE, "compare", *flags], capture_output=True, text=True)
    assert cli.returncode != 0
    allowed = str(python.value).split(": ", 1)[1]
    assert allowed in cli.stderr, (str(python.value), cli.stderr)
