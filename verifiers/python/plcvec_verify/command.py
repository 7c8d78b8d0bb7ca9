"""`plcvec verify`: the CI gate. Exit 0 passed, 1 failures, 2 usage or harness error, 5 nothing tested."""
from __future__ import annotations

import argparse
import os
import re
import sys
from pathlib import Path

from . import settings
from .errors import VerifyError
from .gate import NOTHING_TESTED
from .locate import default_vectors, default_vectors_text

EXIT_STATUS = f"""\
exit status:
  0    every selected vector passed (or is a known failure), and at least one passed
  1    some vector failed, errored, was not run, or is a stale known failure
  2    usage or harness error: bad path or file, an unknown family/instruction/tag/interpretation
       name or an --id glob that matches nothing, an adapter that cannot be started or keeps crashing
  {NOTHING_TESTED}    nothing tested: no vector selected, nothing passed (all skipped), or more skipped
       than --max-skipped allows (--allow-empty accepts the first two; pytest's "no tests collected")
  130  stopped by SIGINT, 143 stopped by SIGTERM (the adapter is ended, the reports are written)
"""


def add_arguments(p: argparse.ArgumentParser) -> None:
    how = p.add_mutually_exclusive_group(required=True)
    how.add_argument("--adapter", metavar="CMD", help='run this adapter process, e.g. "./emu --plcvec" (PROTOCOL.md)')
    how.add_argument("--python", metavar="MODULE:CLASS", help="an adapter object in this process (adapters.py)")
    p.add_argument("--vectors", help=f"vector folder or family file (default: {default_vectors_text()})")
    sel = p.add_argument_group("selection (each repeatable; OR within one, AND across)")
    sel.add_argument("--family", action="append", default=[])
    sel.add_argument("--instruction", action="append", default=[], help='e.g. "LDDT<=" or "TADDP"')
    sel.add_argument("--tag", action="append", default=[], help="e.g. boundary, nonexistent-date")
    sel.add_argument("--id", action="append", default=[], metavar="GLOB", help='id glob, e.g. "fx5-time-add/TADD/*"')
    sel.add_argument("--interpretation", action="append", default=[], metavar="ID",
                     help="vectors whose outcome depends on this interpretation")
    sel.add_argument("--shard", metavar="K/N", help="run the K-th of N shards (by a hash of the id)")
    gate = p.add_argument_group("what a passing run must show")
    gate.add_argument("--allow-empty", action="store_true",
                      help=f"pass a run that selects no vector or in which nothing passes (else exit {NOTHING_TESTED})")
    gate.add_argument("--max-skipped", metavar="N|N%",
                      help=f"exit {NOTHING_TESTED} when more than N vectors (or N%% of those selected) are skipped")
    p.add_argument("--choose", action="append", default=[], metavar="ID=ALT",
                   help="the alternative this implementation follows, for adapters that do not declare it")
    p.add_argument("--infer", action="store_true",
                   help="find the interpretation alternatives the answers follow and print the --choose line "
                        "and hello declaration that give them; exit 0 only when one choice explains every vector")
    p.add_argument("--expectations", metavar="FILE", help="known failures (TOML, see known.py)")
    p.add_argument("--write-expectations", metavar="FILE",
                   help="write the failing vectors as a new expectations file (reason: 'not yet triaged')")
    p.add_argument("--jsonl", metavar="FILE", help="write one JSON line per vector")
    p.add_argument("--junit", metavar="FILE", help="write JUnit XML")
    p.add_argument("--timeout", type=float, default=None,
                   help="the bound on an answer: seconds per batch before an adapter process is killed (default "
                        "30), seconds per vector for an adapter in process (default 10)")
    p.add_argument("--batch-size", type=int, default=256, help="vectors per request line (default 256)")
    p.add_argument("--max-restarts", type=int, default=10, help="restarts after adapter faults before giving up")
    p.add_argument("--quiet", "-q", action="store_true", help="only the totals line")
    p.add_argument("--verbose", "-v", action="store_true", help="also list skipped and known failures")
    p.add_argument("--no-progress", action="store_true", help="no progress bar even on a terminal")


