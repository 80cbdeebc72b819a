#!/usr/bin/python3
"""Checks PTX for the signs of device code that reads host-only data.

nvcc compiles a kernel that indexes a host `constexpr` array with a run-time
index without a warning, into one of three things, each caught here:
  - `trap;` (the whole kernel becomes a trap),
  - a load through an address that is an integer literal (the table's
    offset from a null base: `mov.u64 %rd1, 4; ld.u32 %r1, [%rd1];`),
  - a branch to itself (`$L__BB1_1: bra.uni $L__BB1_1;`: the loop the
    optimizer leaves when it proves the read undefined).
Usage: check_ptx.py FILE.ptx [ENTRY_SUBSTRING ...]; with substrings, only
entries whose mangled name contains one of them are checked (the sampler
paths), and each substring must match at least one entry.
Exit status 0 when clean, 1 with one line per finding.
"""
import re
import sys

ENTRY = re.compile(r"^\s*(?:\.visible\s+|\.weak\s+|\.extern\s+)?\.(?:entry|func)\s+(?:\([^)]*\)\s*)?([A-Za-z_$][\w$]*)")
MOV_IMMEDIATE = re.compile(r"^\s*mov\.[bus]64\s+(%\w+),\s*(-?\d+)\s*;")
DEFINITION = re.compile(r"^\s*(?:@!?%\w+\s+)?[a-z][\w.]*\s+(%\w+)\s*,")
MEMORY = re.compile(r"^\s*(?:@!?%\w+\s+)?(?:ld|st|atom|red|prefetch)\.[\w.]*\s+.*?\[\s*(%\w+|-?\d+)\s*(?:[+-]\s*\d+)?\s*\]")
LABEL = re.compile(r"^\s*(\$[\w$]+):\s*$")
BRANCH = re.compile(r"^\s*(?:@!?%\w+\s+)?bra(?:\.uni)?\s+(\$[\w$]+)\s*;")


def functions(lines):
    """(name, body lines) of every .entry / .func in the file."""
    name, body, depth, opened = None, [], 0, False
    for line in lines:
        match = ENTRY.match(line)
        if match and name is None:
            name, body, depth, opened = match.group(1), [], 0, False
        if name is None:
            continue
        body.append(line)
        opened = opened or "{" in line
        if not opened and line.rstrip().endswith(";"):  # a declaration, no body
            name = None
            continue
        depth += line.count("{") - line.count("}")
        if opened and depth == 0:
            yield name, body
            name = None


def findings(name, body):
    immediate = {}  # register -> literal it holds (last definition wins)
    previous_label = None
    for number, line in enumerate(body):
        code = line.split("//")[0]
        if re.match(r"^\s*trap\s*;", code):
            yield f"{name}: trap instruction: {code.strip()}"
        memory = MEMORY.match(code)
        if memory:
            address = memory.group(1)
            if not address.startswith("%") or address in immediate:
                value = address if not address.startswith("%") else immediate[address]
                yield f"{name}: memory access at literal address {value}: {code.strip()}"
        move = MOV_IMMEDIATE.match(code)
        if move:
            immediate[move.group(1)] = move.group(2)
        else:
            definition = DEFINITION.match(code)
            if definition:
                immediate.pop(definition.group(1), None)
        branch = BRANCH.match(code)
        if branch and previous_label == branch.group(1):
            yield f"{name}: branch to itself (endless loop) at {previous_label}"
        label = LABEL.match(code)
        if label:
            previous_label = label.group(1)
        elif code.strip():
            previous_label = None


def main(argv):
    if len(argv) < 2:
        print("usage: check_ptx.py FILE.ptx [ENTRY_SUBSTRING ...]", file=sys.stderr)
        return 2
    with open(argv[1], encoding="utf-8") as stream:
        lines = stream.read().splitlines()
    wanted = argv[2:]
    seen = {w: 0 for w in wanted}
    problems, checked = [], 0
    for name, body in functions(lines):
        matching = [w for w in wanted if w in name]
        if wanted and not matching:
            continue
        for w in matching:
            seen[w] += 1
        checked += 1
        problems.extend(findings(name, body))
    for w, count in seen.items():
        if count == 0:
            problems.append(f"no function in {argv[1]} matches '{w}'")
    if checked == 0:
        problems.append(f"no function found in {argv[1]}")
    for p in problems:
        print(p)
    print(f"check_ptx: {checked} functions checked, {len(problems)} findings")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
