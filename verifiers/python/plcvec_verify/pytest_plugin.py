"""pytest plugin: one test item per vector, so an implementer gets pytest's -k, -x, --lf and reports.

    pytest --plcvec-adapter "./my-emulator --plcvec"            # a process speaking PROTOCOL.md
    pytest --plcvec-python mypkg.plcvec_adapter:Adapter          # an adapter object in process
    pytest --plcvec-python ... -k "TADD and boundary" --plcvec-expectations known.toml

Items are named by vector id (node id `plcvec::<id>`). The vectors pytest keeps after selection
are run together through one adapter when the first item runs (one process, batched), and each
item then reports its own result. Without --plcvec-adapter or --plcvec-python the plugin does
nothing.
"""
from __future__ import annotations

import pytest

from .errors import VerifyError


def pytest_addoption(parser):
    g = parser.getgroup("plcvec", "plcvec conformance vectors")
    g.addoption("--plcvec-adapter", metavar="CMD", help="adapter process to verify (PROTOCOL.md)")
    g.addoption("--plcvec-python", metavar="MODULE:CLASS", help="adapter object to verify in process")
    g.addoption("--plcvec-vectors", metavar="PATH", help="vector folder or file (default: the checkout's vectors/, else those installed with plcvec)")
    g.addoption("--plcvec-expectations", metavar="FILE", help="known failures (TOML)")
    g.addoption("--plcvec-choose", action="append", default=[], metavar="ID=ALT",
                help="interpretation alternative the implementation follows, if its adapter does not declare it")
    g.addoption("--plcvec-timeout", type=float, default=30.0, help="seconds per batch (adapter processes)")
    g.addoption("--plcvec-batch-size", type=int, default=256)


def _enabled(config):
    return bool(config.getoption("plcvec_adapter") or config.getoption("plcvec_python"))


class VectorFailure(Exception):
    """A vector's differences, shown as pytest's failure text without a Python traceback."""


class PlcvecSuite(pytest.Collector):
    def collect(self):
        return [VectorItem.from_parent(self, name=v["id"], vector=v) for v in self.config._plcvec_suite.vectors]


class VectorItem(pytest.Item):
    def __init__(self, *, vector, **kw):
        super().__init__(**kw)
        self.vector = vector
        for tag in vector.get("tags", ()):
            self.add_marker(tag.replace("-", "_"), append=True)
        self.keywords[vector["instruction"]] = True
        self.keywords[vector["family"]] = True

    def runtest(self):
        from . import runner

        result = _results(self.session).get(self.vector["id"])
        if isinstance(result, str):            # the whole run could not be made
            raise VectorFailure(result)
        if result.status == runner.SKIP:
            pytest.skip(result.message)
        if result.status == runner.XFAIL:
            pytest.xfail(result.message)
        if result.status != runner.PASS:
            raise VectorFailure(self._detail(result))

    def _detail(self, result):
        v = self.vector
        lines = [f"{result.status}: {v['instruction']}: {v.get('description', '')}"]
        if result.choices:
            lines.append("judged by: " + ", ".join(f"{i}={a}" for i, a in sorted(result.choices.items())))
        lines += [p.line() for p in result.problems]
        lines += [m for m in [result.message] if m] + [f"note: {n}" for n in result.notes]
        lines.append("spec clauses: " + ", ".join(v.get("clauses", ())))
        return "\n".join(lines)

    def repr_failure(self, excinfo):
        if isinstance(excinfo.value, VectorFailure):
            return str(excinfo.value)
        return super().repr_failure(excinfo)

    def reportinfo(self):
        return self.config._plcvec_suite.source, None, f"plcvec {self.name}"


def pytest_configure(config):
    if not _enabled(config):
        return
    from .locate import default_vectors
    from .suite import Suite

    try:
        config._plcvec_suite = Suite.load(config.getoption("plcvec_vectors") or default_vectors().path)
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
        items.extend(PlcvecSuite.from_parent(session, name="plcvec").collect())


def _results(session):
    config = session.config
    if config._plcvec_results is None:
        config._plcvec_results = _run(session)
    return config._plcvec_results


def _run(session):
    from .adapters import InProcess, load_python_adapter
    from .command import parse_choices
    from .known import KnownFailures
    from .runner import run
    from .stdio import StdioAdapter

    config = session.config
    suite = config._plcvec_suite
    vectors = [i.vector for i in session.items if isinstance(i, VectorItem)]
    try:
        known = KnownFailures.load(config.getoption("plcvec_expectations")) \
            if config.getoption("plcvec_expectations") else None
        if config.getoption("plcvec_python"):
            spec = config.getoption("plcvec_python")
            adapter = InProcess(load_python_adapter(spec), spec)
        else:
            adapter = StdioAdapter(config.getoption("plcvec_adapter"), timeout=config.getoption("plcvec_timeout"),
                                   batch_size=config.getoption("plcvec_batch_size"))
        report = run(suite, adapter, vectors=vectors, known=known,
                     choose=parse_choices(config.getoption("plcvec_choose")))
    except VerifyError as exc:
        return _Everywhere(f"plcvec: {exc}")
    config._plcvec_report = report
    results = {r.id: r for r in report.results}
    if report.aborted:
        for r in report.results:
            if r.status == "not-run":
                r.message = f"{r.message}: {report.aborted}"
    return results


class _Everywhere(dict):
    """Every id maps to the same harness error."""

    def __init__(self, message):
        super().__init__()
        self.message = message

    def get(self, key, default=None):
        return self.message


def pytest_terminal_summary(terminalreporter, config):
    report = getattr(config, "_plcvec_report", None)
    if report is None:
        return
    from .reports import header

    h = header(report)
    terminalreporter.write_sep("-", "plcvec")
    terminalreporter.write_line(f"suite {h['suite_version']} schema {h['schema_version']} spec sha256 {h['spec_sha256'][:12]}; "
                                f"adapter {h['adapter'].get('name')}")
    stale = [r for r in report.results if r.status == "stale" and not r.family]
    for r in stale:
        terminalreporter.write_line(f"STALE {r.id}: {r.message}")
