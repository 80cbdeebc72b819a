#!/usr/bin/python3
"""plot_points.py DIR OUT.png: one scatter plot (first two coordinates) per
point file in DIR, titled by sampler name; 3D sets are coloured by their
third coordinate (time, for the space-time patterns)."""
import math
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main(directory, output):
    files = sorted(pathlib.Path(directory).glob("*.txt"))
    cols = 6
    rows = math.ceil(len(files) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(2.4 * cols, 2.6 * rows))
    for ax in axes.flat:
        ax.axis("off")
    for ax, path in zip(axes.flat, files):
        points = np.atleast_2d(np.loadtxt(path))
        y = points[:, 1] if points.shape[1] > 1 else np.zeros(len(points))
        if points.shape[1] > 2:
            ax.scatter(points[:, 0], y, s=3, c=points[:, 2], cmap="viridis")
        else:
            ax.scatter(points[:, 0], y, s=3, c="k")
        ax.set_xlim(0, 1)
        ax.set_ylim(0, 1)
        ax.set_aspect("equal")
        ax.set_xticks([])
        ax.set_yticks([])
        ax.axis("on")
        ax.set_title(f"{path.stem} ({len(points)})", fontsize=9)
    fig.tight_layout()
    tmp = pathlib.Path(output).with_suffix(".tmp.png")
    fig.savefig(tmp, dpi=110)
    tmp.rename(output)
    print(f"wrote {output}")


if __name__ == "__main__":
    main(*sys.argv[1:3])
