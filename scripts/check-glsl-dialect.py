#!/usr/bin/env python3
"""Compiles every file of shaders/lib that C++ compiles too, standalone, in both languages of the
CPU/GPU dialect (docs/architecture.md, "The CPU/GPU dialect"):

- as GLSL 4.50 by Khronos' reference compiler (glslangValidator), in a fragment shader holding
  contract.glsl, the file's stub (tests/dialect/NAME: what its includer defines), the shared files
  it needs and the file itself;
- as C++17 with GLM (the C++ compiler, -fsyntax-only -Werror), the same parts inside
  gfield/glsl_begin.hpp and gfield/glsl_end.hpp at namespace scope, where callees must come
  before callers as in GLSL; -Wdouble-promotion and -Wfloat-conversion fail a float file's
  literal without its f suffix (a double in C++, a float on the GPU); after glsl_end.hpp no
  macro of the dialect, of contract.glsl or of the file may be defined.

Usage: check-glsl-dialect.py [--cxx COMPILER] [--glslang VALIDATOR]. Prints one line per file and
language; exits 1 when one fails (its compiler's message printed), 2 when a tool is missing.
CTest runs it (Dialect.SharedGlslFilesCompileStandaloneAsGlslAndCpp).
"""
import argparse
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
LIB = ROOT / "shaders" / "lib"
STUBS = ROOT / "tests" / "dialect"
# Each shared file and the shared files its includer puts before it (after contract.glsl).
SHARED = {
    "contract.glsl": [],
    "optics.glsl": [],
    "environment.glsl": [],
    "shapes.glsl": [],
    "field_lines.glsl": [],
    "field_lookup.glsl": ["field_lines.glsl"],
    "glass_displacement.glsl": [],
    "bvh_trace.glsl": [],
}
DIALECT_MACROS = ["GF_CONST", "GF_INLINE", "GF_IN", "GF_OUT", "GF_INOUT"]
INCLUDE = re.compile(r'^\s*#include\s+"(lib/[^"]+)"\s*$')
DEFINE = re.compile(r"^\s*#define\s+([A-Za-z_][A-Za-z0-9_]*)")


def expand(path, seen):
    """The GLSL text of `path` with its #include "lib/..." lines pasted once, as the runtime does."""
    if path in seen:
        return ""
    seen.add(path)
    out = []
    for line in path.read_text(encoding="utf-8").splitlines():
        found = INCLUDE.match(line)
        out.append(expand(ROOT / "shaders" / found.group(1), seen) if found else line)
    return "\n".join(out) + "\n"


def parts(name):
    stub = STUBS / name
    return ([stub] if stub.exists() else []) + [LIB / d for d in SHARED[name]] + [LIB / name]


def glsl_unit(name):
    seen = set()
    text = "#version 450\n" + expand(LIB / "contract.glsl", seen)
    for path in parts(name):
        text += expand(path, seen)
    return text + "void main() {}\n"


def macros(paths):
    names = set(DIALECT_MACROS)
    for path in paths:
        for line in path.read_text(encoding="utf-8").splitlines():
            found = DEFINE.match(line)
            if found:
                names.add(found.group(1))
    return sorted(names)


def cxx_unit(name):
    lines = ['#include "gfield/glsl_names.hpp"', '#include "gfield/gpu_contract.hpp"', "",
             "namespace gfield_dialect_check {",
             "using namespace gfield::glsl;", "using namespace gfield::gpu;"]
    if name != "contract.glsl":
        lines.append('#include "gfield/glsl_begin.hpp"')
        lines += [f'#include "{p}"' for p in parts(name)]
        lines.append('#include "gfield/glsl_end.hpp"')
    lines.append("}  // namespace gfield_dialect_check")
    for macro in macros([LIB / "contract.glsl"] + parts(name)):
        lines += [f"#ifdef {macro}", f'#error "{macro} is visible after {name} was included"',
                  "#endif"]
    return "\n".join(lines) + "\nint main() { return 0; }\n"


def run(command, what):
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        print(f"FAIL {what}\n{done.stdout}{done.stderr}")
        return False
    print(f"ok   {what}")
    return True


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cxx", default="c++")
    parser.add_argument("--glslang", default="glslangValidator")
    args = parser.parse_args()
    for tool in (args.cxx, args.glslang):
        if shutil.which(tool) is None:
            print(f"check-glsl-dialect: {tool} is missing (scripts/install-deps.sh)")
            return 2
    ok = True
    with tempfile.TemporaryDirectory() as folder:
        work = pathlib.Path(folder)
        for name in SHARED:
            stem = name.removesuffix(".glsl")
            frag = work / f"{stem}.frag"
            frag.write_text(glsl_unit(name), encoding="utf-8")
            ok &= run([args.glslang, str(frag)], f"{name} as GLSL 4.50")
            cpp = work / f"{stem}.cpp"
            cpp.write_text(cxx_unit(name), encoding="utf-8")
            ok &= run([args.cxx, "-std=c++17", "-fsyntax-only", "-Wall", "-Wextra", "-Werror",
                       "-Wno-unused-parameter", "-Wno-unused-function", "-Wdouble-promotion",
                       "-Wfloat-conversion", "-DGLM_ENABLE_EXPERIMENTAL",
                       f"-I{ROOT / 'core' / 'include'}", f"-I{LIB}", str(cpp)],
                      f"{name} as C++17 with GLM, no macro visible after it")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
