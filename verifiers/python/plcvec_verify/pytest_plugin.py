"""pytest plugin: one test item per vector, so an implementer gets pytest's -k, -x, --lf and reports.

    pytest --plcvec-adapter "./my-emulator --plcvec"            # a process speaking PROTOCOL.md
    pytest --plcvec-python mypkg.plcvec_adapter:Adapter          # an adapter object in process
    pytest --plcvec-python ... -k "TADD and boundary" --plcvec-expectations known.toml

Items are named by vector id (node id `plcvec::<id>`). The vectors pytest keeps after selection
are run together through one adapter when the first item runs (one process, batched), and each
item then reports its own result. Without --plcvec-adapter or --plcvec-python the plugin does
nothing.

The gate holds as with `plcvec verify`: an unknown name in --plcvec-family/-instruction/-tag/
-interpretation, an --plcvec-id glob that matches nothing, or a `-m` marker that is neither a tag
nor a registered marker is a usage error (pytest's exit 4); a session in which no vector is
selected, none passes (all skipped), or more are skipped than --plcvec-max-skipped allows exits 5
(pytest's "no tests collected"), unless --plcvec-allow-empty says the job means it. SIGTERM stops
the session like Ctrl-C, with the adapter ended.
"""
from __future__ import annotations

import re
import signal

import pytest

from .errors import VerifyError


def pytest_addoption(parser):
    g = parser.getgroup("plcvec", "plcvec conformance vectors")
    g.addoption("--plcvec-adapter", metavar="CMD", help="adapter process to verify (PROTOCOL.md)")
    g.addoption("--plcvec-python", metavar="MODULE:CLASS", help="adapter object to verify in process")
    g.addoption("--plcvec-vectors", metavar="PATH", help="vector folder or file (default: the checkout's vectors/, else those installed with plcvec)")
    g.addoption("--plcvec-expectations", metavar="FILE", help="known failures (TOML)")
    g.addoption("--plcvec-write-expectations", metavar="FILE",
                help="write the failing vectors of the run as a known-failures file (adopting the suite); "
                     "PLCVEC_WRITE_EXPECTATIONS")
    g.addoption("--plcvec-choose", action="append", default=[], metavar="ID=ALT",
                help="interpretation alternative the implementation follows, if its adapter does not declare it")
    g.addoption("--plcvec-timeout", type=float, default=None,
                help="the bound on an answer: seconds per batch for an adapter process (default 30), per vector "
                     "for an adapter object (default 10); PLCVEC_TIMEOUT")
    g.addoption("--plcvec-batch-size", type=int, default=256)
    for kind, example in (("family", "fx5-time-add"), ("instruction", "TADDP"), ("tag", "boundary"),
                          ("id", "'fx5-time-add/TADD/*'"), ("interpretation", "TADD-EXACT-24")):
        g.addoption(f"--plcvec-{kind}", action="append", default=[], metavar=kind.upper(),
                    help=f"select by {kind} (repeatable; OR within one option, AND across), e.g. {example}")
    g.addoption("--plcvec-shard", metavar="K/N", help="run the K-th of N shards (by a hash of the id)")
    g.addoption("--plcvec-allow-empty", action="store_true",
                help="pass a session that selects no vector or in which nothing passes (else exit 5)")
    g.addoption("--plcvec-infer", action="store_true",
                help="find the interpretation alternatives the answers follow (as plcvec verify --infer): a failure "
                     "another alternative explains is xfail, the session passes only when one choice explains all")
    g.addoption("--plcvec-max-skipped", metavar="N|N%",
                help="exit 5 when more than N vectors (or N%% of those selected) are skipped")


def _enabled(config):
    return bool(config.getoption("plcvec_adapter") or config.getoption("plcvec_python"))


class VectorFailure(Exception):
    """A vector's differences, shown as pytest's failure text without a Python traceback."""


class PlcvecSuite(pytest.Collector):
    def collect(self):
        vectors = self.config._plcvec_selection.apply(self.config._plcvec_suite.vectors)
        return [VectorItem.from_parent(self, name=v["id"], vector=v) for v in vectors]


