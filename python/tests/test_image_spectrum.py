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


def numpy_temporal_power(frames):
    """P(k) pooled over pixels by numpy's FFT along time, white = 1, k and F - k folded."""
    e = frames - frames.mean(axis=0)
    p = (np.abs(np.fft.fft(e, axis=0)) ** 2).reshape(len(e), -1).sum(axis=1) / len(e)
    p = p / (p[1:].sum() / (len(e) - 1))
    f = len(e)
    return np.array([(p[k] + p[f - k]) / 2 for k in range(1, f // 2 + 1)])


def test_temporal_power_equals_numpy_fft_for_even_and_odd_frame_counts():
    rng = np.random.default_rng(7)
    for shape in [(16, 4, 5), (11, 3, 3), (9, 1, 1)]:
        x = rng.normal(size=shape)
        s = stratum.temporal_spectrum(x)
        np.testing.assert_allclose(s["power"], numpy_temporal_power(x), rtol=1e-9, atol=1e-12)
        np.testing.assert_allclose(s["frequency"], np.arange(1, shape[0] // 2 + 1) / shape[0])
        e = x - x.mean(axis=0)
        assert s["lag1_correlation"] == pytest.approx((e[1:] * e[:-1]).sum() / (e * e).sum(), rel=1e-12)
        assert s["variance"] == pytest.approx(x.var(axis=0).mean(), rel=1e-12)


def test_temporal_spectrum_takes_rgb_frames_as_luminance_and_lists():
    rng = np.random.default_rng(8)
    rgb = rng.random((10, 4, 6, 3))
    lum = rgb @ np.array([0.2126, 0.7152, 0.0722])
    np.testing.assert_allclose(stratum.temporal_spectrum(list(rgb))["power"], numpy_temporal_power(lum), rtol=1e-9)


def test_white_in_time_is_one_and_alternating_is_blue():
    # 32 frames x 4096 pixels: P(1..3) pooled over ~4096 exponentials each, sd ~0.01; 0.1 allowed
    x = np.random.default_rng(9).normal(size=(32, 64, 64))
    white = stratum.temporal_spectrum(x)
    assert abs(white["low_frequency_power"] - 1) < 0.1 and abs(white["lag1_correlation"] + 1 / 32) < 0.05
    # circular differences x(t) - x(t-1): power 2 - 2 cos(2 pi k / F), normalized by its mean 2 F / (F - 1)
    blue = stratum.temporal_spectrum(x - np.roll(x, 1, axis=0))
    assert blue["low_frequency_power"] < 0.15 and blue["lag1_correlation"] < -0.4


def test_frames_of_a_continued_sequence_are_blue_in_time():
    # each pixel's sequence continues over the frames (docs/render.md): its error alternates
    def spectrum(sampler):
        return stratum.temporal_spectrum(
            [stratum.render(SCENE, width=16, height=16, spp=1, sampler=sampler, seed=2, frame=k) for k in range(16)])
    white, blue = spectrum("random"), spectrum("sobol-bn")
    assert white["low_frequency_power"] > 0.7 and blue["low_frequency_power"] < 0.65, (white, blue)


def test_temporal_spectrum_refuses_bad_frames():
    with pytest.raises(InvalidArgument, match="9 to 65536 frames"):
        stratum.temporal_spectrum(np.zeros((8, 4, 4)))
    with pytest.raises(InvalidArgument, match="constant in time"):
        stratum.temporal_spectrum(np.ones((9, 4, 4)))
    with pytest.raises(InvalidArgument, match="shape"):
        stratum.temporal_spectrum(np.zeros((9, 16)))
    with pytest.raises(InvalidArgument, match="one shape"):
        stratum.temporal_spectrum([np.zeros((4, 4))] * 8 + [np.zeros((4, 5))])
    with pytest.raises(InvalidArgument, match="finite"):
        stratum.temporal_spectrum(np.full((9, 2, 2), np.nan))
    with pytest.raises(InvalidArgument, match="strings"):
        stratum.temporal_spectrum([["a"]] * 9)
