"""Messages of the Python face (docs/cli.md): a wrong type or value raises
stratum.InvalidArgument naming the argument and the value, never pybind11's
generic TypeError; complex numbers and strings are not read as reals; no
result is inf or nan."""
import re

import numpy as np
import pytest

import stratum
from stratum import InvalidArgument


@pytest.mark.parametrize("kwargs, text", [
    ({"n": 2**70}, "invalid n = 1180591620717411303424: must be a positive integer below 2^64"),
    ({"n": "8"}, "invalid n = '8'"),
    ({"n": 4.0}, "invalid n = 4.0"),
    ({"n": 4 + 0j}, "invalid n = (4+0j)"),
    ({"n": 4, "randomize": 3}, "invalid randomize = 3: must be a string or None"),
])
def test_points_arguments(kwargs, text):
    with pytest.raises(InvalidArgument, match=re.escape(text)):
        stratum.points("halton", **{"d": 2, **kwargs})


def test_points_name_must_be_text():
    with pytest.raises(InvalidArgument, match="invalid name = None: must be a string"):
        stratum.points(None, n=4)


@pytest.mark.parametrize("radius", ["0.1", True, 0.1 + 0j])
def test_radius_must_be_real(radius):
    # '0.1' used to be read as 0.1 while n='8' was refused: both are refused now.
    with pytest.raises(InvalidArgument, match="invalid radius = .*: must be a real number"):
        stratum.points("poisson-disk", n=None, radius=radius)


def test_radius_real_still_works():
    assert stratum.points("poisson-disk", n=None, radius=np.float64(0.2), seed=1).shape[1] == 2


@pytest.mark.parametrize("points, what", [
    (np.array([[0.1, 0.2], [0.3, 0.4]], dtype=complex), "complex numbers"),
    ([["0.1", "0.2"], ["0.3", "0.4"]], "strings"),
])
def test_measures_refuse_complex_and_strings(points, what):
    with pytest.raises(InvalidArgument, match=f"invalid x = array of {what}"):
        stratum.discrepancy(points, "l2-star")


def test_spectrum_and_warps_refuse_complex():
    with pytest.raises(InvalidArgument, match="invalid x = array of complex numbers"):
        stratum.spectrum(np.full((8, 2), 0.5 + 1j))
    with pytest.raises(InvalidArgument, match="invalid u = array of complex numbers"):
        stratum.warp("disk-polar", np.full((4, 2), 0.5 + 0j))
    with pytest.raises(InvalidArgument, match="invalid rate = array of strings"):
        stratum.warp("exponential", np.full((4, 1), 0.5), rate="2")


def test_warp_density_not_representable():
    # rate=1e-320 is in (0, inf) but puts the points at inf: refused, not returned.
    with pytest.raises(InvalidArgument, match=r"invalid warp-param = rate=1e-320: exponential maps u = \(0.125\) to \(inf\)"):
        stratum.warp("exponential", np.full((4, 1), 0.5), rate=1e-320)
    x = stratum.warp("exponential", np.full((4, 1), 0.5), rate=1e-300)
    assert np.all(np.isfinite(x))


def test_warp_invert_outside_domain():
    with pytest.raises(InvalidArgument, match=r"invalid p\[1\] = \(2, 0\): is outside the warp's domain: its pdf there is 0"):
        stratum.warp_invert("disk-polar", np.array([[0.1, 0.2], [2.0, 0.0]]))
    u = stratum.warp_invert("disk-polar", np.array([[0.1, 0.2], [0.0, -0.5]]))
    assert np.all((u >= 0) & (u <= 1))


def test_integrand_not_representable():
    with pytest.raises(InvalidArgument, match=r"invalid integrand-param = a=1e\+200: genz-gaussian is nan"):
        stratum.integrate("genz-gaussian", "random", n=16, a=1e200)


def test_variance_needs_two_samples():
    if not hasattr(stratum, "comparisons"):
        pytest.skip("built without the renderer")
    with pytest.raises(InvalidArgument, match="invalid with_variance = True: needs spp 2 or more"):
        stratum.render(width=4, height=4, spp=1, passes=1, with_variance=True)


def test_confidence_must_be_real():
    with pytest.raises(InvalidArgument, match="invalid confidence = '0.9': must be a level strictly between 0 and 1"):
        stratum.integrate("disk", "random", n=16, runs=4, confidence="0.9")


@pytest.mark.parametrize("call, text", [
    (lambda: stratum.integrate(None), "invalid integrand = None: must be a string"),
    (lambda: stratum.integrate("disk", None), "invalid sampler = None: must be a string"),
    (lambda: stratum.integrate("disk", randomize=3), "invalid randomize = 3: must be a string or None"),
    (lambda: stratum.converge("disk", None), "invalid samplers = None: give a list of names"),
    (lambda: stratum.spectrum(np.full((8, 2), 0.5), max_frequency=2**70), "invalid max_frequency = 1180591620717411303424"),
    (lambda: stratum.local_discrepancy(np.full((8, 2), 0.5), resolution=2**70), "invalid resolution = 1180591620717411303424"),
])
def test_no_pybind11_type_errors(call, text):
    with pytest.raises(InvalidArgument, match=re.escape(text)):
        call()
