"""stratum.report: the lecture page from Python (same sections as `stratum report`)."""
import json
import pathlib

import pytest

import stratum

import build_parts
from build_parts import NO_RENDERER, RENDERER

pytestmark = pytest.mark.skipif(not RENDERER, reason=NO_RENDERER)


def test_sections_listed_in_lecture_order():
    sections = stratum.report_sections()
    assert sections, "no section"
    numbers = [int(s["lecture"].lstrip("§")) for s in sections]
    assert numbers == sorted(numbers)
    assert len({s["id"] for s in sections}) == len(sections)


def test_lecture_slides_name_report_sections_and_the_cli_lists_the_same(tmp_path):
    import subprocess
    slides = stratum.lecture_slides()
    lectures = {s["id"]: s["lecture"] for s in stratum.report_sections()}
    assert len(slides) >= 26
    for slide in slides:
        assert lectures[slide["section"]] == slide["lecture"], slide
        assert slide["anchor"] == "" or slide["anchor"].startswith(("figure-" + slide["section"] + "-", "table-"))
    # Every section shows at least one formula of the lecture.
    assert {s["section"] for s in slides if s["formula"]} == set(lectures)
    # The CLI of the same build: <build>/python/stratum/ beside <build>/bin/stratum.
    cli = pathlib.Path(stratum.__file__).parents[2] / "bin" / "stratum"
    assert cli.is_file() or not build_parts.cache_option("STRATUM_BUILD_APPS"), f"{cli} is missing"
    if cli.is_file():
        lines = subprocess.run([str(cli), "report", "--slides"], check=True, capture_output=True,
                               text=True).stdout.splitlines()
        assert len(lines) == len(slides)
        for line, slide in zip(lines, slides):
            assert line.split()[:2] == [slide["lecture"], slide["section"]] and slide["title"] in line, line


def test_one_section_writes_page_figures_and_numbers(tmp_path):
    result = stratum.report(tmp_path / "r", quick=True, only=["disk-maps"], cache=str(tmp_path / "cache"))
    index = tmp_path / "r" / "index.html"
    assert result["index"] == str(index) and index.is_file()
    page = index.read_text()
    assert 'id="disk-maps"' in page and page.count("<section") == 1
    figures = list((tmp_path / "r" / "figures").glob("disk-maps-*.png"))
    assert figures and all(f.read_bytes()[:4] == b"\x89PNG" for f in figures)
    numbers = result["numbers"]["disk-maps"]
    # The polar map's strata are less compact than the concentric map's (a
    # deterministic property of the maps), and P²/4πA ≥ 1 for any region
    # (the isoperimetric inequality).
    assert numbers["polar"]["compactness_mean"] > numbers["concentric"]["compactness_mean"] >= 1
    saved = json.loads((tmp_path / "r" / "report.json").read_text())
    assert saved["sections"]["disk-maps"]["numbers"] == numbers


@pytest.mark.parametrize("kwargs, word", [
    ({"samplers": ["no-such-sampler"]}, "sampler"),
    ({"only": ["no-such-section"]}, "only"),
    ({"threads": 5000}, "threads"),
])
def test_bad_options_raise_before_any_work(tmp_path, kwargs, word):
    with pytest.raises(stratum.InvalidArgument, match=word):
        stratum.report(tmp_path / "bad", quick=True, **kwargs)
    assert not (tmp_path / "bad").exists()
