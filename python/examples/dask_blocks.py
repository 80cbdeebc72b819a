"""A Monte Carlo integral split into blocks over Dask workers, identical to
one process (docs/distributed.md, "From Python").

Each task draws the points start = k·n … (k+1)·n − 1 of one Owen-scrambled
Sobol' sequence (the index API: a block is the same whichever process draws
it) and sums f over them; the block sums come back in task order and are
added in that order, so the estimate is the same bit for bit for any number
of workers or any scheduler. On a cluster, pass the scheduler's address to
dask.distributed.Client and call client.map(block_sum, range(blocks)).

Usage: /usr/bin/python3 dask_blocks.py [BLOCKS] [N] [WORKERS]"""
import sys

import dask
import numpy as np

import stratum


def block_sum(k, n, d=4, seed=7):
    """Σ exp(−Σ x_j) over the k-th block of n points."""
    x = stratum.points("sobol", n, d=d, seed=seed, randomize="owen", start=k * n)
    return float(np.exp(-x.sum(axis=1)).sum())


def estimate(blocks, n, scheduler="processes", workers=2):
    """The mean of f over blocks·n points, the blocks computed as Dask tasks."""
    tasks = [dask.delayed(block_sum)(k, n) for k in range(blocks)]
    sums = dask.compute(*tasks, scheduler=scheduler, num_workers=workers)  # in task order
    total = 0.0
    for s in sums:  # a fixed order: the same sum for any scheduler or worker count
        total += s
    return total / (blocks * n)


if __name__ == "__main__":
    blocks = int(sys.argv[1]) if len(sys.argv) > 1 else 16
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 1 << 14
    workers = int(sys.argv[3]) if len(sys.argv) > 3 else 2
    value = estimate(blocks, n, "processes", workers)
    exact = (1 - np.exp(-1.0)) ** 4
    print(f"{blocks} blocks of {n} points on {workers} Dask worker processes: {value:.12f} "
          f"(exact {exact:.12f}, error {abs(value - exact):.2e})")