def register(sub, spec_parent) -> None:
    p = sub.add_parser("verify", help="run the vectors against an implementation (CI gate)",
                       description=__doc__, epilog=EXIT_STATUS, formatter_class=argparse.RawDescriptionHelpFormatter)
    add_arguments(p)
    p.set_defaults(func=main_args)


# The environment every runner reads (CONTRACT.md, "Running the suite"): each variable is the
# default of the option beside it; an option given on the command line wins.
ENVIRONMENT = {"PLCVEC_VECTORS": "vectors", "PLCVEC_ID": "id", "PLCVEC_FAMILY": "family",
               "PLCVEC_INSTRUCTION": "instruction", "PLCVEC_TAG": "tag", "PLCVEC_INTERPRETATION": "interpretation",
               "PLCVEC_SHARD": "shard", "PLCVEC_KNOWN_FAILURES": "expectations",
               "PLCVEC_WRITE_EXPECTATIONS": "write_expectations", "PLCVEC_TIMEOUT": "timeout"}
_LISTS = ("id", "family", "instruction", "tag", "interpretation")


def apply_environment(args, environ=None, warn=None) -> dict:
    """Fill the options not given from the PLCVEC_* variables; -> {option: the variable it came from}.

    A deprecated name is read as the setting it was renamed to (settings.DEPRECATED); `warn` is given
    each warning the environment earns (a deprecated name, a PLCVEC_* variable that is no setting)."""
    from .settings import DEPRECATED, warnings

    environ = os.environ if environ is None else environ
    for message in warnings(environ):
        (warn or _warn)(message)
    renamed = {d.replacement: d.name for d in DEPRECATED if d.name in environ and d.replacement not in environ}
    came = {}
    for variable, option in ENVIRONMENT.items():
        source = variable if variable in environ else renamed.get(variable, variable)
        text = environ.get(source)
        if text is None or getattr(args, option):
            continue
        if option in _LISTS:
            # Comma-separated; an empty item (`PLCVEC_FAMILY=,`) stays, to be refused by name.
            value = [item.strip() for item in text.split(",")]
        elif option == "timeout":
            value = parse_timeout(text, source)
        else:
            value = text
            if not text:
                raise VerifyError(f"{source} is set but empty")
        setattr(args, option, value)
        came[option] = source
    return came


def _warn(message: str) -> None:
    print(f"plcvec: {message}", file=sys.stderr)


# The bound on an answer (CONTRACT.md, "The environment"): one rule in every runner, so that a value
# one runner takes is never refused by another, and none overflows a platform's clock.
TIMEOUT_PATTERN = re.compile(r"[0-9]+(\.[0-9]+)?")
TIMEOUT_MAX = settings.TIMEOUT_MAX_S


def parse_timeout(text: str, option: str) -> float:
    """A number of seconds, written as digits with an optional fraction, above 0 and at most one day."""
    value = float(text) if TIMEOUT_PATTERN.fullmatch(text) else None
    if value is None or not 0 < value <= TIMEOUT_MAX:
        raise VerifyError(f"{option}={text}: the bound must be a number of seconds above 0 and at most "
                          f"{TIMEOUT_MAX}, written as digits with an optional fraction (2, 0.5)")
    return value


def build_selection(args, came: dict | None = None):
    from .selection import Selection, parse_shard

    came = came or {}
    return Selection(families=tuple(args.family), instructions=tuple(args.instruction), tags=tuple(args.tag),
                     ids=tuple(args.id), interpretations=tuple(args.interpretation),
                     shard=parse_shard(args.shard, came.get("shard", "--shard")) if args.shard else None)


def build_gate(allow_empty: bool, max_skipped: str | None, option_prefix: str = "--"):
    from .gate import Gate, parse_max_skipped

    if max_skipped is None:
        return Gate(allow_empty=allow_empty, option_prefix=option_prefix)
    limit, percent = parse_max_skipped(max_skipped, f"{option_prefix}max-skipped")
    return Gate(allow_empty=allow_empty, max_skipped=limit, percent=percent, option_prefix=option_prefix)


