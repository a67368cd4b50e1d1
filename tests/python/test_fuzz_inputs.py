"""Short bounded fuzzing of the .mdpa reader and the parameters layer (fuzz_inputs.py)."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
SPEC = importlib.util.spec_from_file_location("fuzz_inputs", ROOT / "benchmarks" / "fuzz_inputs.py")
fuzz_inputs = importlib.util.module_from_spec(SPEC)
sys.modules["fuzz_inputs"] = fuzz_inputs
SPEC.loader.exec_module(fuzz_inputs)

#: Seconds of fuzzing per target; with the atheris start-up (instrumenting every loaded Python
#: function, about 25 s of CPU) both stay under a minute.
SECONDS = 12


MDPA_MISSING = fuzz_inputs.mdpa_fuzzer_missing()
ATHERIS_MISSING = fuzz_inputs.atheris_missing()


@pytest.mark.skipif(bool(MDPA_MISSING), reason=MDPA_MISSING)
def test_mdpa_reader_survives_a_short_fuzzing_run() -> None:
    report = fuzz_inputs.fuzz_mdpa(SECONDS, timeout=10)
    assert report.executions > 0, report.line()
    assert report.findings == [], report.line() + "\n" + "\n".join(report.findings)


@pytest.mark.skipif(bool(ATHERIS_MISSING), reason=ATHERIS_MISSING)
def test_parameters_layer_survives_a_short_fuzzing_run() -> None:
    report = fuzz_inputs.fuzz_parameters(SECONDS, timeout=10)
    assert report.executions > 0, report.line()
    assert report.findings == [], report.line() + "\n" + "\n".join(report.findings)
