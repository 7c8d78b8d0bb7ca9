"""The CI recipes for implementers: the gate script the GitHub action and the GitLab template run.

The script is run as a CI job would run it, against the reference adapter and against a mutant of it
with one bug, from an empty folder; its exit code, reports and Markdown summary are checked against
the vector files and the JSON-lines report (never against the script's own summary text alone).
"""
import hashlib
import importlib.util
import json
import os
import re
import shlex
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
import yaml

from conftest import REPO

GATE = REPO / "verifiers" / "ci" / "gate.sh"
ACTION = REPO / "action.yml"
OLD_ACTION = REPO / "verifiers" / "ci" / "github" / "action.yml"
GITLAB = REPO / "verifiers" / "ci" / "gitlab" / "plcvec-gate.yml"
FAMILY = "fx5-time-add"
REFERENCE = f"{shlex.quote(sys.executable)} -m plcvec_reference.adapter"
MUTANT = "tadd-no-wrap-at-24"


def gate(tmp_path, extra=None, **settings):
    """Run gate.sh in `tmp_path` with PLCVEC_* settings (the plcvec of this test run, no install) and
    `extra` variables (a CI system's own)."""
    tmp_path.mkdir(parents=True, exist_ok=True)
    env = {k: v for k, v in os.environ.items() if not k.startswith(("PLCVEC_", "GITHUB_", "CI_NODE_"))}
    env.update(extra or {})
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
                known_failures=str(known), alternatives="TADD-FLAGS-OFF=written-each-execution")
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
    assert {"PLCVEC_ADAPTER", "PLCVEC_SELECTION", "PLCVEC_KNOWN_FAILURES", "PLCVEC_ALTERNATIVES"} <= set(job["variables"])
    assert any("plcvec-gate.sh" in line for line in job["script"])
    assert job["artifacts"]["when"] == "always"
    assert job["artifacts"]["reports"]["junit"] == "plcvec-reports/junit.xml"


@pytest.mark.parametrize("path", [GATE])
def test_the_script_is_valid_bash(path):
    assert subprocess.run(["bash", "-n", str(path)], capture_output=True, timeout=60).returncode == 0


def _header_example(path):
    """The usage example in a recipe's comment header, as YAML (the lines indented under `#`)."""
    lines = []
    for line in path.read_text(encoding="utf-8").splitlines():
        if line == "---":          # yamllint's document start
            continue
        if not line.startswith("#"):
            break
        if line.startswith("#   "):
            lines.append(line[4:].split("  #", 1)[0].rstrip())
    return yaml.safe_load("\n".join(lines))


def _known_alternatives():
    known = {}
    for path in (REPO / "vectors").glob("*.json"):
        if path.name != "manifest.json":
            for i in json.loads(path.read_text(encoding="utf-8"))["interpretations"]:
                known[i["id"]] = {a["id"] for a in i["alternatives"]}
    return known


def _example_settings():
    """(where, selection, alternatives, home URLs) of each recipe header's example and README block."""
    action = _header_example(ACTION)
    step = next(s for s in action if "uses" in s and "plcvec/plcvec" in s["uses"])
    yield ("action.yml", step["with"]["selection"], step["with"]["alternatives"], [step["uses"]])
    old = _header_example(OLD_ACTION)
    step = next(s for s in old if "uses" in s and "verifiers/ci/github" in s["uses"])
    yield ("verifiers/ci/github/action.yml", step["with"]["selection"], step["with"]["alternatives"], [step["uses"]])
    gitlab = _header_example(GITLAB)
    v = gitlab["plcvec"]["variables"]
    yield ("plcvec-gate.yml", v["PLCVEC_SELECTION"], v["PLCVEC_ALTERNATIVES"], [gitlab["include"][0]["remote"]])
    # The README's two jobs, as .ci/readme_snippets.py extracts them for CI.
    spec = importlib.util.spec_from_file_location("readme_snippets", REPO / ".ci" / "readme_snippets.py")
    snippets = importlib.util.module_from_spec(spec)
    sys.modules.setdefault("readme_snippets", snippets)   # dataclasses look their module up there
    spec.loader.exec_module(snippets)
    blocks = {b.arg: b.text for b in snippets.blocks(REPO / "README.md")[0] if b.kind == "snippet"}
    github = yaml.safe_load(blocks["readme/github-job.yml"])
    step = next(s for s in github["jobs"]["plcvec"]["steps"] if s.get("uses", "").startswith("plcvec/plcvec"))
    yield ("README github", step["with"]["selection"], step["with"]["alternatives"], [step["uses"]])
    job = yaml.safe_load(blocks["readme/gitlab-job.yml"])
    v = job["plcvec"]["variables"]
    yield ("README gitlab", v["PLCVEC_SELECTION"], v.get("PLCVEC_ALTERNATIVES", ""), [job["include"][0]["remote"]])


