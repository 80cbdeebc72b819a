"""Blue-noise error in screen space (docs/render.md): for each pixel sampler at
1, 4 and 16 spp on scenes/penumbra.json (128 x 128, direct lighting), the
low-frequency power of the error (white = 1), the MSE, the MSE after a
1-pixel Gaussian blur and the render time (1 thread), averaged over seeds;
the peer is per-pixel Owen-scrambled Sobol' (`sobol`) in the same run.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/blue_noise_compare.py [SEEDS=4]
"""
import os
import sys
import tempfile
import time

import numpy as np
import stratum

SCENE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scenes", "penumbra.json")
LUMINANCE = np.array([0.2126, 0.7152, 0.0722])


def blur(e, sigma=1.0):
    r = np.arange(-3, 4)
    k = np.exp(-r ** 2 / (2 * sigma * sigma))
    k /= k.sum()
    e = sum(k[i] * np.roll(e, r[i], 0) for i in range(7))
    return sum(k[i] * np.roll(e, r[i], 1) for i in range(7))


def main():
    seeds = int(sys.argv[1]) if len(sys.argv) > 1 else 4
    with tempfile.TemporaryDirectory() as cache:
        ref = stratum.render(SCENE, reference=True, reference_spp=4096, cache=cache, threads=2) @ LUMINANCE
    print("| spp | sampler | low-frequency power | MSE | MSE, 1-px Gaussian blur | seconds (1 thread) | time / sobol's |")
    print("|---:|---|---:|---:|---:|---:|---:|")
    for spp in (1, 4, 16):
        base_seconds = None
        for name in ("sobol", "random", "zsobol", "sobol-bn", "pmj02-bn", "lattice-bn"):
            low, mse, blurred, seconds = [], [], [], []
            for seed in range(seeds):
                start = time.perf_counter()
                image = stratum.render(SCENE, spp=spp, sampler=name, seed=seed, threads=1, passes=1)
                seconds.append(time.perf_counter() - start)
                error = image @ LUMINANCE - ref
                low.append(stratum.image_spectrum(error)["low_frequency_power"])
                mse.append(np.mean(error ** 2))
                blurred.append(np.mean(blur(error) ** 2))
            t = float(np.median(seconds))
            base_seconds = base_seconds or t
            print(f"| {spp} | {name} | {np.mean(low):.3f} | {np.mean(mse):.4g} | {np.mean(blurred):.4g} | "
                  f"{t:.3f} | {t / base_seconds:.2f} |")


if __name__ == "__main__":
    main()
