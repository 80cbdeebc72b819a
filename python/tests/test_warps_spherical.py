"""stratum.warp / warp_pdf / warp_invert for the spherical-polygon and
tabulated warps, against independent oracles: the Van Oosterom–
Strackee solid angle, Lambert's projected-solid-angle formula, and
scipy.stats.rv_histogram for the tabulated densities. Statistical checks use
fixed seeds; their levels are stated where they are made."""
import numpy as np
import pytest
from scipy import stats

import stratum

TRIANGLE = np.array([[0.1, 0.05, 1.0], [1.0, 0.2, 1.0], [-0.1, 1.0, 1.0]])
RECTANGLE = dict(corner=[-0.4, -0.3, 1.0], edge_u=[0.9, 0.3, 0.0], edge_v=[-0.2, 0.6, 0.15])


def uniform(n, d, seed=1):
    return np.random.default_rng(seed).random((n, d))


def van_oosterom_strackee(p0, p1, p2, origin=np.zeros(3)):
    r = [np.asarray(p, float) - origin for p in (p0, p1, p2)]
    l = [np.linalg.norm(v) for v in r]
    numerator = abs(np.dot(r[0], np.cross(r[1], r[2])))
    denominator = l[0] * l[1] * l[2] + np.dot(r[0], r[1]) * l[2] + np.dot(r[0], r[2]) * l[1] + np.dot(r[1], r[2]) * l[0]
    return 2 * np.arctan2(numerator, denominator)


def rectangle_corners(corner, edge_u, edge_v):
    c, u, v = (np.asarray(x, float) for x in (corner, edge_u, edge_v))
    return [c, c + u, c + u + v, c + v]


def test_spherical_triangle_uniform_in_solid_angle():
    omega = van_oosterom_strackee(*TRIANGLE)
    w = stratum.warp("spherical-triangle", uniform(4000, 2), vertices=TRIANGLE)
    assert w.shape == (4000, 3)
    np.testing.assert_allclose(np.linalg.norm(w, axis=1), 1, atol=1e-12)
    # Inside: w is a non-negative combination of the vertices.
    coefficients = np.linalg.solve(TRIANGLE.T, w.T)
    assert np.all(coefficients >= -1e-12)
    np.testing.assert_allclose(stratum.warp_pdf("spherical-triangle", w, vertices=TRIANGLE), 1 / omega, rtol=1e-10)
    # The sub-triangle A B M (M the midpoint of edge AC) holds VOS(A, B, M) / Ω of the
    # samples: binomial test, two-sided level 1e-3.
    a, b, c = TRIANGLE
    m = (a + c) / 2
    share = van_oosterom_strackee(a, b, m) / omega
    inside = np.all(np.linalg.solve(np.array([a, b, m]).T, w.T) >= 0, axis=0)
    assert stats.binomtest(int(inside.sum()), len(w), share).pvalue > 1e-3


def test_spherical_triangle_inverse_and_orientation():
    u = uniform(2000, 2, seed=2)
    w = stratum.warp("spherical-triangle", u, vertices=TRIANGLE)
    np.testing.assert_allclose(stratum.warp_invert("spherical-triangle", w, vertices=TRIANGLE), u, atol=1e-9)
    # Reversing the vertex order changes the parametrization but not the density.
    reversed_vertices = TRIANGLE[::-1]
    assert np.all(stratum.warp_pdf("spherical-triangle", w, vertices=reversed_vertices) > 0)
    # Seen from another origin, directions still point at the triangle.
    origin = np.array([0.2, -0.1, -0.5])
    w = stratum.warp("spherical-triangle", u, vertices=TRIANGLE, origin=origin)
    coefficients = np.linalg.solve((TRIANGLE - origin).T, w.T)
    assert np.all(coefficients >= -1e-12)
    np.testing.assert_allclose(stratum.warp_pdf("spherical-triangle", w, vertices=TRIANGLE, origin=origin),
                               1 / van_oosterom_strackee(*TRIANGLE, origin=origin), rtol=1e-10)