@pytest.mark.parametrize("where,selection,alternatives,urls", list(_example_settings()), ids=lambda x: str(x)[:20])
def test_the_recipe_examples_give_settings_plcvec_verify_accepts(where, selection, alternatives, urls, tmp_path):
    known = _known_alternatives()
    for choice in alternatives.split():
        interp, _, alt = choice.partition("=")
        assert interp in known and alt in known[interp], f"{where}: {choice} is not an interpretation alternative"
    # The selection is accepted (no usage error) and selects something.
    proc = subprocess.run([sys.executable, "-m", "plcvec", "verify", "--adapter", REFERENCE, "-q", *selection.split()],
                          capture_output=True, text=True, cwd=tmp_path, timeout=600)
    assert proc.returncode == 0, f"{where}: {selection}: {proc.stderr}"
    # Every URL is the project's home (pyproject.toml [tool.plcvec]) at a release tag of this version.
    from plcvec import __version__
    for url in urls:
        assert "OWNER" not in url and "HOST" not in url
        assert "plcvec/plcvec" in url and f"v{__version__}" in url, url


def test_the_gitlab_default_gate_script_is_fetched_not_copied_from_a_checkout():
    job = yaml.safe_load(GITLAB.read_text(encoding="utf-8"))[".plcvec-gate"]
    from plcvec import __version__
    url = job["variables"]["PLCVEC_GATE_SCRIPT"]
    assert url.startswith("https://") and url.endswith(f"/v{__version__}/verifiers/ci/gate.sh")
    # The image can build an implementation (the slim image has no make).
    assert "slim" not in job["image"]


def test_settings_left_empty_as_the_templates_default_them_mean_not_given(tmp_path):
    """The GitLab template gives every setting an empty default; plcvec verify refuses an empty
    PLCVEC_* variable, so the gate must pass on none of them."""
    proc = gate(tmp_path, adapter=REFERENCE, selection=f"--family {FAMILY}", known_failures="", alternatives="",
                timeout="", id="")
    assert proc.returncode == 0, proc.stdout + proc.stderr



def test_the_root_action_is_the_old_paths_action_with_branding():
    """The Marketplace lists only a root action.yml; 0.1.0's path stays the same action until 0.3.0."""
    root, old = (yaml.safe_load(p.read_text(encoding="utf-8")) for p in (ACTION, OLD_ACTION))
    assert root["branding"]["icon"] and root["branding"]["color"]
    assert root["inputs"] == old["inputs"] and root["outputs"] == old["outputs"]
    assert root["runs"]["steps"][1] == old["runs"]["steps"][1]
    assert "$GITHUB_ACTION_PATH/verifiers/ci/gate.sh" in root["runs"]["steps"][0]["run"]
    assert "$GITHUB_ACTION_PATH/../gate.sh" in old["runs"]["steps"][0]["run"]


def test_the_gitlab_template_pins_the_gate_script_by_its_sha256(tmp_path):
    job = yaml.safe_load(GITLAB.read_text(encoding="utf-8"))[".plcvec-gate"]
    assert job["variables"]["PLCVEC_GATE_SHA256"] == hashlib.sha256(GATE.read_bytes()).hexdigest()
    # The template's own download step, from a local HTTP server: the pinned script is written, another
    # is refused.
    import functools
    import http.server
    import threading

    handler = functools.partial(http.server.SimpleHTTPRequestHandler, directory=str(GATE.parent))
    handler.log_message = lambda *a: None
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    url = f"http://127.0.0.1:{server.server_address[1]}/{GATE.name}"
    script = job["script"][0]
    env = dict(os.environ, PLCVEC_GATE_SCRIPT=url, PLCVEC_GATE_SHA256=job["variables"]["PLCVEC_GATE_SHA256"])
    out = Path("/tmp/plcvec-gate.sh")
    out.unlink(missing_ok=True)
    proc = subprocess.run(["bash", "-c", script], env=env, capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    assert out.read_bytes() == GATE.read_bytes()
    out.unlink()
    proc = subprocess.run(["bash", "-c", script], env={**env, "PLCVEC_GATE_SHA256": "0" * 64},
                          capture_output=True, text=True, timeout=60)
    server.shutdown()
    assert proc.returncode != 0 and "has sha256" in proc.stderr and not out.exists()


def test_a_parallel_gitlab_job_runs_its_shard(tmp_path):
    whole = gate(tmp_path / "whole", adapter=REFERENCE, selection="--family fx5-time-add")
    counts = []
    for index in (1, 2):
        proc = gate(tmp_path / f"node{index}", adapter=REFERENCE, selection="--family fx5-time-add",
                    extra={"CI_NODE_INDEX": str(index), "CI_NODE_TOTAL": "2"})
        assert proc.returncode == 0, proc.stdout + proc.stderr
        assert f"--shard {index}/2" in proc.stdout
        counts.append(int(re.search(r"^(\d+) vectors:", proc.stdout, re.M).group(1)))
    total = int(re.search(r"^(\d+) vectors:", whole.stdout, re.M).group(1))
    assert sum(counts) == total and all(counts)
