"""The Python verifier: comparison, selection, interpretations, expectations file, reports, CLI.

The implementation under test here is a small adapter that answers from the vector file itself
(what a perfect implementation would say), with one deliberate change per test; so every expected
verdict follows from the change, not from the verifier's own output.
"""
import copy
import json
import subprocess
import sys
import xml.etree.ElementTree as ET

import pytest

from plcvec_verify import InProcess, KnownFailures, Selection, StdioAdapter, Suite, VerifyError, run
from plcvec_verify.command import main as verify_main
from plcvec_verify.reports import jsonl_lines, junit_xml, summary_text
from plcvec_reference.adapter import ReferenceAdapter

from conftest import REPO


@pytest.fixture(scope="module")
def suite():
    return Suite.load(REPO / "vectors")


class Oracle:
    """Answers every vector with the full state its own expectations describe (defaults)."""

    def __init__(self, suite, edit=None, instructions=None, interpretations=None):
        self.suite, self.edit = suite, edit or {}
        self.instructions, self.interpretations = instructions, interpretations or {}

    def hello(self, request):
        every = sorted({i for f in request["families"].values() for i in f["instructions"]})
        return {"adapter": {"name": "oracle"}, "instructions": self.instructions or every,
                "interpretations": self.interpretations}

    def run(self, request):
        v = self.suite.by_id[request["id"]]
        state = dict(v["initial"]["devices"])
        steps = []
        for step in v["steps"]:
            state.update(step.get("set", {}))
            state.update(step["expect"].get("devices", {}))
            out = {"devices": dict(state)}
            if "result" in step["expect"]:
                out["result"] = step["expect"]["result"]
            steps.append(out)
        answer = {"steps": steps}
        if request["id"] in self.edit:
            answer = self.edit[request["id"]](copy.deepcopy(answer))
        return answer


def first(suite, pred):
    return next(v for v in suite.vectors if pred(v))


def test_an_implementation_that_answers_the_expectations_passes(suite):
    report = run(suite, InProcess(Oracle(suite)))
    assert report.counts["pass"] == len(suite.vectors) and report.exit_code == 0


def test_wrong_result_is_reported_with_the_field(suite):
    v = first(suite, lambda v: v["family"] == "fx5-date-compare" and "result" in v["steps"][0]["expect"])
    want = v["steps"][0]["expect"]["result"]

    def flip(a):
        a["steps"][0]["result"] = not want
        return a
    report = run(suite, InProcess(Oracle(suite, {v["id"]: flip})))
    assert [r.id for r in report.failed] == [v["id"]] and report.exit_code == 1
    (problem,) = report.failed[0].problems
    assert (problem.step, problem.field, problem.expected, problem.actual) == (0, "result", want, not want)
    text = summary_text(report)
    show = {True: "true", False: "false"}
    assert f"FAIL {v['id']}\n" in text
    assert f"step 0 result: expected {show[want]}, got {show[not want]}" in text
    assert "spec clauses: " + ", ".join(v["clauses"]) in text


def test_progress_bar_only_on_a_terminal(suite):
    import io

    from plcvec_verify.progress import Progress

    class Terminal(io.StringIO):
        def isatty(self):
            return True
    assert Progress.for_stream(io.StringIO()) is None
    screen = Terminal()
    bar = Progress.for_stream(screen)
    run(suite, InProcess(Oracle(suite)), Selection(families=("fx5-time-add",)), progress=bar)
    n = len(Selection(families=("fx5-time-add",)).apply(suite.vectors))
    assert f"{n}/{n} vectors, 0 failing" in screen.getvalue()


def test_a_bit_reported_as_an_integer_fails_though_python_says_1_equals_true(suite):
    v = first(suite, lambda v: v["initial"]["devices"].get("SM709") is False)

    def as_int(a):
        a["steps"][-1]["devices"]["SM709"] = int(a["steps"][-1]["devices"]["SM709"])
        return a
    report = run(suite, InProcess(Oracle(suite, {v["id"]: as_int})))
    assert [r.id for r in report.failed] == [v["id"]]
    assert report.failed[0].problems[0].field == "SM709"


