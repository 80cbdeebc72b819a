"""The renderer's Python faces exist exactly when the build has the renderer
(build_parts.py reads the build option), so the tests that skip without the
renderer cannot skip because a name changed."""
import stratum

from build_parts import RENDERER, RENDERER_NAMES


def test_renderer_faces_match_the_build():
    # callable: without the renderer, stratum.render and stratum.report are the (empty) submodules.
    present = [name for name in RENDERER_NAMES if callable(getattr(stratum, name, None))]
    assert present == (list(RENDERER_NAMES) if RENDERER else []), (RENDERER, present)
    assert all(name in stratum.__all__ for name in present)
