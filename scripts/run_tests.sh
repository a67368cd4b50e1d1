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
echo "== Python tests (pytest) =="
"$python" -m pytest tests/python "$@"
