"""A Markdown summary of a `plcvec verify` run, made from its JSON-lines report (`--jsonl`).

    python3 -m plcvec_verify.summary results.jsonl >> "$GITHUB_STEP_SUMMARY"

What a CI job page shows: the verdict, what the run was made against (suite version, spec hash,
adapter, interpretations), the counts, and every failing vector as rows of a table, one per field
that differs (step, field, expected, got). The CI recipes under verifiers/ci/ use it.
"""
from __future__ import annotations

import argparse
import json
import sys

MAX_VECTORS = 50      # failing vectors shown in full; a job summary has a size limit (1 MiB on GitHub)
MAX_FIELDS = 8        # field rows per vector
FAILING = ("fail", "error", "stale", "not-run")


def read_report(path) -> tuple[dict, list[dict], dict]:
    """(run header, vector records, summary record) of a JSON-lines report."""
    run, vectors, summary = {}, [], {}
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            if not line.strip():
                continue
            try:
                item = json.loads(line)
            except json.JSONDecodeError as exc:
                raise ValueError(f"{path}:{number}: not a JSON line ({exc.msg})") from None
            kind = item.get("type")
            if kind == "run":
                run = item
            elif kind == "vector":
                vectors.append(item)
            elif kind == "summary":
                summary = item
    if not run or not summary:
        raise ValueError(f"{path}: not a complete plcvec verify report (no run or summary line)")
    return run, vectors, summary


def _cell(value) -> str:
    text = value if isinstance(value, str) else json.dumps(value)
    return text.replace("\\", "\\\\").replace("|", "\\|").replace("\n", " ")


def markdown(run: dict, vectors: list[dict], summary: dict, title: str = "plcvec verify") -> str:
    counts = summary.get("counts", {})
    code = summary.get("exit_code")
    verdict = {0: "passed", 1: "FAILED", 5: "nothing tested"}.get(code, "could not run")
    if code == 0 and not counts.get("pass", 0) + counts.get("xfail", 0):
        verdict = "could not run (no vector was run and passed)"   # an empty gate never passes
    adapter = run.get("adapter", {})
    name = adapter.get("name", "?") + (f" {adapter['version']}" if adapter.get("version") else "")
    lines = [f"## {title}: {verdict}", ""]
    lines.append(f"{name} against plcvec suite {run.get('suite_version') or '?'} (schema {run.get('schema_version') or '?'}, "
                 f"spec sha256 `{(run.get('spec_sha256') or '?')[:12]}`)")
    declared = [f"`{i}={d['alternative']}`" for i, d in sorted(run.get("interpretations", {}).items()) if d.get("declared")]
    lines.append("")
    lines.append("Interpretations: " + (", ".join(declared) + "; " if declared else "") + "others at their default.")
    if run.get("selection"):
        lines.append("")
        lines.append("Selection: " + "; ".join(f"{k} {', '.join(map(str, v)) if isinstance(v, list) else v}"
                                               for k, v in sorted(run["selection"].items())))
    lines += ["", "| " + " | ".join(counts) + " |", "|" + "---|" * len(counts),
              "| " + " | ".join(str(n) for n in counts.values()) + " |", ""]
    if summary.get("aborted"):
        lines += [f"**Aborted:** {_cell(summary['aborted'])}", ""]
    failing = [v for v in vectors if v.get("status") in FAILING]
    if failing:
        lines += [f"### Failing vectors ({len(failing)})", "", "| vector | status | step | field | expected | got |",
                  "|---|---|---|---|---|---|"]
        for v in failing[:MAX_VECTORS]:
            problems = v.get("problems") or []
            vid = f"`{_cell(v['id'])}`"
            if not problems:
                lines.append(f"| {vid} | {v['status']} | | | | {_cell(v.get('message', ''))} |")
            for p in problems[:MAX_FIELDS]:
                step = "" if p.get("step") is None else p["step"]
                lines.append(f"| {vid} | {v['status']} | {step} | `{_cell(p['field'])}` | "
                             f"`{_cell(p['expected'])}` | `{_cell(p['actual'])}` |")
            if len(problems) > MAX_FIELDS:
                lines.append(f"| {vid} | | | … {len(problems) - MAX_FIELDS} more fields | | |")
        if len(failing) > MAX_VECTORS:
            lines += ["", f"… and {len(failing) - MAX_VECTORS} more failing vectors: see the JUnit and JSON-lines reports."]
        lines.append("")
    return "\n".join(lines) + "\n"


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python3 -m plcvec_verify.summary", description=__doc__.split("\n")[0])
    p.add_argument("report", help="the JSON-lines report of plcvec verify --jsonl")
    p.add_argument("--title", default="plcvec verify", help="the heading (default: %(default)s)")
    args = p.parse_args(argv)
    try:
        sys.stdout.write(markdown(*read_report(args.report), title=args.title))
    except (OSError, ValueError) as exc:
        print(f"plcvec_verify.summary: {exc}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
