"""Reports of a run: a summary for people, JSON lines for programs, JUnit XML for CI dashboards.

Each records what a result means only together with: the suite version, the spec hash, the
adapter, and the interpretation alternative every vector was judged by.
"""
from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from ._report import Report
from .atomic import write_atomic
from .verdict import ERROR, FAIL, FAILING, NOT_RUN, PASS, SKIP, STALE, STATUSES, XFAIL

SHOW_PROBLEMS = 12     # field lines shown per failing vector in the summary


def header(report: Report) -> dict:
    s = report.suite
    return {
        "suite": s.source,
        "suite_version": s.suite_version,
        "schema_version": s.schema_version,
        "spec_sha256": s.spec_sha256,
        "adapter": report.adapter,
        "interpretations": {i: {"alternative": d["alternative"], "declared": d["declared"]}
                            for i, d in sorted(report.interpretations.items())},
        "cpu_writes": list(report.cpu_writes),
        "selection": {k: list(v) if isinstance(v, tuple) else v
                      for k, v in vars(report.selection).items() if v},
    }


def summary_text(report: Report, verbose: bool = False, inferred=None, infer: bool = False) -> str:
    """What a person reads at the end of a run (verifiers/parity/TEXT.md): each failing vector once,
    with its field diff, then the roll-up by reading, the skips by reason, and the summary lines.

    `infer` (`plcvec verify --infer`): only the vectors no reading explains get a failure block, and
    the alternatives found follow the roll-up (infer.declaration_lines)."""
    from .describe import block, interpretations_line, rollup_lines, skipped_lines, totals_line
    from .infer import inference

    lines = []
    suite = report.suite
    by_id = suite.by_id
    defaults = {i: d["default"] for i, d in suite.interpretations().items()}
    followed = {**defaults, **{i: d["alternative"] for i, d in report.interpretations.items()}}
    if infer and inferred is None:
        inferred = inference(report, frozenset(report.cpu_writes))
    for r in report.results:
        if r.status not in FAILING and not (verbose and r.status in (XFAIL, SKIP)):
            continue
        if infer and r.id in inferred.explained:
            continue
        lines += block(r, by_id.get(r.id), followed, defaults, suite.expectations)
    noted = [r for r in report.results if r.notes and r.status not in FAILING]
    for r in noted[:SHOW_PROBLEMS]:
        for note in r.notes:
            lines.append(f"NOTE {r.id}: {note}")
    for note in report.notes:
        lines.append(f"NOTE adapter: {note}")
    if any((r.status in FAILING or r.status == XFAIL) and r.family for r in report.results):
        inferred = inferred or inference(report, frozenset(report.cpu_writes))
        lines += rollup_lines(report, inferred)
    if infer:
        from .infer import declaration_lines

        lines += declaration_lines(report, inferred)
    lines += skipped_lines(report)
    if report.aborted:
        lines.append(f"ABORTED: {report.aborted}")
    elif not report.failed and report.shortfall:
        lines.append(f"NOT PASSED (exit {report.exit_code}): {report.shortfall}")
    h = header(report)
    adapter = report.adapter.get("name", "?") + (f" {report.adapter['version']}" if report.adapter.get("version") else "")
    lines.append("")
    lines.append(f"plcvec verify: {adapter} against {h['suite']} (suite {h['suite_version'] or '?'}, "
                 f"schema {h['schema_version']}, spec sha256 {h['spec_sha256'][:12] or '?'})")
    lines.append(interpretations_line(report))
    if report.cpu_writes:
        lines.append("cpu_writes: " + ", ".join(report.cpu_writes))
    lines.append(f"{totals_line(report)} in {report.seconds:.2f} s")
    return "\n".join(lines) + "\n"


def skipped_lines(report: Report) -> list[str]:
    from .describe import skipped_lines as lines

    return lines(report)


def jsonl_lines(report: Report):
    yield {"type": "run", **header(report)}
    for r in report.results:
        item = {"type": "vector", "id": r.id, "family": r.family, "instruction": r.instruction, "status": r.status}
        if r.choices:
            item["choices"] = r.choices
        if r.problems:
            item["problems"] = [{"step": p.step, "field": p.field, "expected": _jsonable(p.expected),
                                 "actual": _jsonable(p.actual)} for p in r.problems]
        if r.message:
            item["message"] = r.message
        if r.notes:
            item["notes"] = list(r.notes)
        yield item
    yield {"type": "summary", "counts": report.counts, "seconds": round(report.seconds, 3),
           "aborted": report.aborted or None, "shortfall": report.shortfall or None, "notes": report.notes,
           "exit_code": report.exit_code}


def _jsonable(value):
    return value if isinstance(value, (bool, int, float, str)) or value is None else repr(value)


def write_jsonl(report: Report, path) -> None:
    write_atomic(path, "".join(json.dumps(item, sort_keys=True, ensure_ascii=False) + "\n" for item in jsonl_lines(report)))


def junit_xml(report: Report) -> str:
    h = header(report)
    root = ET.Element("testsuites", name="plcvec", tests=str(len(report.results)),
                      failures=str(report.count(FAIL) + report.count(STALE)),
                      errors=str(report.count(ERROR) + report.count(NOT_RUN)), time=f"{report.seconds:.3f}")
    families = {}
    for r in report.results:
        families.setdefault(r.family or "(expectations file)", []).append(r)
    from .describe import block

    by_id = report.suite.by_id
    expectations = report.suite.expectations
    defaults = {i: d["default"] for i, d in report.suite.interpretations().items()}
    followed = {**defaults, **{i: d["alternative"] for i, d in report.interpretations.items()}}
    for family, results in sorted(families.items()):
        suite = ET.SubElement(root, "testsuite", name=family, tests=str(len(results)),
                              failures=str(sum(r.status in (FAIL, STALE) for r in results)),
                              errors=str(sum(r.status in (ERROR, NOT_RUN) for r in results)),
                              skipped=str(sum(r.status in (SKIP, XFAIL) for r in results)))
        props = ET.SubElement(suite, "properties")
        for name, value in (("suite_version", h["suite_version"]), ("schema_version", h["schema_version"]),
                            ("spec_sha256", h["spec_sha256"]), ("adapter", json.dumps(h["adapter"], sort_keys=True))):
            ET.SubElement(props, "property", name=name, value=str(value))
        for i, d in h["interpretations"].items():
            ET.SubElement(props, "property", name=f"interpretation.{i}",
                          value=d["alternative"] + ("" if d["declared"] else " (default)"))
        if h["cpu_writes"]:
            ET.SubElement(props, "property", name="cpu_writes", value=", ".join(h["cpu_writes"]))
        for r in results:
            case = ET.SubElement(suite, "testcase", classname=f"plcvec.{family}", name=r.id)
            # The failure block of the summary (TEXT.md), without its status line and indent.
            detail = "\n".join(line[4:] for line in block(r, by_id.get(r.id), followed, defaults, expectations)[1:])
            if r.status == FAIL:
                ET.SubElement(case, "failure", message=f"{len(r.problems)} field(s) differ", type="mismatch").text = detail
            elif r.status == STALE:
                ET.SubElement(case, "failure", message="stale known failure", type="stale").text = detail
            elif r.status in (ERROR, NOT_RUN):
                ET.SubElement(case, "error", message=r.message[:200], type=r.status).text = detail
            elif r.status in (SKIP, XFAIL):
                ET.SubElement(case, "skipped", message=r.message[:200])
    ET.indent(root)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(root, encoding="unicode") + "\n"


def write_junit(report: Report, path) -> None:
    write_atomic(path, junit_xml(report))
