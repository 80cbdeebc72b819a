"""Which optional parts this build of the package has, for the tests that need one.

The answer comes from the CMake cache of the build the package sits in
(<build>/python/stratum/ lies under <build>/CMakeCache.txt), not from the
package's own names: a test keyed on a function's name would skip silently if
that function were renamed or lost; keyed on the build option, it fails. With
STRATUM_BUILD_RENDER=ON the renderer is built or the configure step fails
(find_package(embree REQUIRED)), so the option is the fact. An installed
package has no cache beside it; only then is the extension module asked.
"""
import os

import stratum

CACHE = os.path.normpath(os.path.join(os.path.dirname(stratum.__file__), os.pardir, os.pardir, "CMakeCache.txt"))


def cache_option(name):
    """True/False for a BOOL entry of the build's CMake cache, None without a cache or entry."""
    try:
        with open(CACHE, encoding="utf-8") as cache:
            for line in cache:
                key, _, value = line.partition("=")
                if key.split(":", 1)[0] == name:
                    return value.strip().upper() in ("ON", "1", "TRUE", "YES", "Y")
    except OSError:
        return None
    return None


_render_option = cache_option("STRATUM_BUILD_RENDER")
RENDERER = _render_option if _render_option is not None else hasattr(stratum._stratum, "render")
NO_RENDERER = ("built without the renderer (STRATUM_BUILD_RENDER=OFF in " + CACHE + ")" if _render_option is not None
               else "an installed package without the renderer (its extension has no render)")
# The Python faces of the renderer and the report (python/stratum/render.py, report.py).
RENDERER_NAMES = ("render", "compare", "comparisons", "report", "report_sections", "lecture_slides")
