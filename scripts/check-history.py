#!/usr/bin/env python3
"""Finds history in the code: a date, an issue number or a "before:"/"was" figure in the sources,
shaders, tests, benchmarks and build files. Comments say what and why; what changed when is git
log's job and the measured figures' home is docs/results.md. Prints each offending line as
FILE:LINE: TEXT and exits 1 when there is one. Run from anywhere; CI runs it (.ci/run)."""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
FOLDERS = [".ci", "core", "geometry", "preprocess", "runtime", "shaders", "python", "bench", "tests",
           "scripts", "cmake", "examples", "web"]
SUFFIXES = {".cpp", ".hpp", ".h", ".c", ".glsl", ".vert", ".frag", ".comp", ".geom", ".py",
            ".sh", "", ".cmake", ".txt", ".js", ".mjs", ".html", ".sbatch", ".in"}
# Folders of inputs, not of code: fuzz corpora and regression inputs are data.
SKIP = {"tests/fuzz/corpus", "tests/fuzz/regressions", "web/node_modules"}
PATTERNS = [
    ("a date", re.compile(r"\b(19|20)\d\d-[01]\d-[0-3]\d\b")),
    ("an issue number", re.compile(r"\b[Ii]ssues? #?\d+")),
    ("a before figure", re.compile(r"\bbefore:\s*[-+0-9.]|\(before[ :,]")),
    ("a was figure", re.compile(r"[(,;]\s*was [-+0-9.]")),
    ("a measured date", re.compile(r"\b[Mm]easured (on )?(19|20)\d\d")),
]


def files():
    for folder in FOLDERS:
        base = ROOT / folder
        if not base.is_dir():
            continue
        for path in sorted(base.rglob("*")):
            rel = path.relative_to(ROOT).as_posix()
            if any(rel == s or rel.startswith(s + "/") for s in SKIP):
                continue
            if path.is_file() and (path.suffix in SUFFIXES or path.name == "CMakeLists.txt"):
                yield rel, path
    yield "CMakeLists.txt", ROOT / "CMakeLists.txt"


def main():
    self_name = pathlib.Path(__file__).resolve().relative_to(ROOT).as_posix()
    found = 0
    for rel, path in files():
        if rel == self_name:
            continue
        try:
            text = path.read_text(encoding="utf-8")
        except UnicodeDecodeError:
            continue
        for number, line in enumerate(text.splitlines(), 1):
            for what, pattern in PATTERNS:
                if pattern.search(line):
                    print(f"{rel}:{number}: {what}: {line.strip()}")
                    found += 1
                    break
    if found:
        print(f"check-history: {found} lines carry history (git log keeps it; figures go to "
              "docs/results.md)")
        return 1
    print("check-history: no dates, issue numbers or old figures in the code")
    return 0


if __name__ == "__main__":
    sys.exit(main())
