"""Clean-build baseline: wall time of a from-scratch build and the largest source files (issue 9).

Configures and builds the whole project (the pybind11 module, every library and the C++ unit tests,
Release, the same targets as ``scripts/bootstrap.sh``) in a fresh directory with ccache disabled,
then prints and writes to ``build/benchmarks/build_baseline.json``:

* configure and build wall time, the number of translation units and the parallel jobs used;
* the slowest translation units (from Ninja's log), since compile time is a design constraint;
* the largest tracked source files by size and by lines.

Usage: ``python benchmarks/build_baseline.py [--jobs N] [--keep]``. It takes as long as a clean CI
build (several minutes on 2 cores) and uses every core it is given: run it on an idle machine.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pybind11

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "build" / "benchmarks"
SOURCE_SUFFIXES = (".cpp", ".h", ".py")


def _tracked_sources() -> list[Path]:
    listed = subprocess.run(
        ["git", "ls-files"], cwd=ROOT, capture_output=True, text=True, check=True
    ).stdout.split()
    return [ROOT / name for name in listed if name.endswith(SOURCE_SUFFIXES)]


def _largest_sources(count: int) -> dict[str, list[dict]]:
    rows = []
    for path in _tracked_sources():
        data = path.read_bytes()
        rows.append(
            {
                "file": str(path.relative_to(ROOT)),
                "bytes": len(data),
                "lines": data.count(b"\n"),
            }
        )
    return {
        "by_bytes": sorted(rows, key=lambda r: r["bytes"], reverse=True)[:count],
        "by_lines": sorted(rows, key=lambda r: r["lines"], reverse=True)[:count],
    }


def _compile_times(build_dir: Path) -> list[dict]:
    """Compile time of every object file, slowest first (.ninja_log: start, end, mtime, output)."""
    log = build_dir / ".ninja_log"
    units = []
    for line in log.read_text().splitlines()[1:]:
        fields = line.split("\t")
        if len(fields) >= 4 and fields[3].endswith(".o"):
            units.append({"object": fields[3], "seconds": (int(fields[1]) - int(fields[0])) / 1e3})
    units.sort(key=lambda u: u["seconds"], reverse=True)
    return units


def main(argv: list[str]) -> int:
    """Run the clean build, print the figures and write the JSON file."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--keep", action="store_true", help="keep the build directory")
    args = parser.parse_args(argv)
    build_dir = OUT / "clean_build"
    shutil.rmtree(build_dir, ignore_errors=True)
    build_dir.mkdir(parents=True)
    env = dict(os.environ, CCACHE_DISABLE="1")
    configure = [
        "cmake", "-S", str(ROOT), "-B", str(build_dir), "-G", "Ninja",
        "-DCMAKE_BUILD_TYPE=Release",
        "-DCONTACT_APP_BUILD_TESTS=ON", "-DCONTACT_APP_BUILD_PYTHON=ON",
        f"-DPython_EXECUTABLE={sys.executable}", f"-Dpybind11_DIR={pybind11.get_cmake_dir()}",
    ]  # fmt: skip
    start = time.perf_counter()
    subprocess.run(configure, env=env, check=True, stdout=subprocess.DEVNULL)
    configure_s = time.perf_counter() - start
    start = time.perf_counter()
    subprocess.run(
        ["cmake", "--build", str(build_dir), "-j", str(args.jobs)],
        env=env,
        check=True,
        stdout=subprocess.DEVNULL,
    )
    build_s = time.perf_counter() - start
    compile_times = _compile_times(build_dir)
    slowest = compile_times[:10]
    units = len(compile_times)
    sources = _largest_sources(5)
    figures = {
        "jobs": args.jobs,
        "configure_s": configure_s,
        "build_s": build_s,
        "translation_units": units,
        "slowest_units": slowest,
        "largest_sources": sources,
    }
    if not args.keep:
        shutil.rmtree(build_dir, ignore_errors=True)
    print(f"clean build, {args.jobs} jobs, ccache off: configure {configure_s:.1f} s, "
          f"build {build_s:.1f} s ({units} translation units)")  # fmt: skip
    print("slowest translation units:")
    for unit in slowest:
        print(f"  {unit['seconds']:7.1f} s  {unit['object']}")
    print("largest source files:")
    for row in sources["by_bytes"]:
        print(f"  {row['bytes']:8d} bytes {row['lines']:6d} lines  {row['file']}")
    OUT.mkdir(parents=True, exist_ok=True)
    path = OUT / "build_baseline.json"
    path.write_text(json.dumps(figures, indent=1) + "\n")
    print(f"written: {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