def test_spherical_rectangle_solid_angle_as_two_triangles():
    p = rectangle_corners(**RECTANGLE)
    omega = van_oosterom_strackee(p[0], p[1], p[2]) + van_oosterom_strackee(p[0], p[2], p[3])
    u = uniform(3000, 2, seed=3)
    w = stratum.warp("spherical-rectangle", u, **RECTANGLE)
    np.testing.assert_allclose(stratum.warp_pdf("spherical-rectangle", w, **RECTANGLE), 1 / omega, rtol=1e-9)
    np.testing.assert_allclose(stratum.warp_invert("spherical-rectangle", w, **RECTANGLE), u, atol=1e-9)
    # Each ray hits the rectangle: plane coordinates in [0, 1]².
    corner, eu, ev = (np.asarray(RECTANGLE[k]) for k in ("corner", "edge_u", "edge_v"))
    normal = np.cross(eu, ev)
    hit = w * (np.dot(corner, normal) / (w @ normal))[:, None] - corner
    s, t = hit @ eu / eu.dot(eu), hit @ ev / ev.dot(ev)
    assert np.all((s > -1e-9) & (s < 1 + 1e-9) & (t > -1e-9) & (t < 1 + 1e-9))


def lambert(polygon, normal):
    """∫ |n·ω| dω over a polygon above the plane of n (Lambert 1760)."""
    n = np.asarray(normal, float) / np.linalg.norm(normal)
    v = [np.asarray(p, float) / np.linalg.norm(p) for p in polygon]
    total = 0.0
    for a, b in zip(v, v[1:] + v[:1]):
        cross = np.cross(a, b)
        total += np.arctan2(np.linalg.norm(cross), np.dot(a, b)) * np.dot(n, cross / np.linalg.norm(cross))
    return abs(total) / 2


@pytest.mark.parametrize("name,params,polygon", [
    ("spherical-triangle-projected", dict(vertices=TRIANGLE, normal=[0.6, 0, 0.8]), list(TRIANGLE)),
    ("spherical-rectangle-projected", dict(RECTANGLE, normal=[0.3, -0.4, 0.8]), rectangle_corners(**RECTANGLE)),
])
def test_projected_variants_estimate_irradiance_without_bias(name, params, polygon):
    u = uniform(20000, 2, seed=4)
    w = stratum.warp(name, u, **params)
    p = stratum.warp_pdf(name, w, **params)
    n = np.asarray(params["normal"], float) / np.linalg.norm(params["normal"])
    y = np.abs(w @ n) / p
    # Within 4.5 standard errors of Lambert's exact value (two-sided level 7e-6).
    assert abs(y.mean() - lambert(polygon, params["normal"])) < 4.5 * y.std() / np.sqrt(len(y))
    np.testing.assert_allclose(stratum.warp_invert(name, w, **params), u, atol=1e-9)


def test_piecewise_1d_matches_scipy_rv_histogram():
    values = np.array([0.5, 2, 0, 0, 3.25, 1, 0.125, 4, 0, 2.5])
    histogram = stats.rv_histogram((values, np.linspace(0, 1, len(values) + 1)), density=False)
    u = uniform(5000, 1, seed=5)[:, 0]
    x = stratum.warp("piecewise-1d", u, values=values, width=len(values))
    assert x.shape == (5000,)
    np.testing.assert_allclose(x, histogram.ppf(u), atol=1e-12)
    np.testing.assert_allclose(stratum.warp_pdf("piecewise-1d", x[:, None], values=values, width=len(values)),
                               histogram.pdf(x), rtol=1e-12)
    np.testing.assert_allclose(stratum.warp_invert("piecewise-1d", x, values=values, width=len(values)),
                               histogram.cdf(x), atol=1e-12)