class VectorItem(pytest.Item):
    def __init__(self, *, vector, **kw):
        super().__init__(**kw)
        self.vector = vector
        for tag in vector.get("tags", ()):
            self.add_marker(tag.replace("-", "_"), append=True)
        self.keywords[vector["instruction"]] = True
        self.keywords[vector["family"]] = True

    def runtest(self):
        from .verdict import PASS, SKIP, XFAIL

        result = _results(self.session).get(self.vector["id"])
        if isinstance(result, str):            # the whole run could not be made
            raise VectorFailure(result)
        if result.status == SKIP:
            pytest.skip(result.message)
        if result.status == XFAIL:
            pytest.xfail(result.message)
        if result.status != PASS:
            raise VectorFailure(self._detail(result))

    def _detail(self, result):
        """The one failure block (verifiers/parity/TEXT.md), as `plcvec verify` prints it."""
        from .describe import describe

        report = getattr(self.config, "_plcvec_report", None)
        if report is None:      # no run was made: a message alone
            return "\n".join([f"{result.status.upper()} {result.id}", f"    {result.message}"])
        suite = report.suite
        defaults = {i: d["default"] for i, d in suite.interpretations().items()}
        followed = {**defaults, **{i: d["alternative"] for i, d in report.interpretations.items()}}
        return describe(result, self.vector, followed, defaults, suite.expectations)

    def repr_failure(self, excinfo):
        if isinstance(excinfo.value, VectorFailure):
            return str(excinfo.value)
        if isinstance(excinfo.value, pytest.xfail.Exception):
            # A known failure is reported by its reason; pytest would build a whole traceback for it
            # (the source of every frame parsed again) and then drop it: 0.1 s per known failure.
            return str(excinfo.value)
        return super().repr_failure(excinfo)

    def reportinfo(self):
        return self.config._plcvec_suite.source, None, f"plcvec {self.name}"


def pytest_configure(config):
    if not _enabled(config):
        return
    from types import SimpleNamespace

    from .command import _LISTS, apply_environment, build_gate, build_selection
    from .locate import default_vectors
    from .suite import Suite

    try:
        # The PLCVEC_* variables are the options' defaults, as for plcvec verify.
        options = SimpleNamespace(**{k: config.getoption(f"plcvec_{k}") for k in (*_LISTS, "vectors", "shard",
                                                                                    "expectations", "timeout",
                                                                                    "write_expectations")})
        came = apply_environment(options)
        config._plcvec_options = options
        config._plcvec_suite = Suite.load(options.vectors or default_vectors().path)
        config._plcvec_selection = build_selection(options, {"shard": came.get("shard", "--plcvec-shard")})
        config._plcvec_selection.check(config._plcvec_suite, option_prefix="--plcvec-",
                                       labels={kind: came[kind] for kind in _LISTS if kind in came})
        config._plcvec_gate = build_gate(config.getoption("plcvec_allow_empty"),
                                         config.getoption("plcvec_max_skipped"), option_prefix="--plcvec-")
    except VerifyError as exc:
        raise pytest.UsageError(f"plcvec: {exc}")
    # Every tag becomes a marker (`-m boundary`), declared with the meaning the vector file gives it.
    tags = {}
    for h in config._plcvec_suite.headers.values():
        tags.update(h.get("tags", {}))
    for tag, meaning in sorted(tags.items()):
        config.addinivalue_line("markers", f"{tag.replace('-', '_')}: {meaning}")
    config._plcvec_results = None


@pytest.hookimpl(tryfirst=True)
def pytest_collection_modifyitems(session, config, items):
    # tryfirst: the vector items must be in the list before -k/-m deselect from it.
    if _enabled(config):
        _check_markexpr(config)
        items.extend(PlcvecSuite.from_parent(session, name="plcvec").collect())


# An identifier in a -m expression, as pytest's own expression grammar reads one.
_IDENT = re.compile(r"(?:\w|:|\+|-|\.|\[|\]|\\|/)+")
_MARKEXPR_WORDS = {"and", "or", "not", "True", "False", "None"}


