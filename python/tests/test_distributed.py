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


def _dask_example():
    """python/examples/dask_blocks.py, imported by path."""
    import importlib.util
    import pathlib
    path = pathlib.Path(__file__).resolve().parents[1] / "examples" / "dask_blocks.py"
    spec = importlib.util.spec_from_file_location("dask_blocks", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_dask_blocks_equal_one_process_bit_for_bit():
    # Debian's python3-dask (installed by scripts/install-deps.sh --test).
    dask = __import__("pytest").importorskip("dask")
    example = _dask_example()
    blocks, n = 6, 512
    # One process, no Dask: the same blocks summed in the same order.
    serial = 0.0
    for k in range(blocks):
        serial += example.block_sum(k, n)
    serial /= blocks * n
    for scheduler, workers in [("processes", 2), ("processes", 3), ("threads", 2), ("synchronous", 1)]:
        assert example.estimate(blocks, n, scheduler, workers) == serial, (scheduler, workers)
    # The blocks are the sequence's points: drawn by Dask worker processes, they equal one call.
    parts = dask.compute(*[dask.delayed(stratum.points)("sobol", n, d=4, seed=7, randomize="owen", start=k * n)
                           for k in range(blocks)], scheduler="processes", num_workers=2)
    whole = stratum.points("sobol", n * blocks, d=4, seed=7, randomize="owen")
    np.testing.assert_array_equal(np.concatenate(parts), whole)
    # And the estimate is the integral's: (1 − e^−1)^4, Owen-scrambled Sobol' at 3072 points.
    assert abs(serial - (1 - np.exp(-1.0)) ** 4) < 1e-4
