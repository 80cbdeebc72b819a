#!/usr/bin/python3
"""stratum through Python against scipy.stats.qmc and a numpy memory-write
baseline, in the same run, one core unless --threads says otherwise.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/scipy_compare.py [--quick]

Prints a Markdown table (ns per coordinate, and ratios) for BENCHMARKS.md.
With --poisson-rounds R, only the Poisson-disk comparison (radius 0.01, 2D,
the issue's target), R times over, each round timing scipy once and stratum
best-of-20, then the median ratio: the one to quote on a loaded machine.
"""
import argparse
import time

import numpy as np
from scipy.stats import qmc

import stratum


def best_time(fn, repeat):
    best = float("inf")
    result = None
    for _ in range(repeat):
        start = time.perf_counter()
        result = fn()
        best = min(best, time.perf_counter() - start)
    return best, result


def poisson_once(radius, repeat):
    """(stratum seconds, scipy seconds, stratum points, scipy points) for
    the maximal set at `radius` in 2D, against scipy's fill_space."""
    ours, pts = best_time(lambda: stratum.points("poisson-disk", None, 2, seed=1, radius=radius), repeat)
    peer, ref = best_time(lambda: qmc.PoissonDisk(2, radius=radius, seed=1).fill_space(), 1)
    return ours, peer, len(pts), len(ref)


def best_wall_and_cpu(fn, repeat):
    """Best wall time and best CPU time of this thread (the one that counts
    when other processes share the cores), over `repeat` calls."""
    wall = cpu = float("inf")
    result = None
    for _ in range(repeat):
        start, start_cpu = time.perf_counter(), time.thread_time()
        result = fn()
        cpu = min(cpu, time.thread_time() - start_cpu)
        wall = min(wall, time.perf_counter() - start)
    return wall, cpu, result


def poisson_rounds(rounds, radius=0.01):
    wall_ratios, cpu_ratios = [], []
    print(f"poisson-disk radius {radius}, d = 2: stratum best of 20 calls, scipy PoissonDisk.fill_space once, per round\n")
    print("| round | stratum wall ms | scipy wall ms | wall speed-up | stratum CPU ms | scipy CPU ms | CPU speed-up "
          "| points (stratum / scipy) |")
    print("|---:|---:|---:|---:|---:|---:|---:|---|")
    for k in range(rounds):
        ours, ours_cpu, pts = best_wall_and_cpu(
            lambda: stratum.points("poisson-disk", None, 2, seed=1, radius=radius), 20)
        peer, peer_cpu, ref = best_wall_and_cpu(lambda: qmc.PoissonDisk(2, radius=radius, seed=1).fill_space(), 1)
        wall_ratios.append(peer / ours)
        cpu_ratios.append(peer_cpu / ours_cpu)
        print(f"| {k + 1} | {ours * 1e3:.3f} | {peer * 1e3:.1f} | {peer / ours:.1f}x | {ours_cpu * 1e3:.3f} "
              f"| {peer_cpu * 1e3:.1f} | {peer_cpu / ours_cpu:.1f}x | {len(pts)} / {len(ref)} |", flush=True)
    print(f"\nmedian speed-up over {rounds} rounds: wall {float(np.median(wall_ratios)):.1f}x, "
          f"CPU {float(np.median(cpu_ratios)):.1f}x")


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--quick", action="store_true", help="smaller sizes, fewer repeats")
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--poisson-rounds", type=int, default=0, help="only the Poisson-disk comparison, R rounds")
    args = parser.parse_args()
    if args.poisson_rounds > 0:
        poisson_rounds(args.poisson_rounds)
        return
    repeat = 3 if args.quick else 5
    n, d = (1 << 16, 8) if args.quick else (1 << 20, 8)
    t = args.threads
    rows = []

    def row(label, ours, peer, peer_label, coords, note=""):
        rows.append((label, ours * 1e9 / coords, peer_label, peer * 1e9 / coords, peer / ours, note))

    base, _ = best_time(lambda: np.full((n, d), 0.5), repeat)
    rows.append(("memory-write baseline: np.full((n, d))", base * 1e9 / (n * d), "", float("nan"), float("nan"), ""))

    ours, _ = best_time(lambda: stratum.points("sobol", n, d, seed=1, randomize="owen-hash", threads=t), repeat)
    peer, _ = best_time(lambda: qmc.Sobol(d, scramble=True, seed=1).random(n), repeat)
    row("sobol owen-hash", ours, peer, "scipy Sobol(scramble=True)", n * d, f"{ours / base:.2f}x baseline")
    ours, _ = best_time(lambda: stratum.points("sobol", n, d, seed=1, randomize="lms", threads=t), repeat)
    row("sobol lms (scipy's scramble)", ours, peer, "scipy Sobol(scramble=True)", n * d, f"{ours / base:.2f}x baseline")

    nh = n // 4
    ours, _ = best_time(lambda: stratum.points("halton", nh, d, seed=1, randomize="permute", threads=t), repeat)
    peer, _ = best_time(lambda: qmc.Halton(d, scramble=True, seed=1).random(nh), max(1, repeat // 2))
    row("halton permute", ours, peer, "scipy Halton(scramble=True)", nh * d)

    ours, _ = best_time(lambda: stratum.points("n-rooks", n, d, seed=1, threads=t), repeat)
    peer, _ = best_time(lambda: qmc.LatinHypercube(d, seed=1).random(n), repeat)
    row("n-rooks", ours, peer, "scipy LatinHypercube", n * d)

    radius = 0.02 if args.quick else 0.01
    ours, peer, n_ours, n_peer = poisson_once(radius, repeat)
    row(f"poisson-disk r={radius} maximal", ours, peer, "scipy PoissonDisk.fill_space", 2 * n_ours,
        f"{n_ours} points vs scipy {n_peer}")

    print(f"n = {n}, d = {d}, threads = {t}\n")
    print("| stratum | ns/coord | peer | ns/coord | speed-up | note |")
    print("|---|---:|---|---:|---:|---|")
    for label, ns, peer_label, peer_ns, ratio, note in rows:
        peer_text = "" if np.isnan(peer_ns) else f"{peer_ns:.2f}"
        ratio_text = "" if np.isnan(ratio) else f"{ratio:.1f}x"
        print(f"| {label} | {ns:.2f} | {peer_label} | {peer_text} | {ratio_text} | {note} |")


if __name__ == "__main__":
    main()
