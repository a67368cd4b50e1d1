"""Coverage-guided fuzzing of the input layers (issue 16): the .mdpa reader, the parameters layer.

Two targets, each must turn any bytes into success or a user error; anything else is a finding:

* ``mdpa``: the libFuzzer binary ``build/fuzz/mdpa_reader_fuzzer`` (source
  tests/fuzz/mdpa_reader_fuzzer.cpp: the C++ reader built with clang, coverage instrumentation,
  AddressSanitizer and UBSan). Allowed end: an ``InputError`` naming the file. Findings: another
  exception, a crash, a sanitizer report, a leak, an input slower than ``--timeout`` seconds.
* ``parameters``: atheris over the Python layer (contact_app's own functions instrumented). The
  first byte picks what the rest is: a ``ProjectParameters.json`` or the case's materials file; the
  analysis is then constructed (``safe=True``), which validates both. Allowed ends: ``InputError``,
  ``ConfigurationError``. Findings: any other exception or a hang.

Seeds: the meshes and JSON files of ``../shared/kratos_cases`` (read at run time) and
``tests/fuzz/seeds``. Corpora and findings go to ``build/fuzz/<target>/``, so later runs resume.

Usage: ``python benchmarks/fuzz_inputs.py --minutes N [--target mdpa|parameters|all]``; with
``all`` the time is split evenly. Prints executions, coverage (libFuzzer's ``cov`` edges and ``ft``
features), corpus size and the findings, and exits 1 if there is a finding. One core; run long
sessions under ``nice -n 10``. Building the mdpa target and installing atheris: docs/running.md,
"Fuzzing".
"""

from __future__ import annotations

import argparse
import importlib.util
import inspect
import json
import logging
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
import types
import warnings
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
CASES = ROOT.parent / "shared" / "kratos_cases"
SEEDS = ROOT / "tests" / "fuzz" / "seeds"
MDPA_DICTIONARY = ROOT / "tests" / "fuzz" / "mdpa.dict"
WORK = ROOT / "build" / "fuzz"
MDPA_FUZZER = WORK / "mdpa_reader_fuzzer"
#: The case whose folder the parameters target works in (its mesh and materials are the references).
PARAMETERS_CASE = "ALM_frictionless_contact_test_2D"
PARAMETERS_STEM = "hyper_simple_patch_test"
KIND_PARAMETERS, KIND_MATERIALS = 0, 1
#: The Python packages whose functions the parameters target instruments.
PACKAGES = ("contact_app", "python_scripts")

_STATS = re.compile(r"^#(\d+)\s+\w+\s+cov: (\d+) ft: (\d+) corp: (\d+)")
_EXECUTED = re.compile(r"stat::number_of_executed_units: (\d+)")


@dataclass
class Report:
    """What one fuzzing session did."""

    target: str
    seconds: float = 0.0
    executions: int = 0
    coverage: int = 0  # libFuzzer "cov": instrumented edges reached
    features: int = 0  # libFuzzer "ft"
    corpus: int = 0
    findings: list[str] = field(default_factory=list)
    skipped: str = ""

    def line(self) -> str:
        """One summary line."""
        if self.skipped:
            return f"{self.target}: skipped ({self.skipped})"
        return (
            f"{self.target}: {self.executions} executions in {self.seconds:.0f} s, "
            f"coverage {self.coverage} edges ({self.features} features), corpus {self.corpus}, "
            f"findings {len(self.findings)}"
        )


def atheris_missing() -> str:
    """Why the parameters target cannot run, or "" when it can."""
    if importlib.util.find_spec("atheris") is None:
        return "atheris is not installed: python -m pip install atheris"
    return ""


def mdpa_fuzzer_missing() -> str:
    """Why the mdpa target cannot run, or "" when it can."""
    if not MDPA_FUZZER.is_file():
        return f"{MDPA_FUZZER.relative_to(ROOT)} is not built (docs/running.md, 'Fuzzing')"
    return ""


def _seed_files(suffixes: tuple[str, ...]) -> list[Path]:
    files = [p for p in sorted(CASES.rglob("*")) if p.is_file() and p.name.endswith(suffixes)]
    if SEEDS.is_dir():
        files += [p for p in sorted(SEEDS.iterdir()) if p.name.endswith(suffixes)]
    return files


def _libfuzzer_options(seconds: float, timeout: int, artifacts: Path) -> list[str]:
    return [
        f"-max_total_time={max(1, int(seconds))}",
        f"-timeout={timeout}",
        "-rss_limit_mb=2048",
        "-max_len=65536",
        "-print_final_stats=1",
        f"-artifact_prefix={artifacts}/",
    ]


