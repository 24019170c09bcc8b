#!/usr/bin/env bash
# The layout check (CI runs it): every C and C++ file git tracks is as .clang-format lays it out
# (clang-format --dry-run -Werror); a file that is not is named with the lines that differ.
# Fix with: git ls-files '*.cpp' '*.hpp' '*.c' '*.h' | xargs clang-format -i
set -euo pipefail
cd "$(dirname "$0")/.."
git ls-files -z '*.cpp' '*.hpp' '*.c' '*.h' | xargs -0 clang-format --dry-run -Werror
echo "check-format: $(git ls-files '*.cpp' '*.hpp' '*.c' '*.h' | wc -l) files laid out as .clang-format says"
