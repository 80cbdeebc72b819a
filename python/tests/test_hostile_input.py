"""Hostile input through stratum.render and stratum.compare: JSON nested
100 000 deep is refused with its line and column (it used to overflow the
stack and kill Python), a FIFO is refused instead of read forever, and a
triangle index that does not fit 32 bits is an error, not wrapped."""
import os
import subprocess
import sys
import textwrap

import pytest

import stratum

from build_parts import NO_RENDERER, RENDERER

pytestmark = pytest.mark.skipif(not RENDERER, reason=NO_RENDERER)


def run_python(code, tmp_path, timeout=120):
    """Runs `code` in a child interpreter: a crash there is a failed test, not a dead test run."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in sys.path if p)
    return subprocess.run([sys.executable, "-c", textwrap.dedent(code)], cwd=tmp_path, env=env, capture_output=True,
                          text=True, timeout=timeout)


def test_deeply_nested_scene_is_refused_without_a_crash(tmp_path):
    (tmp_path / "deep.json").write_text("[" * 100000 + "]" * 100000)
    result = run_python("""
        import stratum
        try:
            stratum.render(scene="deep.json", spp=1)
        except stratum.InvalidArgument as e:
            print("refused:", e)
        """, tmp_path)
    assert result.returncode == 0, result.stderr[-2000:]
    assert "refused: invalid scene = deep.json: nests arrays and objects deeper than 256 levels at line 1, column 257" \
        in result.stdout
    assert len(result.stdout) < 400


def test_a_fifo_scene_is_refused_at_once(tmp_path):
    os.mkfifo(tmp_path / "scene.json")
    try:  # in a child: a read of the FIFO would never end
        result = run_python("""
            import stratum
            try:
                stratum.render(scene="scene.json", spp=1)
            except stratum.InvalidArgument as e:
                print("refused:", e)
            """, tmp_path, timeout=60)
    except subprocess.TimeoutExpired:
        pytest.fail("stratum.render read the FIFO instead of refusing it")
    assert "refused: invalid scene = scene.json: must be a regular file (this is a FIFO)" in result.stdout, result.stderr


def test_a_triangle_index_beyond_32_bits_is_an_error(tmp_path):
    scene = tmp_path / "overflow.json"
    scene.write_text('{"materials": {"m": {"reflectance": [0.5, 0.5, 0.5]}}, "shapes": [{"type": "triangles", '
                     '"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "indices": [[0, 1, 4294967298]], "material": "m"}]}')
    with pytest.raises(stratum.InvalidArgument, match=r"indices\[0\]\[2\] = 4294967298"):
        stratum.render(scene=str(scene), spp=1)


def test_deeply_nested_configs_are_refused():
    deep = []
    for _ in range(100000):
        deep = [deep]
    with pytest.raises(stratum.InvalidArgument, match="invalid configs = .*deeper than 256 levels"):
        stratum.compare(configs=deep)
    shallow = {"spp": 1}  # deep enough for the C++ cap, not for Python's recursion limit
    for _ in range(300):
        shallow = [shallow]
    with pytest.raises(stratum.InvalidArgument, match=r"nests arrays and objects deeper than 256 levels at line 1, column 257"):
        stratum.compare(configs=shallow)