def test_writing_a_device_the_vector_does_not_list_fails(suite):
    v = suite.vectors[0]

    def extra(a):
        a["steps"][0]["devices"]["D7000"] = 1
        return a
    report = run(suite, InProcess(Oracle(suite, {v["id"]: extra})))
    (problem,) = report.failed[0].problems
    assert problem.field == "D7000" and problem.expected == "<not in the vector>"


def test_a_device_left_unchanged_that_must_change(suite):
    v = first(suite, lambda v: v["family"] == "fx5-time-add" and v["steps"][0]["expect"]["devices"])
    dev, new = sorted(v["steps"][0]["expect"]["devices"].items())[0]
    old = v["initial"]["devices"][dev]

    def keep(a):
        a["steps"][0]["devices"][dev] = old
        a["steps"][-1]["devices"][dev] = old if len(a["steps"]) == 1 else a["steps"][-1]["devices"][dev]
        return a
    report = run(suite, InProcess(Oracle(suite, {v["id"]: keep})))
    problem = report.failed[0].problems[0]
    assert (problem.field, problem.expected, problem.actual, problem.before) == (dev, new, old, old)
    assert f"got {old!r} (before the step: {old!r})" in problem.line()


def test_the_expectation_follows_the_declared_alternative(suite):
    """A vector touched by an interpretation is judged by the alternative the adapter declares."""
    v = first(suite, lambda v: "TADD-EXACT-24" in v["outcome"].get("interpretations", ()) and v["alternatives"])
    alt = next(a for a in v["alternatives"] if a["choices"] == {"TADD-EXACT-24": "carry-above-24"})
    # The reference follows carry-above-24 on request; judged by the default it must fail there.
    ref = ReferenceAdapter(choices={"TADD-EXACT-24": "carry-above-24"})

    class Undeclared(ReferenceAdapter):
        def hello(self, request):
            h = super().hello(request)
            h["interpretations"] = {}
            return h
    undeclared = Undeclared(choices={"TADD-EXACT-24": "carry-above-24"})
    sel = Selection(ids=(v["id"],))
    assert run(suite, InProcess(ref), sel).exit_code == 0
    failed = run(suite, InProcess(undeclared), sel)
    assert [r.id for r in failed.failed] == [v["id"]]
    passed = run(suite, InProcess(undeclared), sel, choose={"TADD-EXACT-24": "carry-above-24"})
    assert passed.exit_code == 0 and passed.results[0].choices == alt["choices"]


def test_unknown_interpretation_or_alternative_is_a_usage_error(suite):
    with pytest.raises(VerifyError, match="NO-SUCH"):
        run(suite, InProcess(Oracle(suite, interpretations={"NO-SUCH": "x"})))
    with pytest.raises(VerifyError, match="has the alternatives"):
        run(suite, InProcess(Oracle(suite, interpretations={"TADD-EXACT-24": "never"})))


def test_unsupported_instructions_are_skipped_not_sent(suite):
    seen = []

    class Only(Oracle):
        def run(self, request):
            seen.append(request["instruction"])
            return super().run(request)
    report = run(suite, InProcess(Only(suite, instructions=["TADD"])))
    tadd = sum(v["instruction"] == "TADD" for v in suite.vectors)
    assert set(seen) == {"TADD"} and report.counts["pass"] == tadd
    assert report.counts["skip"] == len(suite.vectors) - tadd and report.exit_code == 0


def test_requests_carry_no_expectation(suite):
    seen = []

    class Spy(Oracle):
        def run(self, request):
            seen.append(request)
            return super().run(request)
    run(suite, InProcess(Spy(suite)), Selection(families=("fc6a-hour-meter",)))
    text = json.dumps(seen)
    assert seen and '"expect"' not in text and '"final"' not in text and '"alternatives"' not in text