def test_piecewise_2d_matches_marginal_and_conditional_histograms():
    image = np.array([[1, 2, 0, 0.5, 1], [0, 0, 0, 0, 0], [3, 9, 1, 0, 2], [0.25, 1, 4, 1, 0.5]])
    u = uniform(3000, 2, seed=6)
    p = stratum.warp("piecewise-2d", u, values=image)  # width and height from the array's shape
    edges_y, edges_x = np.linspace(0, 1, 5), np.linspace(0, 1, 6)
    marginal = stats.rv_histogram((image.sum(axis=1), edges_y), density=False)
    np.testing.assert_allclose(p[:, 1], marginal.ppf(u[:, 1]), atol=1e-12)
    rows = np.minimum((p[:, 1] * 4).astype(int), 3)
    assert not np.any(rows == 1)
    for row in (0, 2, 3):
        conditional = stats.rv_histogram((image[row], edges_x), density=False)
        chosen = rows == row
        np.testing.assert_allclose(p[chosen, 0], conditional.ppf(u[chosen, 0]), atol=1e-12)
    density = stratum.warp_pdf("piecewise-2d", p, values=image)
    columns = np.minimum((p[:, 0] * 5).astype(int), 4)
    np.testing.assert_allclose(density, image[rows, columns] / image.mean(), rtol=1e-12)
    np.testing.assert_allclose(stratum.warp_invert("piecewise-2d", p, values=image), u, atol=1e-12)


def test_alias_index_frequencies_chi_square():
    weights = np.array([1, 0, 3, 2, 0.5, 7, 0.01, 4, 4, 0, 12, 0.25])
    x = stratum.warp("alias", uniform(100000, 1, seed=7)[:, 0], values=weights)
    index = np.floor(x * len(weights)).astype(int)
    counts = np.bincount(index, minlength=len(weights))
    assert counts[1] == 0 and counts[9] == 0
    positive = weights > 0
    expected = len(x) * weights[positive] / weights.sum()
    # scipy's χ² test of the frequencies against the normalized weights, level 1e-3.
    assert stats.chisquare(counts[positive], expected).pvalue > 1e-3
    np.testing.assert_allclose(stratum.warp_pdf("alias", x, values=weights),
                               weights[index] / weights.sum() * len(weights), rtol=1e-15)
    u = uniform(1000, 1, seed=8)[:, 0]
    back = stratum.warp_invert("alias", stratum.warp("alias", u, values=weights), values=weights)
    np.testing.assert_allclose(back, u, atol=1e-13)


@pytest.mark.parametrize("name,params,text", [
    ("spherical-triangle", dict(vertices=[0, 0, 1, 1, 1, 1, 2, 2, 1]), "invalid vertices = (0, 0, 1), (1, 1, 1), (2, 2, 1)"),
    ("spherical-triangle", dict(vertices=[1, 0, 0, 0, 1, 0, 1, 1, 0]), "positive solid angle"),
    ("spherical-rectangle", dict(edge_u=[0, 0, 0]), "invalid edge_u = (0, 0, 0): must be non-zero"),
    ("spherical-rectangle", dict(edge_u=[1, 0, 0], edge_v=[2, 0, 0]), "must not be parallel to edge_u"),
    ("spherical-rectangle-projected", dict(origin=[3, 3, 1]), "invalid origin = (3, 3, 1): must not lie on the rectangle's plane"),
    ("spherical-triangle-projected", dict(normal=[0, 0, 0]), "invalid normal = (0, 0, 0)"),
    ("piecewise-1d", dict(values=[1, -1], width=2), "invalid values[1] = -1: must be a finite real in [0, inf)"),
    ("piecewise-1d", dict(values=[0, 0], width=2), "all 2 values zero"),
    ("piecewise-1d", dict(values=[1, np.inf], width=2), "invalid values[1] = inf: must be a finite real"),
    ("piecewise-2d", dict(values=[1, 2, 3], width=2, height=2), "must hold width × height = 2 × 2 = 4 values"),
    ("piecewise-2d", dict(values=[1, 2], width=2, height=0.5), "invalid height = 0.5: must be an integer in [1, 2^40]"),
    ("alias", dict(values=[0, 0, 0]), "all 3 values zero"),
])
def test_bad_input_names_parameter_and_value(name, params, text):
    u = uniform(4, 1 if name in ("piecewise-1d", "alias") else 2)
    with pytest.raises(ValueError) as error:
        stratum.warp(name, u[:, 0] if u.shape[1] == 1 else u, **params)
    assert text in str(error.value)
