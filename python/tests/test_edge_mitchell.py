"""Edge discrepancies and Mitchell's study through the Python face.

Oracles: an independent numpy search over directions (closed-form half-plane
area, exact best offset per direction) that can only find lines that exist,
so it bounds the exact edge discrepancy from below and must come close; the
binomial law of a random pattern; Mitchell's ordering of patterns (1992)."""
import numpy as np
import pytest

import stratum


def half_plane_area(a, b, c):
    """Area of {x in [0,1]^2 : a x + b y < c} for a, b != 0: reflect to a, b > 0, then
    inclusion-exclusion of the four corner triangles."""
    c = np.where(a < 0, c - a, c)
    a = np.abs(a)
    c = np.where(b < 0, c - b, c)
    b = np.abs(b)
    ramp = lambda t: np.maximum(t, 0.0) ** 2  # noqa: E731
    return (ramp(c) - ramp(c - a) - ramp(c - b) + ramp(c - a - b)) / (2 * a * b)


def search_edge_discrepancy(x, angles=20000):
    theta = (np.arange(angles) + 0.37) * np.pi / angles  # never exactly axis-aligned
    normal = np.stack([np.cos(theta), np.sin(theta)], axis=1)
    projections = np.sort(x @ normal.T, axis=0)  # (n, angles)
    n = x.shape[0]
    area = half_plane_area(normal[:, 0][None, :], normal[:, 1][None, :], projections)
    index = np.arange(n)[:, None]
    # Random data: no ties, so at projection i the open count is i and the closed count i + 1.
    return float(np.max(np.maximum((index + 1) / n - area, area - index / n)))


def test_area_closed_form_sanity():
    assert half_plane_area(np.array(1.0), np.array(1.0), np.array(1.0)) == pytest.approx(0.5)
    assert half_plane_area(np.array(-1.0), np.array(2.0), np.array(0.0)) == pytest.approx(0.25)


@pytest.mark.parametrize("n,seed", [(5, 1), (12, 2), (30, 3)])
def test_exact_edge_against_search(n, seed):
    x = np.random.default_rng(seed).random((n, 2))
    exact = stratum.discrepancy(x, "edge")
    found = search_edge_discrepancy(x)
    # The search evaluates real lines: a lower bound. Its direction step π/20000 moves
    # the area by at most ~1.6e-4 from the supremum's limit.
    assert found <= exact + 1e-12
    assert found >= exact - 5e-4
    result = stratum.measure(x, "edge")
    assert result["kind"] == "exact" and result["value"] == exact


def test_edge_random_faces_and_bounds():
    x = stratum.points("random", 200, 2, seed=4)
    result = stratum.measure(x, "edge-random", lines=3000, seed=7)
    assert result["kind"] == "estimate"
    assert stratum.discrepancy(x, "edge-random", lines=3000, seed=7) == result["value"]
    extras = result["extras"]
    assert extras["mean"] <= result["value"] <= extras["max"] <= stratum.discrepancy(x, "edge") + 1e-12
    assert stratum.measure(x, "edge-random", lines=3000, seed=7, threads=2)["value"] == result["value"]
    assert stratum.measure(x, "edge-random", lines=3000, seed=8)["value"] != result["value"]


@pytest.mark.parametrize("name,params,message", [
    ("edge", {}, "invalid d = 3"),
    ("edge-random", {"lines": 0}, "invalid lines = 0"),
    ("edge-random", {"lines": -5}, "invalid lines = -5"),
])
def test_edge_bad_input(name, params, message):
    x = np.random.default_rng(0).random((10, 3 if message.startswith("invalid d") else 2))
    with pytest.raises(stratum.InvalidArgument, match=message):
        stratum.measure(x, name, **params)


def test_study_mitchell_structure_and_ordering():
    study = stratum.study_mitchell(counts=(16, 256), realizations=12, lines=1500, seed=3)
    assert [p["sampler"] for p in study["patterns"]] == ["zaremba", "jittered", "poisson-disk", "n-rooks", "random"]
    cells = {p["sampler"]: {c["requested"]: c for c in p["cells"]} for p in study["patterns"]}
    for sampler, row in cells.items():
        for n in (16, 256):
            assert row[n]["n"] == n and len(row[n]["rms_values"]) == 12
            assert row[n]["rms"]["mean"] == pytest.approx(np.mean(row[n]["rms_values"]), rel=1e-12)
    # Zaremba's set does not depend on the seed: its mean RMS over 12 x 1500 lines agrees with
    # the measure face's RMS over 200000 lines (two-sided z < 4.4; the Jensen bias of an RMS over
    # 1500 lines, about CV(D^2)^2/(8L) ~ 1e-3 relative, is far below the standard error).
    zaremba = stratum.points("zaremba", 256, 2, randomize="none")
    reference = stratum.discrepancy(zaremba, "edge-random", lines=200000, seed=1)
    se = cells["zaremba"][256]["rms"]["se"]
    assert abs(cells["zaremba"][256]["rms"]["mean"] - reference) < 4.4 * se * np.sqrt(1 + 12 * 1500 / 200000)
    # Mitchell's ordering at N = 256 with a wide margin (one-sided z > 4.4: α = 1e-5 per
    # comparison, 4 comparisons).
    for better in ("jittered", "poisson-disk"):
        for worse in ("random", "n-rooks"):
            b, w = cells[better][256]["rms"], cells[worse][256]["rms"]
            assert (w["mean"] - b["mean"]) / np.hypot(w["se"], b["se"]) > 4.4, (better, worse)
    # Random patterns: E[D^2] = E[A(1 - A)]/N for every line, so RMS shrinks as N^(-1/2): 16x the points, 1/4 the RMS.
    ratio = cells["random"][16]["rms"]["mean"] / cells["random"][256]["rms"]["mean"]
    assert 3.0 < ratio < 5.0
    spectrum = study["patterns"][4]["spectrum"]
    assert spectrum["n"] == 256 and len(spectrum["frequency"]) == len(spectrum["power"])
    assert len(study["patterns"][0]["example"]) == 2 * 256
    assert "Zaremba" in study["table"]


@pytest.mark.parametrize("kwargs,message", [
    ({"counts": (1,)}, "invalid counts = 1"),
    ({"counts": ()}, "invalid counts"),
    ({"counts": "16"}, "invalid counts"),
    ({"realizations": 0}, "invalid realizations = 0"),
    ({"lines": 0}, "invalid lines = 0"),
    ({"lines": 2.5}, "invalid lines = 2.5"),
    ({"seed": -1}, "invalid seed = -1"),
])
def test_study_mitchell_bad_input(kwargs, message):
    with pytest.raises(stratum.InvalidArgument, match=message):
        stratum.study_mitchell(**kwargs)


def test_study_mitchell_extra_samplers_add_rows_and_leave_the_five_unchanged():
    five = stratum.study_mitchell(counts=(16, 64), realizations=2, lines=200, seed=3)
    seven = stratum.study_mitchell(counts=(16, 64), realizations=2, lines=200, seed=3, samplers=["sobol:owen", "halton"])
    assert [p["label"] for p in seven["patterns"]][5:] == ["sobol:owen", "halton"]
    assert seven["patterns"][:5] == five["patterns"]
    with pytest.raises(stratum.InvalidArgument, match="sampler"):
        stratum.study_mitchell(counts=(16,), samplers=["no-such"])
