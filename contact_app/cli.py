"""Command line: ``contact-app info <file.mdpa>`` and ``contact-app run <parameters.json>``.

Exit codes: 0 success (with ``solver_settings.on_non_converged_step`` "continue", unconverged
steps are warned about and the run goes on, as in Kratos); 1 a step did not converge (the
default stops there, after step cutting when it is on), or a result check
(``from_json_check_result_process``) failed; 2 bad input or usage (the message starts with
``error:``; no traceback unless ``--debug``); 3 an internal error (a bug in contact_app);
130 interrupted (Ctrl-C).
"""

from __future__ import annotations

import argparse
import logging
import os
import sys
import time
from collections import Counter
from collections.abc import Callable, Sequence

import contact_app as ca
from contact_app.json_input import not_regular, quote

EXIT_OK = 0
EXIT_NOT_CONVERGED = 1
EXIT_INPUT_ERROR = 2
EXIT_INTERNAL_ERROR = 3
EXIT_INTERRUPTED = 130
#: Longest line of an error message printed (the quotes inside are shorter still).
MAX_LINE = 500

#: Historical variables the structural solver declares on the root model part "Structure".
INFO_HISTORICAL_VARIABLES = (
    "DISPLACEMENT",
    "REACTION",
    "VELOCITY",
    "ACCELERATION",
    "VOLUME_ACCELERATION",
    "NORMAL",
    "NODAL_H",
)


def count_entity_types(mdpa_path: str) -> dict[str, Counter[str]]:
    """Count the entities of each ``Begin Elements <Name>`` and ``Begin Conditions <Name>`` block.

    The model part does not keep the registered names of its entities, so they are taken from the
    block headers of the file (which the reader has already validated).

    Args:
        mdpa_path: path of the .mdpa file, extension included.

    Returns:
        ``{"Elements": Counter(name -> count), "Conditions": Counter(name -> count)}``.

    """
    counts: dict[str, Counter[str]] = {"Elements": Counter(), "Conditions": Counter()}
    block: tuple[str, str] | None = None
    with open(mdpa_path, encoding="utf-8", errors="replace") as stream:
        for raw_line in stream:
            words = raw_line.split("//", 1)[0].split()
            if not words:
                continue
            if block is None:
                if len(words) >= 3 and words[0] == "Begin" and words[1] in counts:
                    block = (words[1], words[2])
            elif words[0] == "End":
                block = None
            else:
                counts[block[0]][block[1]] += 1
    return counts


def _info(args: argparse.Namespace) -> int:
    """Read an mdpa file into a fresh model and print its summary."""
    start = time.perf_counter()
    model = ca.Model()
    model_part = model.CreateModelPart("Structure")
    for name in INFO_HISTORICAL_VARIABLES:
        model_part.AddNodalSolutionStepVariable(ca.get_variable(name))
    for candidate in (args.mdpa, args.mdpa + ".mdpa"):
        if os.path.exists(candidate) and not os.path.isfile(candidate):
            raise not_regular(candidate, "mdpa file")
    reader = ca.ModelPartIO(args.mdpa)
    reader.ReadModelPart(model_part)
    elapsed = time.perf_counter() - start

    print(model_part.Info(), end="")
    for kind, counter in count_entity_types(reader.FileName()).items():
        print(f"{kind.lower()} by type:" + ("" if counter else " none"))
        for name, count in sorted(counter.items()):
            print(f"  {name}: {count}")
    print(f"read {reader.FileName()} in {elapsed:.3f} s")
    return EXIT_OK


class _WarningFormatter(logging.Formatter):
    """``warning: <message>`` lines for the console."""

    def format(self, record: logging.LogRecord) -> str:
        return f"{record.levelname.lower()}: {record.getMessage()}"


def _install_console_logging() -> logging.Handler:
    handler = logging.StreamHandler(sys.stderr)
    handler.setFormatter(_WarningFormatter())
    handler.setLevel(logging.WARNING)
    logger = logging.getLogger("contact_app")
    logger.addHandler(handler)
    return handler


