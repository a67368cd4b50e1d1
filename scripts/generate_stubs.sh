#!/usr/bin/env bash
# Regenerates the type stubs of the compiled module, contact_app/_core/*.pyi, from the installed build
# (pybind11-stubgen). Run it after changing a binding and rebuilding; tests/python/test_stubs.py fails
# while the committed stubs differ from what it writes.
# Usage: bash scripts/generate_stubs.sh [OUTPUT_ROOT]
#   default: the repository, replacing contact_app/_core/; with OUTPUT_ROOT, writes OUTPUT_ROOT/contact_app/_core/.
set -euo pipefail
cd "$(dirname "$0")/.."
python=${PYTHON:-python3}
out=${1:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# --exit-code: a name the stubs cannot resolve (a C++ type in a signature, a default value that is not a
# Python expression) is an error to fix in the binding, not a silent "..." in the stubs.
"$python" -m pybind11_stubgen contact_app._core --exit-code -o "$work" >"$work/log" 2>&1 || {
  cat "$work/log"
  echo "generate_stubs: pybind11-stubgen failed"
  exit 1
}
if [ -n "$out" ]; then
  mkdir -p "$out/contact_app"
  rm -rf "$out/contact_app/_core"
  cp -r "$work/contact_app/_core" "$out/contact_app/_core"
else
  rm -rf contact_app/_core
  cp -r "$work/contact_app/_core" contact_app/_core
  echo "generate_stubs: wrote $(ls contact_app/_core | tr '\n' ' ')"
fi
