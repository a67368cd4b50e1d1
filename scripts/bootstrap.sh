#!/usr/bin/env bash
# Installs what a fresh Debian machine lacks, then builds contact_app in place (editable install).
# Idempotent and quiet when everything is already there. Usage: bash scripts/bootstrap.sh
set -euo pipefail
cd "$(dirname "$0")/.."

# libpetsc-real-dev (+ pkg-config to find it, openmpi-bin for mpirun): the iterative solver (docs/architecture.md).
# doxygen: the header doc check of scripts/run_tests.sh (docs/Doxyfile).
apt_packages=(build-essential libeigen3-dev libsuitesparse-dev libmumps-seq-dev libopenblas0-pthread libgtest-dev ccache
  ninja-build pkg-config libpetsc-real-dev openmpi-bin doxygen)
missing=()
for package in "${apt_packages[@]}"; do
  dpkg -s "$package" >/dev/null 2>&1 || missing+=("$package")
done
if ((${#missing[@]})); then
  echo "bootstrap: installing system packages: ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq "${missing[@]}" >/dev/null
fi

python=${PYTHON:-python3}
# pybind11-stubgen is pinned: tests/python/test_core_stubs.py compares its output with the committed stubs.
if ! "$python" -c "import scikit_build_core, pybind11, numpy, meshio, matplotlib, pytest, cmake, pybind11_stubgen, mypy" \
  >/dev/null 2>&1; then
  echo "bootstrap: installing Python build and test packages"
  "$python" -m pip install -q "scikit-build-core>=0.9" "pybind11>=2.12" "numpy>=1.24" "meshio>=5.3" \
    "matplotlib>=3.5" "pytest>=7.4" "ruff>=0.5" "cmake>=3.20" ninja "pybind11-stubgen==3.0.0" \
    "mypy>=1.10"
fi

# Incremental C++ build (ccache + a persistent build/python directory): fast when nothing changed.
start=$(date +%s)
log=build/bootstrap.log
mkdir -p build
if ! CMAKE_BUILD_PARALLEL_LEVEL=${CMAKE_BUILD_PARALLEL_LEVEL:-$(nproc)} \
  "$python" -m pip install --no-build-isolation -e ".[test]" \
  -Ccmake.define.CONTACT_APP_BUILD_TESTS=ON >"$log" 2>&1; then
  grep -E "error|Error" "$log" | head -40
  echo "bootstrap: the build failed; the full log is $log"
  exit 1
fi
"$python" -c "import contact_app" || { echo "bootstrap: contact_app does not import (build log: $log)"; exit 1; }
echo "bootstrap: build and install took $(( $(date +%s) - start )) s"
