"""Console report: table rows, progress bar only on terminals, closing summary."""

from __future__ import annotations

import io

from contact_app.analysis import Reporter, StepRecord


class _Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def _records() -> list[StepRecord]:
    return [
        StepRecord(1, 0.5, 2, (1e-12, 3e-15), None, True),
        StepRecord(2, 1.0, 10, (2e-3, 4e-4), (1e-2, 5e-5), False),
    ]


def test_table_rows_and_summary() -> None:
    stream = io.StringIO()
    reporter = Reporter(stream)
    reporter.begin_loop(0.0, 1.0, 2)
    for record in _records():
        reporter.record_step(record)
    reporter.add_builder_timings({"setup": 0.5, "build": 1.0, "solve": 0.25})
    reporter.files = ["out/a.vtu", "out/b.vtu"]
    reporter.finish()
    lines = stream.getvalue().splitlines()
    assert lines[0].split() == [
        "step",
        "time",
        "iter",
        "res",
        "ratio",
        "res",
        "abs",
        "dx",
        "ratio",
        "dx",
        "abs",
        "converged",
    ]
    assert lines[1].split() == ["1", "5.000000e-01", "2", "1.000e-12", "3.000e-15", "-", "-", "yes"]
    assert lines[2].split()[-1] == "NO"
    assert lines[3] == "summary: 2 steps, 12 Newton iterations, 1 NOT converged (steps 2)"
    assert "assembly 1.500 s, linear solve 0.250 s" in lines[4]
    assert lines[5] == "  files written (2): out/a.vtu, out/b.vtu"
    assert "\r" not in stream.getvalue()  # not a terminal: no progress bar
    assert reporter.non_converged_steps() == [2]


def test_progress_bar_on_a_terminal_with_several_steps() -> None:
    stream = _Terminal()
    reporter = Reporter(stream)
    reporter.begin_loop(0.0, 1.0, 2)
    reporter.record_step(_records()[0])
    assert stream.getvalue().endswith("[###############...............]  50%  step 1/2")
    reporter.record_step(_records()[1])
    reporter.finish()
    text = stream.getvalue()
    assert text.count("\r\x1b[K") == 2  # the bar is cleared before the next row and the summary
    assert "summary:" in text.splitlines()[-3]


def test_no_progress_bar_for_a_single_step() -> None:
    stream = _Terminal()
    reporter = Reporter(stream)
    reporter.begin_loop(0.0, 1.0, 1)
    reporter.record_step(_records()[0])
    assert "[" not in stream.getvalue()


def test_quiet_prints_nothing_but_keeps_the_records() -> None:
    reporter = Reporter(quiet=True)
    reporter.begin_loop(0.0, 1.0, 2)
    reporter.record_step(_records()[1])
    reporter.finish()
    assert reporter.non_converged_steps() == [2]
    assert reporter.summary().startswith("summary: 1 steps, 10 Newton iterations")
