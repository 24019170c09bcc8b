#!/usr/bin/env python3
"""Tests mirror the sources (CI runs it beside the docs' path check): every library source
(core/src, geometry, preprocess, preprocess/cli, runtime, runtime/methods, python/src) has a
same-named test, tests/*/NAME_test.cpp, or matches a row of docs/architecture.md's test map (between
its test-map markers), whose test files exist; every row matches some source. Prints what breaks
the rule and exits 1 when anything does."""
import fnmatch
import glob
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOURCES = ["core/src/*.cpp", "geometry/*.cpp", "preprocess/*.cpp", "preprocess/cli/*.cpp",
           "runtime/*.cpp", "runtime/methods/*.cpp", "python/src/*.cpp"]


def test_map():
    text = open(os.path.join(ROOT, "docs/architecture.md"), encoding="utf-8").read()
    table = text.split("<!-- test-map begin -->")[1].split("<!-- test-map end -->")[0]
    rows = []
    for line in table.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) < 2 or not cells[0].startswith("`"):
            continue
        rows.append((re.findall(r"`([^`]+)`", cells[0]), re.findall(r"`([^`]+)`", cells[1])))
    return rows


def main():
    sources = sorted(os.path.relpath(p, ROOT) for pattern in SOURCES
                     for p in glob.glob(os.path.join(ROOT, pattern)))
    tests = {os.path.basename(p)[:-len("_test.cpp")]
             for p in glob.glob(os.path.join(ROOT, "tests/*/*_test.cpp"))}
    rows = test_map()
    problems = []
    for patterns, files in rows:
        for f in files:
            if not os.path.exists(os.path.join(ROOT, f)):
                problems.append(f"test map: {f} does not exist")
        if not any(fnmatch.fnmatch(s, p) for s in sources for p in patterns):
            problems.append(f"test map: {', '.join(patterns)} matches no source")
    for source in sources:
        name = os.path.basename(source)[:-len(".cpp")]
        if name in tests or any(fnmatch.fnmatch(source, p) for ps, _ in rows for p in ps):
            continue
        problems.append(f"{source}: no tests/*/{name}_test.cpp and no row of the test map "
                        "(docs/architecture.md)")
    for p in problems:
        print(p)
    mirrored = sum(os.path.basename(s)[:-4] in tests for s in sources)
    print(f"check-test-map: {len(sources)} sources, {mirrored} with a same-named test, "
          f"{len(rows)} rows for the rest, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
