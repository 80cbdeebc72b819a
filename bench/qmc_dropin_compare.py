#!/usr/bin/python3
"""The scipy drop-in itself: stratum.qmc against scipy.stats.qmc with the
same calls (engine construction included), one thread, in one run.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/qmc_dropin_compare.py [--rounds R]

Each round times every call for scipy and for stratum.qmc alternately (the
best of a few repeats each, by process CPU time, which a loaded machine
inflates less than wall time); the speed-up of a call is the median over
rounds of scipy's CPU time over stratum's. Prints a Markdown table for
BENCHMARKS.md §1.4.
"""
import argparse
import statistics
import time
import warnings

import numpy as np
from scipy.stats import qmc as scipy_qmc

from stratum import qmc as stratum_qmc

# (label, call on a qmc module, repeats, target speed-up)
CASES = [
    ("Sobol(8, scramble=True).random(2**20)", lambda q: q.Sobol(8, scramble=True, seed=1).random(2**20), 5, 2),
    ("Sobol(8, scramble=False).random(2**20)", lambda q: q.Sobol(8, scramble=False, seed=1).random(2**20), 5, None),
    ("Halton(8, scramble=True).random(2**16)", lambda q: q.Halton(8, scramble=True, seed=1).random(2**16), 3, 30),
    ("LatinHypercube(8).random(2**16)", lambda q: q.LatinHypercube(8, seed=1).random(2**16), 5, 2),
    ("LatinHypercube(8, scramble=False).random(2**16)",
     lambda q: q.LatinHypercube(8, scramble=False, seed=1).random(2**16), 5, None),
    ("PoissonDisk(2, radius=0.01).fill_space()", lambda q: q.PoissonDisk(2, radius=0.01, seed=1).fill_space(), 1, 500),
]


def best(call, module, repeats):
    """(best CPU seconds, best wall seconds, result) over `repeats` calls."""
    cpu = wall = float("inf")
    result = None
    for _ in range(repeats):
        start_cpu, start_wall = time.process_time(), time.perf_counter()
        result = call(module)
        cpu = min(cpu, time.process_time() - start_cpu)
        wall = min(wall, time.perf_counter() - start_wall)
    return cpu, wall, result


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--rounds", type=int, default=5)
    args = parser.parse_args()
    warnings.simplefilter("ignore")
    rows = {label: [] for label, *_ in CASES}
    for _ in range(args.rounds):
        for label, call, repeats, _target in CASES:
            scipy_cpu, scipy_wall, theirs = best(call, scipy_qmc, 1 if "PoissonDisk" in label else repeats)
            ours_cpu, ours_wall, ours = best(call, stratum_qmc, max(repeats, 5))
            assert ours.shape[1] == theirs.shape[1] and np.all((ours >= 0) & (ours < 1)), label
            rows[label].append((scipy_cpu, ours_cpu, scipy_wall, ours_wall, len(ours), len(theirs)))
    print(f"{args.rounds} rounds; CPU ms are medians over rounds; speed-up = median of scipy CPU / stratum CPU\n")
    print("| call | scipy CPU ms | stratum.qmc CPU ms | speed-up (CPU) | speed-up (wall) | target | points |")
    print("|---|---:|---:|---:|---:|---:|---|")
    for label, _call, _repeats, target in CASES:
        runs = rows[label]
        cpu_ratio = statistics.median(s / o for s, o, *_ in runs)
        wall_ratio = statistics.median(s / o for _, _, s, o, *_ in runs)
        scipy_ms = statistics.median(r[0] for r in runs) * 1e3
        ours_ms = statistics.median(r[1] for r in runs) * 1e3
        goal = "" if target is None else f"≥ {target}x " + ("met" if cpu_ratio >= target else "**not met**")
        points = f"{runs[0][4]} / {runs[0][5]}"
        print(f"| `{label}` | {scipy_ms:.2f} | {ours_ms:.3f} | {cpu_ratio:.1f}x | {wall_ratio:.1f}x | {goal} | {points} |")


if __name__ == "__main__":
    main()
