#!/usr/bin/env bash
# The whole test suite: bootstrap (install + build), C++ unit tests (ctest), Python tests (pytest).
# Extra arguments go to pytest, e.g. bash scripts/run_tests.sh -m "not slow".
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/bootstrap.sh
python=${PYTHON:-python3}
echo "== C++ unit tests (ctest) =="
ctest --test-dir build/python --output-on-failure -j "$(nproc)"
echo "== Python lint (ruff) =="
"$python" -m ruff check contact_app python_scripts tests/python examples benchmarks
"$python" -m ruff format --check contact_app python_scripts tests/python examples benchmarks
echo "== Python types (mypy) =="
"$python" -m mypy  # files and options: pyproject.toml [tool.mypy]
echo "== C++ header docs (Doxygen) =="
# docs/Doxyfile, with the output in the build folder; any warning (a doc that does not match its declaration) fails.
doc_dir=build/doxygen
mkdir -p "$doc_dir"
if ! { cat docs/Doxyfile; echo "OUTPUT_DIRECTORY = $doc_dir"; } | doxygen - >/dev/null 2>"$doc_dir/warnings.log"; then
  sed "s|^$PWD/||" "$doc_dir/warnings.log"
  echo "doxygen: $(grep -c ': \(warning\|error\):' "$doc_dir/warnings.log") warning(s) in the C++ header docs," \
    "at the file:line above (full list: $doc_dir/warnings.log); fix the comments: every parameter of a documented" \
    "function gets its @param, names as in the declaration (docs/architecture.md, 'Header docs')"
  exit 1
fi
echo "== Python tests (pytest) =="
"$python" -m pytest tests/python "$@"