def test_selection_filters(suite):
    by = lambda **kw: {v["id"] for v in Selection(**kw).apply(suite.vectors)}  # noqa: E731
    assert by(instructions=("TADDP",)) == {v["id"] for v in suite.vectors if v["instruction"] == "TADDP"}
    assert by(tags=("nonexistent-date",)) == {v["id"] for v in suite.vectors if "nonexistent-date" in v["tags"]}
    assert by(ids=("fx5-time-add/TADD/*",)) == {v["id"] for v in suite.vectors if v["id"].startswith("fx5-time-add/TADD/")}
    assert by(interpretations=("HOUR-INPUT-OFF",)) == {
        v["id"] for v in suite.vectors if "HOUR-INPUT-OFF" in v["outcome"].get("interpretations", ())}
    both = by(families=("fx5-time-add",), tags=("boundary",))
    assert both and all(suite.by_id[i]["family"] == "fx5-time-add" and "boundary" in suite.by_id[i]["tags"] for i in both)


def test_shards_partition_the_suite(suite):
    shards = [Selection(shard=(k, 4)).apply(suite.vectors) for k in range(1, 5)]
    ids = [v["id"] for s in shards for v in s]
    assert sorted(ids) == sorted(v["id"] for v in suite.vectors)   # each vector in exactly one shard
    assert all(len(s) > len(suite.vectors) / 8 for s in shards)      # and none is starved
    # By a hash of the id alone: a vector's shard does not move when the suite grows.
    grown = Selection(shard=(1, 4)).apply(suite.vectors + [dict(suite.vectors[0], id="new/vector")])
    assert [v["id"] for v in grown if v["id"] != "new/vector"] == [v["id"] for v in shards[0]]


def test_expectations_file_known_failure_and_stale(suite, tmp_path):
    bad, good = suite.vectors[0], suite.vectors[1]

    def flip(a):
        for s in a["steps"]:
            for k, val in s["devices"].items():
                if isinstance(val, bool):
                    s["devices"][k] = not val
                    return a
            s["devices"]["D7001"] = 1
        return a
    path = tmp_path / "known.toml"
    path.write_text(f'[[known-failure]]\nid = "{bad["id"]}"\nreason = "tracked as #1"\n\n'
                    f'[[known-failure]]\nid = "{good["id"]}"\nreason = "fixed since"\n\n'
                    '[[known-failure]]\nid = "gone/vector"\nreason = "removed from the suite"\n')
    report = run(suite, InProcess(Oracle(suite, {bad["id"]: flip})), known=KnownFailures.load(path))
    status = {r.id: r.status for r in report.results}
    assert status[bad["id"]] == "xfail" and status[good["id"]] == "stale" and status["gone/vector"] == "stale"
    assert report.exit_code == 1
    stale = next(r for r in report.results if r.id == good["id"])
    assert f"{path}:5" in stale.message


@pytest.mark.parametrize("text, message", [
    ('[[known-failure]]\nid = "x"\n', ":1: x: every known failure needs a `reason`"),
    ('[[known-failure]]\nid = "x"\nreason = "a"\n[[known-failure]]\nid = "x"\nreason = "b"\n', ":4: x is listed twice"),
    ('[[known-failure]]\nid = "x"\nreason = "a"\nowner = "me"\n', ":1: unknown key 'owner'"),
    ('[[known-failure]\n', ":1: not valid TOML"),
])
def test_bad_expectations_file_names_file_and_line(tmp_path, text, message):
    path = tmp_path / "known.toml"
    path.write_text(text)
    with pytest.raises(VerifyError, match=None) as e:
        KnownFailures.load(path)
    assert str(path) in str(e.value) and message in str(e.value)


