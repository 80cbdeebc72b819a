"""stratum.image_spectrum against numpy's FFT (an independent oracle), white
noise at 1, the error spectra that compare reports, and bad input."""
import numpy as np
import pytest
import stratum
from stratum import InvalidArgument

SCENE = __file__.rsplit("/python/", 1)[0] + "/scenes/penumbra.json"


def numpy_power(values):
    e = values - values.mean()
    p = np.abs(np.fft.fftshift(np.fft.fft2(e))) ** 2 / e.size
    return p / (p.sum() / (e.size - 1))


def test_power_equals_numpy_fft_for_even_and_odd_sizes():
    rng = np.random.default_rng(4)
    for shape in [(16, 16), (9, 14), (7, 5)]:
        x = rng.normal(size=shape)
        s = stratum.image_spectrum(x)
        np.testing.assert_allclose(s["power"], numpy_power(x), rtol=1e-9, atol=1e-12)


def test_white_noise_has_low_frequency_power_one():
    # ~800 frequencies below 1/8 cycle per pixel, ~400 independent: sd ~0.05; 5 sd allowed
    x = np.random.default_rng(5).normal(size=(128, 128))
    assert abs(stratum.image_spectrum(x)["low_frequency_power"] - 1) < 0.25


def test_rgb_uses_luminance_and_reference_is_subtracted():
    rng = np.random.default_rng(6)
    rgb = rng.random((12, 10, 3))
    ref = rng.random((12, 10, 3))
    lum = (rgb - ref) @ np.array([0.2126, 0.7152, 0.0722])
    np.testing.assert_allclose(stratum.image_spectrum(rgb, ref)["power"], numpy_power(lum), rtol=1e-9, atol=1e-12)


def test_refused_input():
    with pytest.raises(InvalidArgument, match="constant image"):
        stratum.image_spectrum(np.ones((8, 8)))
    with pytest.raises(InvalidArgument, match="must have the image's shape"):
        stratum.image_spectrum(np.zeros((8, 8)), np.zeros((8, 9)))
    with pytest.raises(InvalidArgument, match="width"):
        stratum.image_spectrum(np.random.default_rng(1).random((8, 3)))
    with pytest.raises(InvalidArgument, match="shape"):
        stratum.image_spectrum(np.zeros(16))


def test_compare_rows_carry_the_error_spectrum(tmp_path):
    rows = stratum.compare(SCENE, configs=[{"label": "sobol", "sampler": "sobol", "spp": 1},
                                           {"label": "zsobol", "sampler": "zsobol", "spp": 1},
                                           {"label": "sobol-bn", "sampler": "sobol-bn", "spp": 1}],
                           width=64, height=64, reference_spp=256, cache=tmp_path)
    assert len(rows[0]["error_spectrum"]["power"]) == 32
    # one seed: sobol scatters around 1.09 (sd 0.16), zsobol around 0.25 (sd 0.04), sobol-bn around 0.29 (sd 0.015)
    assert rows[0]["low_frequency_power"] > 0.6 and rows[1]["low_frequency_power"] < 0.45, rows
    assert rows[2]["low_frequency_power"] < 0.45, rows
