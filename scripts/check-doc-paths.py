#!/usr/bin/env python3
"""The docs' links and paths (CI runs it with the docs test): every relative Markdown link of
README.md and docs/*.md names a file or folder of the repository, and every path in backticks that
starts with one of the source folders (core/, geometry/, preprocess/, runtime/, shaders/, scripts/,
tests/, bench/, docs/, data/, examples/, python/, cmake/) names one: as written, or with .cpp,
.hpp, .glsl, .py or .sh added (docs name a unit as `preprocess/field_build`; core/X also under
core/src/ and core/include/gfield/). Paths with placeholders (upper-case words such as NAME or
MESH, *, {…}, <…>, $) are not checked. Prints each broken one as FILE:LINE and
exits 1 when there is any."""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FOLDERS = ("core/", "geometry/", "preprocess/", "runtime/", "shaders/", "scripts/", "tests/",
           "bench/", "docs/", "data/", "examples/", "python/", "cmake/")
SUFFIXES = ("", ".cpp", ".hpp", ".glsl", ".py", ".sh", ".h")
# Placeholders: globs, braces, variables, and upper-case words (NAME, MESH, EXT, TARGET, …).
PLACEHOLDER = re.compile(r"[*{}<>$]|\.\.\.|…|(^|[/_.-])[A-Z][A-Z0-9]+([/_.-]|$)")


def exists(path):
    """`path` as written or with a suffix; core/X also as core/src/X and core/include/gfield/X."""
    candidates = [path]
    if path.startswith("core/"):
        unit = path[len("core/"):]
        candidates += ["core/src/" + unit, "core/include/gfield/" + unit]
    return any(
        os.path.exists(os.path.join(ROOT, c + suffix)) for c in candidates for suffix in SUFFIXES)


def problems(doc):
    found = []
    folder = os.path.dirname(doc)
    with open(os.path.join(ROOT, doc), encoding="utf-8") as text:
        fence = False
        for number, line in enumerate(text, 1):
            if line.lstrip().startswith("```"):
                fence = not fence
                continue
            if fence:
                continue
            for target in re.findall(r"\]\(([^)\s]+)\)", line):
                target = target.split("#")[0]
                if not target or re.match(r"[a-z]+:", target):
                    continue
                if not os.path.exists(os.path.join(ROOT, folder, target)):
                    found.append(f"{doc}:{number}: link to {target}: no such file")
            for quoted in re.findall(r"`([^`\s]+)`", line):
                path = quoted.rstrip(".,;:)").split("#")[0]
                if not path.startswith(FOLDERS) or PLACEHOLDER.search(path):
                    continue
                path = re.sub(r"(\.[a-z]+)?:\d+$", r"\1", path)  # FILE:LINE
                if "(" in path or "=" in path:
                    continue
                if not exists(path):
                    found.append(f"{doc}:{number}: `{quoted}`: no such file")
    return found


def main():
    docs = ["README.md"] + sorted(
        os.path.join("docs", f) for f in os.listdir(os.path.join(ROOT, "docs")) if f.endswith(".md"))
    found = [p for doc in docs for p in problems(doc)]
    for p in found:
        print(p)
    print(f"check-doc-paths: {len(docs)} documents, {len(found)} broken links or paths")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