def _check_markexpr(config):
    """`-m nosuchtag` would deselect every vector: a typo, refused like an unknown --plcvec-tag."""
    expr = config.getoption("markexpr", "") or ""
    registered = {line.split(":")[0].split("(")[0].strip() for line in config.getini("markers")}
    tags = sorted(config._plcvec_suite.names()["tag"])
    for name in _IDENT.findall(re.sub(r"\([^)]*\)", "", expr)):
        if name not in _MARKEXPR_WORDS and name not in registered:
            raise pytest.UsageError(f"plcvec: -m {expr!r}: {name} is neither a vector tag nor a registered marker; "
                                    f"tags (as markers): {', '.join(t.replace('-', '_') for t in tags)}")


def _results(session):
    config = session.config
    if config._plcvec_results is None:
        config._plcvec_results = _run(session)
    return config._plcvec_results


def _run(session):
    from .adapters import InProcess, load_python_adapter
    from .command import IN_PROCESS_TIMEOUT, parse_choices
    from .known import KnownFailures
    from .runner import run
    from .stdio import StdioAdapter
    from .stopping import stop_on_signals

    config = session.config
    suite = config._plcvec_suite
    vectors = [i.vector for i in session.items if isinstance(i, VectorItem)]
    try:
        options = config._plcvec_options
        known = KnownFailures.load(options.expectations) if options.expectations else None
        if config.getoption("plcvec_python"):
            spec = config.getoption("plcvec_python")
            adapter = InProcess(load_python_adapter(spec), spec, timeout=options.timeout or IN_PROCESS_TIMEOUT)
        else:
            adapter = StdioAdapter(config.getoption("plcvec_adapter"), timeout=options.timeout or 30.0,
                                   batch_size=config.getoption("plcvec_batch_size"))
        # pytest ends on SIGTERM without unwinding; within the run, it ends the adapter first.
        with stop_on_signals((signal.SIGTERM,)):
            report = run(suite, adapter, vectors=vectors, known=known, gate=config._plcvec_gate,
                         choose=parse_choices(config.getoption("plcvec_choose")))
    except VerifyError as exc:
        return _Everywhere(f"plcvec: {exc}")
    config._plcvec_report = report
    if options.write_expectations:
        # As plcvec verify does: written before anything is reported, an aborted run's failures so far included.
        from .known import write_expectations

        try:
            config._plcvec_written = write_expectations(options.write_expectations, report.results, "not yet triaged")
        except OSError as exc:
            # The vectors were judged; the file could not be written: a usage error at the session's end.
            config._plcvec_write_error = (f"plcvec: --plcvec-write-expectations {options.write_expectations}: "
                                          f"{exc.strerror or exc}")
    if report.stopped:
        raise KeyboardInterrupt(report.aborted)
    results = {r.id: r for r in report.results}
    if config.getoption("plcvec_infer"):
        results.update(_inferred_results(config, report))
    if report.aborted:
        for r in report.results:
            if r.status == "not-run":
                results[r.id] = r._replace(message=f"{r.message}: {report.aborted}")
    return results


def _inferred_results(config, report) -> dict:
    """--plcvec-infer: a failure the inferred choice explains becomes xfail (naming the declaration that
    explains it); a vector that passes now but would fail under that choice fails, saying so."""
    from .infer import inference
    from .verdict import FAIL, XFAIL

    inferred = config._plcvec_inference = inference(report, frozenset(report.cpu_writes))
    by_id = {r.id: r for r in report.results}
    out = {}
    for vid, change in inferred.explained.items():
        declare = " ".join(f"--choose {i}={a}" for i, a in change)
        out[vid] = by_id[vid]._replace(status=XFAIL, message=f"explained by another reading: {declare}")
    for vid in inferred.broken:
        out[vid] = by_id[vid]._replace(status=FAIL, message="passes under the alternatives followed, but not under "
                                       "the choice inferred for the other vectors (see the plcvec summary)")
    return out


