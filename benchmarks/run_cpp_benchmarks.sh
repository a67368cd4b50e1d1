#!/usr/bin/env bash
# Builds and runs the C++ micro-benchmarks (AD scalar choice, mortar pairs per second, contact local systems per
# second) against the static libraries of a CMake build tree (default build/mortar, configured with -DCONTACT_APP_BUILD_TESTS=ON).
# Usage: benchmarks/run_cpp_benchmarks.sh [build_dir]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build/mortar}"
cmake --build "$build" --target contact_app_application >/dev/null
flags=(-std=c++17 -O2 -DNDEBUG -I"$root" -I/usr/include/eigen3 -I/usr/include)
out="$build/benchmarks"
mkdir -p "$out"
c++ "${flags[@]}" "$root/benchmarks/ad_benchmark.cpp" -o "$out/ad_benchmark"
c++ "${flags[@]}" "$root/benchmarks/mortar_benchmark.cpp" -o "$out/mortar_benchmark" \
    "$build/libcontact_app_contact_utilities.a" "$build/libcontact_app_kernel.a" -lgtest -pthread
# application registers everything (kernel, structural, contact conditions, constraints): link every area once.
c++ "${flags[@]}" "$root/benchmarks/condition_benchmark.cpp" -o "$out/condition_benchmark" -Wl,--start-group \
    "$build"/libcontact_app_*.a -Wl,--end-group -lgtest -pthread
"$out/ad_benchmark"
echo
"$out/mortar_benchmark"
echo
"$out/condition_benchmark"
