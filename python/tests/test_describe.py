"""stratum.describe: the parameter schema in Python is the CLI's (the same
JSON), every entry is there, a name in two registries needs `kind`, and a
bounded parameter's range is enforced by the call that uses it."""
import json
import os
import subprocess

import pytest

import stratum

import build_parts

# The CLI of the same build: <build>/python/stratum/ beside <build>/bin/stratum.
STRATUM_EXE = os.path.join(os.path.dirname(stratum.__file__), os.pardir, os.pardir, "bin", "stratum")


def cli_describe_all():
    if not os.access(STRATUM_EXE, os.X_OK):
        # In a build tree with the CLI on (STRATUM_BUILD_APPS) a missing executable is a failure, not a skip.
        assert not build_parts.cache_option("STRATUM_BUILD_APPS"), f"{STRATUM_EXE} is missing: build the stratum target"
        pytest.skip("no stratum executable beside the package (an installed package, or a build without the CLI)")
    out = subprocess.run([STRATUM_EXE, "describe", "--all", "--json"], check=True, capture_output=True, text=True)
    return json.loads(out.stdout)


def test_every_entry_matches_the_cli():
    entries = cli_describe_all()
    assert len(entries) >= 60
    for entry in entries:
        assert stratum.describe(entry["name"], kind=entry["kind"]) == entry, entry["name"]


def test_a_name_in_two_registries_gives_both_unless_kind_picks():
    both = stratum.describe("triangle")
    assert isinstance(both, list) and {e["kind"] for e in both} == {"warp", "integrand"}
    assert stratum.describe("triangle", kind="warp")["kind"] == "warp"


def test_schema_fields():
    pd = stratum.describe("poisson-disk")
    assert pd["kind"] == "sampler"
    by_name = {p["name"]: p for p in pd["params"]}
    assert by_name["periodic"]["type"] == "flag"
    star = stratum.describe("star", kind="measure")
    method = {p["name"]: p for p in star["params"]}["method"]
    assert method["type"] == "choice" and "exact" in method["choices"] and method["default"] == "auto"


@pytest.mark.parametrize("name, kind, match", [
    ("nope", None, "no sampler, measure, warp or integrand is called that"),
    ("jittered", "measure", "invalid name = jittered"),
    ("jittered", "nope", "invalid kind = nope"),
])
def test_bad_names(name, kind, match):
    with pytest.raises(stratum.InvalidArgument, match=match):
        stratum.describe(name, kind=kind)


def test_ranges_are_enforced_by_points():
    checked = 0
    for entry in cli_describe_all():
        if entry["kind"] != "sampler":
            continue
        for param in entry["params"]:
            r = param.get("range")
            if param["type"] != "integer" or not r or r["min"] is None or r["min"] < 1:
                continue
            below = int(r["min"]) - 1
            for d in (2, 3):
                try:
                    stratum.points(entry["name"], 16, d)
                    break
                except stratum.InvalidArgument:
                    continue
            with pytest.raises(stratum.InvalidArgument, match=f"invalid {param['name']} = "):
                stratum.points(entry["name"], 16, d, **{param["name"]: below})
            checked += 1
    assert checked >= 5
