"""The CI recipes for implementers: the gate script the GitHub action and the GitLab template run.

The script is run as a CI job would run it, against the reference adapter and against a mutant of it
with one bug, from an empty folder; its exit code, reports and Markdown summary are checked against
the vector files and the JSON-lines report (never against the script's own summary text alone).
"""
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

import pytest
import yaml

from conftest import REPO

GATE = REPO / "verifiers" / "ci" / "gate.sh"
ACTION = REPO / "verifiers" / "ci" / "github" / "action.yml"
GITLAB = REPO / "verifiers" / "ci" / "gitlab" / "plcvec-gate.yml"
FAMILY = "fx5-time-add"
REFERENCE = f"{sys.executable} -m plcvec_reference.adapter"
MUTANT = "tadd-no-wrap-at-24"


def gate(tmp_path, **settings):
    """Run gate.sh in `tmp_path` with PLCVEC_* settings (the plcvec of this test run, no install)."""
    env = {k: v for k, v in os.environ.items() if not k.startswith(("PLCVEC_", "GITHUB_"))}
    env.update(PLCVEC_PYTHON=sys.executable, PLCVEC_PACKAGE="", PLCVEC_REPORT_DIR=str(tmp_path / "reports"))
    env.update({f"PLCVEC_{k.upper()}": v for k, v in settings.items() if k != "github_summary"})
    if "github_summary" in settings:
        env["GITHUB_STEP_SUMMARY"] = settings["github_summary"]
    return subprocess.run(["bash", str(GATE)], cwd=tmp_path, env=env, capture_output=True, text=True, timeout=600)


def family_ids():
    data = json.loads((REPO / "vectors" / f"{FAMILY}.json").read_text(encoding="utf-8"))
    return {v["id"] for v in data["vectors"]}


def read_jsonl(path):
    return [json.loads(line) for line in path.read_text(encoding="utf-8").splitlines()]


def test_reference_passes_with_reports_and_summary(tmp_path):
    proc = gate(tmp_path, adapter=REFERENCE, selection=f"--family {FAMILY}")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    reports = tmp_path / "reports"
    cases = ET.parse(reports / "junit.xml").getroot().iter("testcase")
    assert {c.get("name") for c in cases} == family_ids()
    lines = read_jsonl(reports / "results.jsonl")
    assert {x["id"] for x in lines if x["type"] == "vector"} == family_ids()
    assert lines[-1]["exit_code"] == 0
    summary = (reports / "summary.md").read_text(encoding="utf-8")   # no GITHUB_STEP_SUMMARY: beside the reports
    assert summary.startswith("## plcvec verify: passed")
    assert f"| {len(family_ids())} | 0 |" in summary        # pass, fail columns first
    assert "Failing vectors" not in summary


def test_a_mutant_fails_and_the_summary_tables_its_field_diffs(tmp_path):
    github_summary = tmp_path / "step-summary.md"
    github_summary.write_text("earlier step\n", encoding="utf-8")
    proc = gate(tmp_path, adapter=f"{REFERENCE} --mutant {MUTANT}", selection=f"--family {FAMILY}",
                github_summary=str(github_summary))
    assert proc.returncode == 1, proc.stdout + proc.stderr
    lines = read_jsonl(tmp_path / "reports" / "results.jsonl")
    failed = [x for x in lines if x["type"] == "vector" and x["status"] == "fail"]
    assert failed and lines[-1]["exit_code"] == 1
    junit = ET.parse(tmp_path / "reports" / "junit.xml").getroot()
    assert int(junit.get("failures")) == len(failed)
    text = github_summary.read_text(encoding="utf-8")
    assert text.startswith("earlier step\n")                  # appended, as GitHub expects
    assert "## plcvec verify: FAILED" in text
    assert f"### Failing vectors ({len(failed)})" in text
    assert "| vector | status | step | field | expected | got |" in text
    first = failed[0]
    p = first["problems"][0]
    row = (f"| `{first['id']}` | fail | {p['step']} | `{p['field']}` | `{json.dumps(p['expected'])}` | "
           f"`{json.dumps(p['actual'])}` |")
    assert row in text
    assert not (tmp_path / "reports" / "summary.md").exists()


def test_known_failures_and_alternatives_are_passed_on(tmp_path):
    first = tmp_path / "first"
    first.mkdir()
    proc = gate(first, adapter=f"{REFERENCE} --mutant {MUTANT}", selection=f"--family {FAMILY}")
    failed = sorted(x["id"] for x in read_jsonl(first / "reports" / "results.jsonl")
                    if x["type"] == "vector" and x["status"] == "fail")
    known = tmp_path / "known.toml"
    known.write_text("".join(f'[[known-failure]]\nid = "{vid}"\nreason = "the mutant\'s bug"\n\n' for vid in failed),
                     encoding="utf-8")
    proc = gate(tmp_path, adapter=f"{REFERENCE} --mutant {MUTANT}", selection=f"--family {FAMILY}",
                expectations=str(known), alternatives="TADD-FLAGS-OFF=written-each-execution")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert "--choose TADD-FLAGS-OFF=written-each-execution" in proc.stdout
    counts = read_jsonl(tmp_path / "reports" / "results.jsonl")[-1]["counts"]
    assert counts["xfail"] == len(failed) and counts["fail"] == 0


def test_no_adapter_or_a_bad_selection_is_an_error(tmp_path):
    proc = gate(tmp_path, adapter="")
    assert proc.returncode == 2 and "PLCVEC_ADAPTER" in proc.stderr
    proc = gate(tmp_path, adapter=REFERENCE, selection="--family no-such-family")
    assert proc.returncode == 2, proc.stdout + proc.stderr
    summary = (tmp_path / "reports" / "summary.md").read_text(encoding="utf-8")
    assert summary.startswith("## plcvec verify: could not run"), summary


def test_the_action_runs_the_gate_with_every_input():
    action = yaml.safe_load(ACTION.read_text(encoding="utf-8"))
    assert action["runs"]["using"] == "composite"
    inputs = set(action["inputs"])
    assert {"adapter", "selection", "expectations", "alternatives"} <= inputs
    assert action["inputs"]["adapter"]["required"] is True
    gate_step, upload = action["runs"]["steps"]
    assert "gate.sh" in gate_step["run"]
    for name in ("adapter", "selection", "expectations", "alternatives", "package", "report-dir"):
        assert f"inputs.{name}" in " ".join(gate_step["env"].values()), name
    assert upload["uses"].startswith("actions/upload-artifact@") and upload["if"] == "always()"


def test_the_gitlab_template_runs_the_gate_and_keeps_the_reports():
    job = yaml.safe_load(GITLAB.read_text(encoding="utf-8"))[".plcvec-gate"]
    assert {"PLCVEC_ADAPTER", "PLCVEC_SELECTION", "PLCVEC_EXPECTATIONS", "PLCVEC_ALTERNATIVES"} <= set(job["variables"])
    assert any("plcvec-gate.sh" in line for line in job["script"])
    assert job["artifacts"]["when"] == "always"
    assert job["artifacts"]["reports"]["junit"] == "plcvec-reports/junit.xml"


@pytest.mark.parametrize("path", [GATE])
def test_the_script_is_valid_bash(path):
    assert subprocess.run(["bash", "-n", str(path)], capture_output=True, timeout=60).returncode == 0
