"""Splitting work by index across worker processes is exact (docs/distributed.md):
blocks start = k·n of a sequence, drawn by separate processes, equal one call."""
from concurrent.futures import ProcessPoolExecutor

import numpy as np
import stratum


def _block(args):
    name, randomize, k, n = args
    return stratum.points(name, n, d=3, seed=11, randomize=randomize, start=k * n)


def test_blocks_from_worker_processes_equal_one_call():
    n, blocks = 256, 6
    for name, randomize in [("sobol", "owen"), ("halton", "owen"), ("sobol", "xor")]:
        whole = stratum.points(name, n * blocks, d=3, seed=11, randomize=randomize)
        with ProcessPoolExecutor(max_workers=2) as pool:
            parts = list(pool.map(_block, [(name, randomize, k, n) for k in range(blocks)]))
        np.testing.assert_array_equal(np.concatenate(parts), whole, err_msg=f"{name}:{randomize}")


def test_a_shifted_block_is_not_the_first():
    # The check above could pass if start were ignored: it is not.
    first = stratum.points("sobol", 64, d=3, seed=11, randomize="owen", start=0)
    second = stratum.points("sobol", 64, d=3, seed=11, randomize="owen", start=64)
    assert not np.array_equal(first, second)