def _run(args: argparse.Namespace) -> int:
    """Run the analysis of a ProjectParameters.json."""
    handler = _install_console_logging()
    try:
        ca.analysis.run(
            args.parameters,
            stop_on_non_convergence=True if args.stop_on_non_convergence else None,
            quiet=args.quiet,
            safe=args.safe,
        )
    finally:
        logging.getLogger("contact_app").removeHandler(handler)
    return EXIT_OK


def _result_check_error() -> type[BaseException]:
    """The error class of from_json_check_result_process (AssertionError before it exists)."""
    try:
        from contact_app.processes.from_json_check_result_process import ResultCheckError
    except ImportError:
        return AssertionError
    return ResultCheckError


def _shown(error: BaseException) -> str:
    """The message of an error, each line escaped and capped (NULs, 20,000-character lines)."""
    return "\n".join(quote(line, MAX_LINE) for line in str(error).split("\n"))


def build_parser() -> argparse.ArgumentParser:
    """Build the argument parser of ``contact-app``."""
    parser = argparse.ArgumentParser(
        prog="contact-app", description="Finite-element mortar contact mechanics."
    )
    parser.add_argument("--debug", action="store_true", help="show tracebacks of errors")
    debug = argparse.ArgumentParser(add_help=False)
    debug.add_argument(
        "--debug", action="store_true", default=argparse.SUPPRESS, help="show tracebacks of errors"
    )
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

    info = commands.add_parser(
        "info", parents=[debug], help="read an .mdpa file and print its summary"
    )
    info.add_argument("mdpa", help="the .mdpa file (the extension may be omitted)")
    info.set_defaults(handler=_info)

    run = commands.add_parser(
        "run", parents=[debug], help="run an analysis (ProjectParameters.json)"
    )
    run.add_argument(
        "parameters",
        help="the ProjectParameters.json file; relative paths inside it resolve against the "
        "working directory, then against the file's own folder",
    )
    run.add_argument(
        "--stop-on-non-convergence",
        action="store_true",
        help="stop with exit code 1 at the first step that does not converge, even if "
        'solver_settings.on_non_converged_step is "continue" (stopping is the default); the '
        "outputs end at the last converged step",
    )
    run.add_argument("--quiet", action="store_true", help="no per-step table and summary")
    run.add_argument(
        "--safe",
        action="store_true",
        help="run only contact_app's own processes: refuse any python_module that would import "
        "code from the case folder, the working directory or sys.path (for cases you did not "
        "write)",
    )
    run.set_defaults(handler=_run)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of ``contact-app`` and ``python -m contact_app``.

    Args:
        argv: the arguments without the program name (default: ``sys.argv[1:]``).

    Returns:
        The exit code (see the module docstring).

    """
    args = build_parser().parse_args(argv)
    handler: Callable[[argparse.Namespace], int] = args.handler
    errors: tuple[tuple[type[BaseException], int], ...] = (
        (ca.InputError, EXIT_INPUT_ERROR),
        (ca.ConfigurationError, EXIT_INPUT_ERROR),
        (OSError, EXIT_INPUT_ERROR),
        (ca.ConvergenceError, EXIT_NOT_CONVERGED),
        (ca.InternalError, EXIT_INTERNAL_ERROR),
    )
    try:
        return handler(args)
    except KeyboardInterrupt:
        if args.debug:
            raise
        print("interrupted (Ctrl-C)", file=sys.stderr)
        return EXIT_INTERRUPTED
    except _result_check_error() as error:
        if args.debug:
            raise
        print(f"result check failed: {_shown(error)}", file=sys.stderr)
        return EXIT_NOT_CONVERGED
    except tuple(error for error, _ in errors) as error:
        if args.debug:
            raise
        print(f"error: {_shown(error)}", file=sys.stderr)
        return next(code for kind, code in errors if isinstance(error, kind))
    except Exception as error:  # a bug: say so in one paragraph unless --debug
        if args.debug:
            raise
        print(
            f"internal error (a bug in contact_app; please report it): {type(error).__name__}: "
            f"{_shown(error)}\n  fix:      rerun with --debug for the traceback",
            file=sys.stderr,
        )
        return EXIT_INTERNAL_ERROR