class _Everywhere(dict):
    """Every id maps to the same harness error."""

    def __init__(self, message):
        super().__init__()
        self.message = message

    def get(self, key, default=None):
        return self.message


# Said when -k, -m or a --plcvec- filter left no vector: how to pick vectors by id instead.
_BY_ID = "; to run vectors by id, give --plcvec-id GLOB or PLCVEC_ID (a glob on the whole id)"


@pytest.hookimpl(tryfirst=True)
def pytest_sessionfinish(session, exitstatus):
    """A session that passed but proves nothing (or too little) exits 5, like `plcvec verify`."""
    config = session.config
    if not _enabled(config) or not hasattr(config, "_plcvec_gate") or config.option.collectonly:
        return
    if getattr(config, "_plcvec_write_error", None):
        session.exitstatus = pytest.ExitCode.USAGE_ERROR
        return
    gate = config._plcvec_gate
    report = getattr(config, "_plcvec_report", None)
    if exitstatus == pytest.ExitCode.OK:
        # No report: no vector item was left to run (-k, -m or the --plcvec- filters removed them all).
        config._plcvec_shortfall = report.shortfall if report is not None else gate.shortfall({}, 0)
        if report is None and config._plcvec_shortfall:
            # -k, -m or a --plcvec- filter left no vector: say how to pick vectors by id.
            config._plcvec_shortfall += _BY_ID
        if config._plcvec_shortfall:
            session.exitstatus = pytest.ExitCode.NO_TESTS_COLLECTED
    elif exitstatus == pytest.ExitCode.NO_TESTS_COLLECTED and gate.allow_empty and report is None:
        session.exitstatus = pytest.ExitCode.OK
    elif exitstatus == pytest.ExitCode.NO_TESTS_COLLECTED and report is None:
        config._plcvec_shortfall = gate.shortfall({}, 0) + _BY_ID


def pytest_terminal_summary(terminalreporter, config):
    shortfall = getattr(config, "_plcvec_shortfall", "")
    report = getattr(config, "_plcvec_report", None)
    if report is None:
        if shortfall:
            terminalreporter.write_sep("-", "plcvec")
            terminalreporter.write_line(f"NOT PASSED (exit 5): {shortfall}", red=True)
        return
    from .describe import interpretations_line, rollup_lines, skipped_lines
    from .infer import inference
    from .reports import header
    from .verdict import FAILING

    h = header(report)
    terminalreporter.write_sep("-", "plcvec")
    terminalreporter.write_line(f"suite {h['suite_version']} schema {h['schema_version']} spec sha256 {h['spec_sha256'][:12]}; "
                                f"adapter {h['adapter'].get('name')}")
    terminalreporter.write_line(interpretations_line(report))
    if report.cpu_writes:
        terminalreporter.write_line("cpu_writes: " + ", ".join(report.cpu_writes))
    stale = [r for r in report.results if r.status == "stale" and not r.family]
    for r in stale:
        terminalreporter.write_line(f"STALE {r.id}: {r.message}")
    # Each failure was printed once, by its own item; here only what explains them.
    inferred = getattr(config, "_plcvec_inference", None)
    if inferred is None and any((r.status in FAILING or r.status == "xfail") and r.family for r in report.results):
        inferred = inference(report, frozenset(report.cpu_writes))
    if inferred is not None:
        for line in rollup_lines(report, inferred, syntax="pytest"):
            terminalreporter.write_line(line)
    if config.getoption("plcvec_infer") and inferred is not None:
        from .infer import declaration_lines

        for line in declaration_lines(report, inferred):
            terminalreporter.write_line(line)
    for line in skipped_lines(report):
        terminalreporter.write_line(line, yellow=True)
    if shortfall:
        terminalreporter.write_line(f"NOT PASSED (exit 5): {shortfall}", red=True)
    if getattr(config, "_plcvec_write_error", None):
        terminalreporter.write_line(config._plcvec_write_error, red=True)
    written = getattr(config, "_plcvec_written", None)
    if written is not None:
        terminalreporter.write_line(f"{written} known failures written to {config._plcvec_options.write_expectations}")