def _run_libfuzzer(command: list[str], report: Report, artifacts: Path) -> None:
    """Runs one libFuzzer-style process and reads its statistics and findings."""
    before = set(artifacts.iterdir())
    start = time.monotonic()
    completed = subprocess.run(
        command, capture_output=True, text=True, errors="replace", check=False
    )
    report.seconds = time.monotonic() - start
    for line in completed.stderr.splitlines():
        if match := _STATS.match(line):
            report.executions = max(report.executions, int(match[1]))
            report.coverage, report.features, report.corpus = map(int, match.group(2, 3, 4))
        if match := _EXECUTED.search(line):
            report.executions = max(report.executions, int(match[1]))
    new = sorted(set(artifacts.iterdir()) - before)
    report.findings += [str(path) for path in new]
    if completed.returncode != 0 and not new:
        tail = "\n".join(completed.stderr.splitlines()[-30:])
        report.findings.append(f"exit code {completed.returncode} without an artifact:\n{tail}")
    if report.findings:
        (artifacts / "last_log.txt").write_text(completed.stderr)


def fuzz_mdpa(seconds: float, timeout: int) -> Report:
    """The libFuzzer run of the .mdpa reader."""
    report = Report("mdpa")
    if why := mdpa_fuzzer_missing():
        report.skipped = why
        return report
    corpus, seeds, artifacts = (WORK / "mdpa" / name for name in ("corpus", "seeds", "findings"))
    for folder in (corpus, artifacts):
        folder.mkdir(parents=True, exist_ok=True)
    shutil.rmtree(seeds, ignore_errors=True)
    seeds.mkdir(parents=True)
    for index, path in enumerate(_seed_files((".mdpa",))):
        shutil.copyfile(path, seeds / f"{index:03d}_{path.name}")
    options = [*_libfuzzer_options(seconds, timeout, artifacts), f"-dict={MDPA_DICTIONARY}"]
    _run_libfuzzer([str(MDPA_FUZZER), *options, str(corpus), str(seeds)], report, artifacts)
    return report


def fuzz_parameters(seconds: float, timeout: int) -> Report:
    """The atheris run of the parameters and materials layer (in a worker process)."""
    report = Report("parameters")
    if why := atheris_missing():
        report.skipped = why
        return report
    corpus, seeds, artifacts = (
        WORK / "parameters" / name for name in ("corpus", "seeds", "findings")
    )
    for folder in (corpus, artifacts):
        folder.mkdir(parents=True, exist_ok=True)
    shutil.rmtree(seeds, ignore_errors=True)
    seeds.mkdir(parents=True)
    for index, path in enumerate(_seed_files((".json",))):
        if path.name.endswith("_results.json"):
            continue
        kind = KIND_MATERIALS if "materials" in path.name else KIND_PARAMETERS
        (seeds / f"{index:03d}_{path.name}").write_bytes(bytes([kind]) + path.read_bytes())
    dictionary = WORK / "parameters" / "keys.dict"
    _write_json_dictionary(dictionary)
    options = [*_libfuzzer_options(seconds, timeout, artifacts), f"-dict={dictionary}"]
    command = [sys.executable, str(Path(__file__).resolve()), "--worker", *options]
    _run_libfuzzer([*command, str(corpus), str(seeds)], report, artifacts)
    return report


def _write_json_dictionary(path: Path) -> None:
    """A libFuzzer dictionary: the keys and short strings of the seed JSON files, as JSON tokens."""
    words: set[str] = set()

    def walk(value: object) -> None:
        if isinstance(value, dict):
            words.update(value)
            for item in value.values():
                walk(item)
        elif isinstance(value, list):
            for item in value:
                walk(item)
        elif isinstance(value, str) and len(value) < 64:
            words.add(value)

    for seed in _seed_files((".json",)):
        if not seed.name.endswith("_results.json"):
            try:
                walk(json.loads(seed.read_text()))
            except ValueError:  # a seed need not be valid JSON
                pass
    tokens = [json.dumps(word) for word in sorted(words)]
    tokens += [
        "NaN",
        "Infinity",
        "1e308",
        "-1",
        "true",
        "null",
        "[]",
        "{}",
        '"..evil"',
        '"\\u0000"',
    ]
    escaped = (token.replace("\\", "\\\\").replace('"', '\\"') for token in tokens)
    path.write_text("".join(f'k{i}="{token}"\n' for i, token in enumerate(escaped)))


# -- the atheris worker (a separate process: atheris takes over the interpreter) --