def test_reports_record_versions_and_interpretations(suite):
    v = suite.vectors[3]
    report = run(suite, InProcess(Oracle(suite, {v["id"]: lambda a: {"error": "clock not configured"}},
                                         interpretations={"TADD-EXACT-24": "carry-at-24"})))
    lines = list(jsonl_lines(report))
    head, tail = lines[0], lines[-1]
    assert head["spec_sha256"] == json.loads((REPO / "vectors" / "manifest.json").read_text())["spec_sha256"]
    assert head["suite_version"] and head["schema_version"].startswith("1.")
    assert head["interpretations"]["TADD-EXACT-24"] == {"alternative": "carry-at-24", "declared": True}
    assert head["interpretations"]["HOUR-INPUT-OFF"]["declared"] is False
    errored = [x for x in lines if x.get("status") == "error"]
    assert [x["id"] for x in errored] == [v["id"]] and "clock not configured" in errored[0]["message"]
    assert tail["counts"]["error"] == 1 and tail["exit_code"] == 1
    root = ET.fromstring(junit_xml(report))
    assert int(root.get("tests")) == len(suite.vectors) and root.get("errors") == "1"
    case = root.find(f".//testcase[@name='{v['id']}']")
    assert case.find("error") is not None and "clock not configured" in case.find("error").text
    props = {p.get("name"): p.get("value") for p in root.iter("property")}
    assert props["interpretation.TADD-EXACT-24"] == "carry-at-24" and props["spec_sha256"] == head["spec_sha256"]
    text = summary_text(report)
    assert f"ERROR {v['id']}" in text and "spec clauses: " in text and "1 error" in text


def test_cli_exit_codes_and_reports(tmp_path):
    assert verify_main(["--python", "plcvec_reference.adapter:ReferenceAdapter", "-q"]) == 0
    jsonl, junit = tmp_path / "r.jsonl", tmp_path / "r.xml"
    rc = verify_main(["--adapter", f"{sys.executable} -m plcvec_reference.adapter --choose TADD-EXACT-24=carry-above-24",
                      "--family", "fx5-time-add", "--interpretation", "TADD-EXACT-24", "--jsonl", str(jsonl),
                      "--junit", str(junit), "-q"])
    assert rc == 0 and jsonl.exists() and ET.parse(junit).getroot().get("failures") == "0"


@pytest.mark.parametrize("args, message", [
    (["--python", "no_such_module:Adapter"], "cannot import no_such_module"),
    (["--python", "plcvec_reference.adapter"], "MODULE:CLASS"),
    (["--adapter", "/no/such/adapter"], "cannot start it"),
    (["--python", "plcvec_reference.adapter:ReferenceAdapter", "--vectors", "/no/such/dir"], "/no/such/dir: no such"),
    (["--python", "plcvec_reference.adapter:ReferenceAdapter", "--shard", "5/4"], "--shard 5/4"),
    (["--python", "plcvec_reference.adapter:ReferenceAdapter", "--choose", "TADD-EXACT-24"], "INTERPRETATION=ALTERNATIVE"),
    (["--python", "plcvec_reference.adapter:ReferenceAdapter", "--expectations", "/no/such.toml"], "/no/such.toml"),
])
def test_cli_usage_errors_exit_2_without_traceback(args, message):
    proc = subprocess.run([sys.executable, "-m", "plcvec", "verify", *args], capture_output=True, text=True, timeout=120)
    assert proc.returncode == 2, proc.stderr
    assert message in proc.stderr and "Traceback" not in proc.stderr


def test_a_newer_major_schema_is_refused(tmp_path):
    data = json.loads((REPO / "vectors" / "fx5-time-add.json").read_text())
    data["schema_version"] = "2.0.0"
    path = tmp_path / "fx5-time-add.json"
    path.write_text(json.dumps(data))
    with pytest.raises(VerifyError, match="schema_version 2.0.0 is not 1.x"):
        Suite.load(path)


def test_an_inconsistent_vector_file_is_caught_not_trusted(suite, tmp_path):
    data = json.loads((REPO / "vectors" / "fx5-time-add.json").read_text())
    v = data["vectors"][0]
    dev = next(iter(v["final"]["devices"]))
    v["final"]["devices"][dev] = 12345 if v["final"]["devices"][dev] != 12345 else 1
    path = tmp_path / "f.json"
    path.write_text(json.dumps(data))
    with pytest.raises(VerifyError, match=f"vector {v['id']}.*do not add up"):
        run(Suite.load(path), InProcess(ReferenceAdapter()))


