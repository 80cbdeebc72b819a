#!/usr/bin/env bash
# CLI tests of `stratum describe` (the parameter schema's face): the docs page
# docs/parameters.md is exactly `describe --all --markdown`; every entry's
# schema agrees with `samplers --json` and `integrate --list --json`; each
# bounded number parameter's range is enforced where the entry is used (a
# value just outside is refused naming the parameter, the bound itself is
# not refused for that reason); and the bad-input contract.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1"
py=/usr/bin/python3
docs="$(dirname "${BASH_SOURCE[0]}")/../../docs/parameters.md"

"$stratum" describe --all --markdown >"$tmp/parameters.md" && ok || fail "describe --all --markdown"
if cmp -s "$tmp/parameters.md" "$docs"; then ok; else
  fail "docs/parameters.md differs from 'stratum describe --all --markdown' (regenerate it): $(diff "$docs" "$tmp/parameters.md" | head -5)"
fi

"$stratum" describe --all --json >"$tmp/all.json" && ok || fail "describe --all --json"
"$stratum" samplers --json >"$tmp/samplers.json" && ok || fail "samplers --json"
"$stratum" integrate --list --json >"$tmp/integrands.json" && ok || fail "integrate --list --json"
$py - "$tmp/all.json" "$tmp/samplers.json" "$tmp/integrands.json" <<'PY' && ok || fail "describe agrees with samplers/integrate listings"
import json, sys
entries = json.load(open(sys.argv[1]))
kinds = {e["kind"] for e in entries}
assert kinds == {"sampler", "measure", "warp", "integrand"}, kinds
by_kind = {(e["kind"], e["name"]): e for e in entries}
assert len(by_kind) == len(entries), "an entry twice in one registry"
def listed(doc, key):
    items = doc if isinstance(doc, list) else doc[key]
    return {item["name"]: item for item in items}
samplers = listed(json.load(open(sys.argv[2])), "samplers")
integrands = listed(json.load(open(sys.argv[3])), "integrands")
assert set(samplers) == {n for k, n in by_kind if k == "sampler"}, "sampler names differ"
assert set(integrands) == {n for k, n in by_kind if k == "integrand"}, "integrand names differ"
for name, item in samplers.items():
    assert item["params"] == by_kind["sampler", name]["params"], name
for name, item in integrands.items():
    assert item["params"] == by_kind["integrand", name]["params"], name
PY

# One entry: text and JSON; a name in two registries prints both unless --kind picks.
"$stratum" describe poisson-disk >"$tmp/pd.txt" && grep -q "^sampler poisson-disk:" "$tmp/pd.txt" && grep -q "periodic: flag" "$tmp/pd.txt" && ok || fail "describe poisson-disk text"
"$stratum" describe triangle >"$tmp/tri.txt" && grep -q "^warp triangle" "$tmp/tri.txt" && grep -q "^integrand triangle" "$tmp/tri.txt" && ok || fail "describe triangle: both registries"
"$stratum" describe triangle --kind integrand >"$tmp/tri1.txt" && ! grep -q "^warp" "$tmp/tri1.txt" && ok || fail "describe --kind integrand"

# Ranges enforced where they are used: for every sampler's bounded integer or
# real parameter, points with the value just below the minimum is refused
# naming the parameter. The bound itself (or one step inside) must not be
# refused *for that parameter* (it may be refused for another reason, e.g.
# strata whose product is not n: the message then names something else).
$py - "$stratum" "$tmp/all.json" <<'PY' && ok || fail "sampler ranges enforced by points"
import json, subprocess, sys
stratum, entries = sys.argv[1], json.load(open(sys.argv[2]))
checked = 0
# A dimension each sampler takes by default (latin-square and the space-time
# patterns need 3).
shape = {}
for e in entries:
    if e["kind"] == "sampler":
        shape[e["name"]] = next((d for d in (2, 3) if subprocess.run(
            [stratum, "points", "-s", e["name"], "-n", "16", "-d", str(d)], capture_output=True).returncode == 0), 2)
for e in entries:
    if e["kind"] != "sampler":
        continue
    for p in e["params"]:
        r = p.get("range")
        if p["type"] not in ("integer", "real") or not r or r["min"] is None:
            continue
        low = r["min"]
        if p["type"] == "integer":
            bad, good = int(low) - (0 if r["min_open"] else 1), int(low) + (1 if r["min_open"] else 0)
        else:
            bad, good = (low if r["min_open"] else low - 0.5), (low + 0.5 if r["min_open"] else low)
        def run(value):
            return subprocess.run([stratum, "points", "-s", e["name"], "-n", "16", "-d", str(shape[e["name"]]), "-p",
                                   f"{p['name']}={value}"], capture_output=True, text=True)
        res = run(bad)
        assert res.returncode != 0, (e["name"], p["name"], bad, "accepted")
        assert f"invalid {p['name']} = " in res.stderr, (e["name"], p["name"], res.stderr)
        res = run(good)
        assert f"invalid {p['name']} = " not in res.stderr, (e["name"], p["name"], good, res.stderr)
        checked += 1
assert checked >= 10, f"only {checked} bounded sampler parameters"
print(f"{checked} bounded sampler parameters checked")
PY

expect_error "no sampler, measure, warp or integrand is called that" describe nope
expect_error "give a NAME" describe
expect_error "invalid kind = nope" describe jittered --kind nope
expect_error "give --all" describe jittered --markdown
expect_error "not both" describe --all jittered
expect_error "invalid name = jittered" describe jittered --kind measure
finish