def _worker(libfuzzer_argv: list[str]) -> None:
    import atheris  # noqa: PLC0415 - optional dependency, only in the worker
    import numpy  # noqa: F401, PLC0415 - imported before instrumenting: not part of the target

    import contact_app as ca  # noqa: PLC0415
    from contact_app.analysis import StructuralMechanicsAnalysis  # noqa: PLC0415
    from contact_app.analysis.reporting import Reporter  # noqa: PLC0415
    from contact_app.parameters import Parameters  # noqa: PLC0415

    logging.disable(
        logging.CRITICAL
    )  # the deprecation warnings of mutated inputs would flood the log
    warnings.simplefilter("ignore")
    case = Path(tempfile.mkdtemp(prefix="contact_app_fuzz_"))
    for path in (CASES / PARAMETERS_CASE).iterdir():
        if path.name.startswith(PARAMETERS_STEM):
            shutil.copyfile(path, case / path.name)
    os.chdir(case)
    parameters_file = case / f"{PARAMETERS_STEM}_parameters.json"
    materials_file = case / f"{PARAMETERS_STEM}_materials.json"
    reference_parameters = parameters_file.read_bytes()
    reference_materials = materials_file.read_bytes()
    fuzzed_file = case / "fuzzed_parameters.json"

    def one_input(data: bytes) -> None:
        if not data:
            return
        materials_file.write_bytes(reference_materials)
        if data[0] % 2 == KIND_MATERIALS:
            materials_file.write_bytes(data[1:])
            fuzzed_file.write_bytes(reference_parameters)
        else:
            fuzzed_file.write_bytes(data[1:])
        try:
            parameters = Parameters.from_file(fuzzed_file)
            StructuralMechanicsAnalysis(
                ca.Model(),
                parameters,
                base_dir=case,
                reporter=Reporter(quiet=True),
                safe=True,
                parameters_file=fuzzed_file,
            )
        except (ca.InputError, ca.ConfigurationError):
            pass

    # Every seed once first, so that the modules the analysis imports lazily are loaded, then only
    # contact_app's own functions are instrumented (atheris.instrument_all() would take a minute).
    for seed in libfuzzer_argv:
        folder = Path(seed)
        if not seed.startswith("-") and folder.is_dir():
            for path in sorted(folder.iterdir()):
                one_input(path.read_bytes())
    print(f"INFO: instrumented {_instrument(atheris)} contact_app functions", file=sys.stderr)
    atheris.Setup([sys.argv[0], *libfuzzer_argv], one_input)
    atheris.Fuzz()


def _instrument(atheris: Any) -> int:
    """Instruments contact_app's functions in place; returns how many.

    Every function of the loaded contact_app modules, and every reference to it from those modules
    (module globals, class members), is replaced by its atheris-instrumented copy.
    """
    instrumented: dict[Any, Any] = {}

    def swap(value: Any) -> Any:
        function = value.__func__ if isinstance(value, staticmethod | classmethod) else value
        if not isinstance(function, types.FunctionType):
            return None
        if not (function.__module__ or "").startswith(PACKAGES):
            return None
        if function not in instrumented:
            instrumented[function] = atheris.instrument_func(function)
        new = instrumented[function]
        return type(value)(new) if isinstance(value, staticmethod | classmethod) else new

    for name, module in list(sys.modules.items()):
        if not name.startswith(PACKAGES) or module is None:
            continue
        for owner in [module, *(v for v in vars(module).values() if inspect.isclass(v))]:
            if inspect.isclass(owner) and not owner.__module__.startswith(PACKAGES):
                continue
            for attribute, value in list(vars(owner).items()):
                if (new := swap(value)) is not None:
                    setattr(owner, attribute, new)
    return len(instrumented)


def main(argv: list[str] | None = None) -> int:
    """Command line: run the targets for the given time and print the reports."""
    argv = sys.argv[1:] if argv is None else argv
    if argv[:1] == ["--worker"]:
        _worker(argv[1:])
        return 0
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--minutes", type=float, default=1.0, help="total fuzzing time")
    parser.add_argument("--target", choices=("mdpa", "parameters", "all"), default="all")
    parser.add_argument("--timeout", type=int, default=10, help="seconds one input may take")
    args = parser.parse_args(argv)
    targets = ("mdpa", "parameters") if args.target == "all" else (args.target,)
    seconds = 60.0 * args.minutes / len(targets)
    runners = {"mdpa": fuzz_mdpa, "parameters": fuzz_parameters}
    reports = []
    for target in targets:
        report = runners[target](seconds, args.timeout)
        print(report.line(), flush=True)
        for finding in report.findings:
            print(f"  finding: {finding}")
        reports.append(report)
    return 1 if any(report.findings for report in reports) else 0


if __name__ == "__main__":
    sys.exit(main())
