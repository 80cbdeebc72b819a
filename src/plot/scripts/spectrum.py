"""Figure for `stratum spectrum -o FILE.png`: the mean periodogram as an image
(2D; a line for 1D) beside the radially averaged power with the white-noise
level 1 and the effective Nyquist frequency marked.
Usage: python3 spectrum.py DATA.json OUT.png"""
import json
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

with open(sys.argv[1]) as handle:
    data = json.load(handle)

k = data["max_frequency"]
scale = data["frequency_scale"]  # sqrt(N): frequencies are shown in its units
extent = k / scale
power = np.array(data["power"], dtype=float)
figure, (left, right) = plt.subplots(1, 2, figsize=(11, 4.8))
if data["d"] == 2:
    image = power.reshape(2 * k + 1, 2 * k + 1)
    image[k, k] = np.nan  # the DC term P(0) = N would dominate the grey scale
    shown = left.imshow(image, origin="lower", cmap="gray", vmin=0, vmax=2,
                        extent=(-extent, extent, -extent, extent), interpolation="nearest")
    figure.colorbar(shown, ax=left, label="P(k) (white noise = 1; clipped at 2)")
    left.set_xlabel("k_x / sqrt(N)")
    left.set_ylabel("k_y / sqrt(N)")
else:
    frequencies = np.arange(-k, k + 1) / scale
    left.plot(frequencies, power, lw=0.8)
    left.set_xlabel("k / sqrt(N)")
    left.set_ylabel("P(k)")
left.set_title(f'{data["source"]}: N = {data["n"]}, {data["realizations"]} realization(s)')

radial = data["radial"]
values = [math.nan if v is None else v for v in radial["power"]]
right.plot(radial["frequency"], values, lw=1.2, label="radial power")
right.axhline(1.0, color="gray", lw=0.8, ls="--", label="white noise")
nyquist = data["effective_nyquist"]
if nyquist and nyquist > 0:
    right.axvline(nyquist, color="tab:red", lw=0.8, ls=":", label=f"effective Nyquist {nyquist:.3f}")
oscillation = data["oscillation"]
title = "radially averaged power" + (f", oscillation {oscillation:.3g}" if oscillation is not None else "")
right.set_title(title)
right.set_xlabel("frequency / sqrt(N)")
right.set_ylabel("P")
finite = [v for v in values if not math.isnan(v)]
right.set_ylim(0, max(2.0, min(4.0, max(finite) * 1.05)) if finite else 2.0)
right.legend(loc="lower right")
figure.tight_layout()
figure.savefig(sys.argv[2], dpi=110)