def test_in_process_and_stdio_give_the_same_verdicts(suite):
    mutated = ReferenceAdapter(choices={"HOUR-INPUT-OFF": "reset"})

    class Undeclared(ReferenceAdapter):
        def hello(self, request):
            return dict(super().hello(request), interpretations={})
    sel = Selection(families=("fc6a-hour-meter",))
    inproc = run(suite, InProcess(Undeclared(choices={"HOUR-INPUT-OFF": "reset"})), sel)
    assert inproc.failed, "judged by the default, the reset alternative must fail somewhere"
    proc = run(suite, StdioAdapter([sys.executable, "-m", "plcvec_reference.adapter", "--choose", "HOUR-INPUT-OFF=reset"]), sel)
    assert proc.exit_code == 0 and run(suite, InProcess(mutated), sel).exit_code == 0


@pytest.mark.parametrize("damage, message", [
    (lambda v: v.pop("id"), "vector #0: no `id`"),
    (lambda v: v.pop("final"), "no `final`"),
    (lambda v: v["steps"][0].pop("expect"), "every step needs an `expect`"),
    (lambda v: v.update(family="fx5-time-compare"), "family 'fx5-time-compare' in a 'fx5-time-add' file"),
])
def test_a_damaged_vector_file_is_named_not_a_traceback(tmp_path, damage, message):
    data = json.loads((REPO / "vectors" / "fx5-time-add.json").read_text())
    damage(data["vectors"][0])
    path = tmp_path / "fx5-time-add.json"
    path.write_text(json.dumps(data))
    proc = subprocess.run([sys.executable, "-m", "plcvec", "verify", "--python",
                           "plcvec_reference.adapter:ReferenceAdapter", "--vectors", str(path)],
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 2 and message in proc.stderr and str(path) in proc.stderr
    assert "Traceback" not in proc.stderr


def test_the_package_gives_every_public_name_from_its_module():
    """plcvec_verify imports its names when first used; each is the object of the module it lives in,
    `from plcvec_verify import *` gives them all (the deprecated old names with their warning:
    test_renamed.py), and an unknown name is an AttributeError."""
    import importlib

    import plcvec_verify

    for name in set(plcvec_verify.__all__) - set(plcvec_verify.RENAMED):
        module = importlib.import_module(f"plcvec_verify.{plcvec_verify._WHERE[name]}")
        assert getattr(plcvec_verify, name) is getattr(module, name), name
    space = {}
    with pytest.warns(DeprecationWarning):
        exec("from plcvec_verify import *", space)
    assert set(plcvec_verify.__all__) <= set(space)
    with pytest.raises(AttributeError, match="no_such_name"):
        plcvec_verify.no_such_name


def test_python_module_in_the_current_folder_is_found_and_a_failed_import_says_the_forms(tmp_path):
    """`plcvec verify --python plcvec_adapter:SoftPLCAdapter` run from the module's own folder, as a user
    runs it (the installed command's folder, not the current one, is on its path)."""
    (tmp_path / "plcvec_adapter.py").write_text(
        "from plcvec_reference.adapter import ReferenceAdapter as SoftPLCAdapter\n", encoding="utf-8")
    cmd = [sys.executable, "-c", "import sys; sys.path.pop(0); from plcvec.cli import main; sys.exit(main())",
           "verify", "--family", "fx5-time-add", "-q"]
    proc = subprocess.run([*cmd, "--python", "plcvec_adapter:SoftPLCAdapter"], cwd=tmp_path, capture_output=True,
                          text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    proc = subprocess.run([*cmd, "--python", "no_such_adapter:X"], cwd=tmp_path, capture_output=True, text=True,
                          timeout=300)
    assert proc.returncode == 2 and "Traceback" not in proc.stderr
    assert "the forms are MODULE:CLASS" in proc.stderr and "path/to/file.py:CLASS" in proc.stderr