def parse_choices(items) -> dict:
    out = {}
    for text in items:
        if "=" not in text:
            raise VerifyError(f"--choose takes INTERPRETATION=ALTERNATIVE, got {text!r}")
        k, v = text.split("=", 1)
        out[k] = v
    return out


IN_PROCESS_TIMEOUT = float(settings.TIMEOUT_DEFAULT_S)   # seconds per vector for an adapter object (PLCVEC_TIMEOUT's default)


def make_adapter(args):
    from .adapters import InProcess, load_python_adapter
    from .stdio import StdioAdapter

    if args.timeout is not None and not args.timeout > 0 or args.batch_size < 1:
        raise VerifyError("--timeout must be > 0 and --batch-size >= 1")
    if args.python:
        return InProcess(load_python_adapter(args.python), args.python, timeout=args.timeout or IN_PROCESS_TIMEOUT)
    return StdioAdapter(args.adapter, timeout=args.timeout or 30.0, batch_size=args.batch_size,
                        max_restarts=args.max_restarts)


def infer_exit_code(report, inferred) -> int:
    """`--infer`: 0 only when one choice of alternatives explains every vector (and the run tested
    something); a harness error or a stop keeps its own status."""
    if report.stopped or report.aborted:
        return report.exit_code
    if not inferred.complete:
        return 1
    return NOTHING_TESTED if not report.failed and report.shortfall else 0


def main_args(args) -> int:
    from .stdio import end_all
    from .stopping import Stopped, stop_on_signals

    try:
        with stop_on_signals():
            return _verify(args)
    except Stopped as exc:   # stopped outside the run itself (loading, writing reports)
        end_all()
        print(f"plcvec verify: {exc}", file=sys.stderr)
        return exc.exit_code


def _verify(args) -> int:
    from . import reports
    from .known import KnownFailures, write_expectations
    from .progress import Progress
    from .runner import run
    from .suite import Suite

    try:
        came = apply_environment(args)
        # The options' own mistakes first, before the vectors are read: a usage error costs no load.
        gate = build_gate(args.allow_empty, args.max_skipped)
        choose = parse_choices(args.choose)
        suite = Suite.load(args.vectors or default_vectors().path)
        selection = build_selection(args, came)
        selection.check(suite, labels={kind: came[kind] for kind in _LISTS if kind in came})
        known = KnownFailures.load(args.expectations) if args.expectations else None
        adapter = make_adapter(args)
        progress = None if args.no_progress or args.quiet else Progress.for_stream(sys.stderr)
        report = run(suite, adapter, selection, choose=choose, known=known,
                     progress=progress, gate=gate)
        if progress:
            progress.done()
        # Reports first: whatever the outcome, the CI job keeps them.
        if args.jsonl:
            reports.write_jsonl(report, args.jsonl)
        if args.junit:
            reports.write_junit(report, args.junit)
        if args.write_expectations:
            n = write_expectations(args.write_expectations, report.results, "not yet triaged")
            print(f"plcvec verify: {n} known failures written to {args.write_expectations}", file=sys.stderr)
        inferred = None
        if args.infer:
            from .infer import inference

            inferred = inference(report, frozenset(report.cpu_writes))
        text = reports.summary_text(report, verbose=args.verbose, inferred=inferred, infer=args.infer)
        if args.quiet:
            text = text.rstrip("\n").rsplit("\n", 1)[-1] + "\n"
        sys.stdout.write(text)
        if report.aborted:
            print(f"plcvec verify: {report.aborted}", file=sys.stderr)
        elif not report.failed and report.shortfall:
            print(f"plcvec verify: {report.shortfall}", file=sys.stderr)
        if inferred is not None:
            return infer_exit_code(report, inferred)
        return report.exit_code
    except VerifyError as exc:
        print(f"plcvec verify: {exc}", file=sys.stderr)
        return 2


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python3 -m plcvec_verify", description=__doc__, epilog=EXIT_STATUS,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    add_arguments(p)
    return main_args(p.parse_args(argv))
