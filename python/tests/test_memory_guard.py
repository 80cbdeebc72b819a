"""The memory guard through Python: a request just above STRATUM_MEMORY_LIMIT
raises MemoryError naming the size needed and what is available (before
anything is allocated); one at the limit runs."""
import numpy as np
import pytest

import stratum

from build_parts import NO_RENDERER, RENDERER


def test_points_just_above_the_limit_raise_memory_error(monkeypatch):
    monkeypatch.setenv("STRATUM_MEMORY_LIMIT", "63999")  # 1000 x 8 doubles are 64000 bytes
    with pytest.raises(MemoryError, match=r"needs 62\.5 KiB for 1000 x 8 points of random, 62\.5 KiB available"):
        stratum.points("random", 1000, 8)
    monkeypatch.setenv("STRATUM_MEMORY_LIMIT", "64000")
    assert stratum.points("random", 1000, 8).shape == (1000, 8)


def test_the_l2_measure_counts_its_buffers(monkeypatch):
    x = stratum.points("sobol", 1000, 1)
    monkeypatch.setenv("STRATUM_MEMORY_LIMIT", "23999")  # the fast L2-star needs 24 bytes per point in d = 1
    with pytest.raises(MemoryError, match="needs 23.4 KiB for the l2-star measure of 1000 x 1 points"):
        stratum.measure(x, "l2-star")
    monkeypatch.setenv("STRATUM_MEMORY_LIMIT", "24000")
    assert stratum.measure(x, "l2-star")["value"] > 0


def test_the_other_measures_count_their_buffers(monkeypatch):
    x = stratum.points("random", 16, 2)
    monkeypatch.setenv("STRATUM_MEMORY_LIMIT", str(1 << 30))  # random-edge keeps 8 bytes per line
    with pytest.raises(MemoryError, match=r"needs 32\.0 GiB for the edge-random measure of 16 x 2 points"):
        stratum.measure(x, "edge-random", lines=1 << 32)
    assert stratum.measure(x, "edge-random", lines=1000)["value"] > 0
    monkeypatch.setenv("STRATUM_MEMORY_LIMIT", "127")  # min-distance's neighbour grid: 8 bytes per point
    with pytest.raises(MemoryError, match="needs 128 B for the min-distance measure of 16 x 2 points"):
        stratum.measure(x, "min-distance")
    monkeypatch.setenv("STRATUM_MEMORY_LIMIT", "128")
    assert stratum.measure(x, "min-distance")["value"] > 0


@pytest.mark.skipif(not RENDERER, reason=NO_RENDERER)
def test_a_render_counts_its_buffers(monkeypatch):
    monkeypatch.setenv("STRATUM_MEMORY_LIMIT", str(96 * 64 * 64 - 1))
    with pytest.raises(MemoryError, match="needs 384.0 KiB for a 64x64 render"):
        stratum.render(width=64, height=64, spp=1)
    monkeypatch.setenv("STRATUM_MEMORY_LIMIT", str(96 * 64 * 64))
    assert stratum.render(width=64, height=64, spp=1).shape == (64, 64, 3)
