"""Figure for `stratum converge --plot`: variance against N on log-log axes,
one line per sampler, with the fitted slope in the legend.
Usage: python3 converge.py DATA.json OUT.png"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

with open(sys.argv[1]) as handle:
    data = json.load(handle)

figure, axes = plt.subplots(figsize=(6.4, 4.8))
for entry in data["samplers"]:
    quantity = "rmse" if entry["fitted"] == "mse" else "variance"
    n = [row["n"] for row in entry["rows"]]
    y = [row["rmse"] ** 2 if quantity == "rmse" else row["variance"] for row in entry["rows"]]
    label = f'{entry["name"]}:{entry["randomize"]}'
    if entry["slope"] is not None:
        interval = entry.get("slope_interval") or [None, None]
        if None not in interval:
            level = f'{100 * entry["slope_confidence"]:g}%'
            label += f' (slope {entry["slope"]:.2f}, {level} [{interval[0]:.2f}, {interval[1]:.2f}])'
        else:
            label += f' (slope {entry["slope"]:.2f})'
        if quantity == "rmse":
            label += " [MSE]"
    positive = [(a, b) for a, b in zip(n, y) if b > 0]
    if positive:
        axes.loglog(*zip(*positive), marker="o", label=label)
axes.set_xlabel("N (points per estimate)")
axes.set_ylabel("variance of the estimate")
axes.set_title(f'{data["integrand"]} (d = {data["d"]}), {data["runs"]} runs per N')
axes.grid(True, which="both", alpha=0.3)
axes.legend(fontsize="small")
figure.tight_layout()
figure.savefig(sys.argv[2], dpi=120)
