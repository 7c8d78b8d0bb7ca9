"""`plcvec diff OLD NEW`: two vector sets compared by vector id, as a reviewer of a spec change runs it."""
import io
import json
import shutil
import subprocess
import sys
import tarfile
from pathlib import Path

import pytest

from plcvec.cli import main

REPO = Path(__file__).resolve().parents[1]
TA = "fx5-time-add"
TA_COUNT = json.loads((REPO / "vectors" / f"{TA}.json").read_text())["count"]
EX1 = f"{TA}/TADD/manual-example/ex1"
OVER24 = f"{TA}/TADD/manual-example/over24"
PROGRAM = f"{TA}/TADD/manual-example/program"
CARRY = f"{TA}/TADD/manual-example/carry"
NEW_ID = f"{TA}/TADD/manual-example/ex1-again"


def plcvec(*args, cwd=REPO):
    return subprocess.run([sys.executable, "-m", "plcvec", *args], capture_output=True, text=True, cwd=cwd, timeout=300)


def edit_family(folder, family, edit):
    path = folder / f"{family}.json"
    doc = json.loads(path.read_text(encoding="utf-8"))
    edit({v["id"]: v for v in doc["vectors"]}, doc)
    path.write_text(json.dumps(doc, indent=1), encoding="utf-8")


@pytest.fixture(scope="module")
def sets(tmp_path_factory):
    """An unchanged copy of vectors/ and a copy with one change of each sort in fx5-time-add."""
    root = tmp_path_factory.mktemp("sets")
    old, new = root / "old", root / "new"
    shutil.copytree(REPO / "vectors", old)
    shutil.copytree(REPO / "vectors", new)

    def edit(by_id, doc):
        ex1 = by_id[EX1]
        head = ex1["initial"]["operands"]["d"]["device"]
        ex1["final"]["devices"][head] = 99                     # an expectation
        by_id[PROGRAM]["description"] += " (reworded)"         # metadata only
        by_id[OVER24]["tags"] = by_id[OVER24]["tags"] + ["wrap"]
        carry = by_id[CARRY]
        carry["initial"]["devices"]["SD0"] = 7                 # an input
        added = json.loads(json.dumps(ex1))
        added["id"] = NEW_ID
        doc["vectors"] = [v for v in doc["vectors"] if v["id"] != f"{TA}/TADDP/pulse/en-off"] + [added]

    edit_family(new, TA, edit)
    return old, new


def test_reports_each_change_by_id(sets, capsys):
    old, new = sets
    assert main(["diff", str(old), str(new), "--json"]) == 1
    report = json.loads(capsys.readouterr().out)
    fam = report["families"][TA]
    assert fam["added"] == [NEW_ID]
    assert fam["removed"] == [f"{TA}/TADDP/pulse/en-off"]
    assert {v["id"]: v["class"] for v in fam["changed"]} == {EX1: "expectation", CARRY: "inputs", PROGRAM: "metadata",
                                                             OVER24: "metadata"}
    ex1 = next(v for v in fam["changed"] if v["id"] == EX1)
    # 6:32:40 + 7:48:10 = 14:20:50: the hour word of (d) (D300) held 14 and now holds 99.
    assert ex1["changes"] == [{"path": "final.devices.D300", "old": 14, "new": 99}]
    assert fam["counts"] == {"added": 1, "removed": 1, "expectation": 1, "inputs": 1, "metadata": 2}
    assert not fam["header"]
    others = {name: f for name, f in report["families"].items() if name != TA}
    assert others and all(sum(f["counts"].values()) == 0 and not f["header"] for f in others.values())
    assert report["identical"] is False


def test_text_output_shows_field_level_changes(sets, capsys):
    old, new = sets
    assert main(["diff", str(old), str(new)]) == 1
    out = capsys.readouterr().out
    assert f"  ~ {EX1} (expectation)\n      final.devices.D300: 14 -> 99\n" in out
    assert f"  + {NEW_ID}\n" in out and f"  - {TA}/TADDP/pulse/en-off\n" in out
    assert f"  ~ {OVER24} (metadata)\n" in out
    assert f"{TA}: 1 added, 1 removed, 1 expectation changed, 1 inputs changed, 2 metadata only ({TA_COUNT} -> {TA_COUNT} vectors)" in out
    assert "  fx5-time-compare: identical" in out
    assert main(["diff", str(old), str(new), "--brief"]) == 1
    brief = capsys.readouterr().out
    assert f"  ~ {EX1} (expectation)\n" in brief and "final.devices" not in brief


def test_identical_sets_exit_0(sets):
    old, _ = sets
    proc = plcvec("diff", str(old), str(REPO / "vectors"))
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert "total: no vector differs\n" in proc.stdout


def test_a_family_file_against_a_folder(sets, capsys):
    old, new = sets
    assert main(["diff", str(old / f"{TA}.json"), str(old)]) == 0
    out = capsys.readouterr().out
    assert f"  {TA}: identical ({TA_COUNT} -> {TA_COUNT} vectors)" in out and "fx5-time-compare" not in out
    assert main(["diff", str(old), str(new / f"{TA}.json"), "--brief"]) == 1


@pytest.mark.parametrize("make,named", [
    (lambda root: root / "missing", "missing"),
    (lambda root: (root / "empty").mkdir() or root / "empty", "manifest.json"),
])
def test_bad_path_exits_2_naming_it(tmp_path, sets, make, named):
    bad = make(tmp_path)
    proc = plcvec("diff", str(bad), str(sets[0]), cwd=tmp_path)
    assert proc.returncode == 2
    assert named in proc.stderr and "Traceback" not in proc.stderr
    assert proc.stdout == ""


def test_invalid_json_exits_2_naming_the_file_and_line(tmp_path, sets):
    broken = tmp_path / "broken"
    shutil.copytree(sets[0], broken)
    path = broken / f"{TA}.json"
    lines = path.read_text().split("\n")
    lines[5] = lines[5] + ","  # a trailing comma after a header key
    path.write_text("\n".join(lines))
    proc = plcvec("diff", str(sets[0]), str(broken))
    assert proc.returncode == 2
    assert f"{path}:6: not valid JSON" in proc.stderr and "Traceback" not in proc.stderr


def test_manifest_naming_a_missing_file_exits_2(tmp_path, sets):
    partial = tmp_path / "partial"
    shutil.copytree(sets[0], partial)
    (partial / f"{TA}.json").unlink()
    proc = plcvec("diff", str(partial), str(sets[0]))
    assert proc.returncode == 2 and f"{partial / (TA + '.json')}: no such file" in proc.stderr


@pytest.fixture(scope="module")
def head_vectors(tmp_path_factory):
    """vectors/ as committed at HEAD, unpacked with git archive (independent of `git show`)."""
    out = tmp_path_factory.mktemp("head")
    tar = subprocess.run(["git", "archive", "--format=tar", "HEAD", "vectors"], cwd=REPO, capture_output=True, check=True).stdout
    with tarfile.open(fileobj=io.BytesIO(tar)) as archive:
        archive.extractall(out)
    return out / "vectors"


@pytest.mark.parametrize("revision", ["HEAD:vectors", "HEAD", f"HEAD:vectors/{TA}.json", "HEAD:./vectors"])
def test_git_revision_forms(head_vectors, revision):
    proc = plcvec("diff", revision, str(head_vectors))
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert proc.stdout.startswith(f"plcvec diff: {revision} (")


def test_git_revision_against_a_changed_set(sets):
    proc = plcvec("diff", "HEAD:vectors", str(sets[1]), "--family", TA, "--json")
    assert proc.returncode == 1
    fam = json.loads(proc.stdout)["families"][TA]
    assert fam["added"] == [NEW_ID] and fam["removed"] == [f"{TA}/TADDP/pulse/en-off"]


def test_unknown_revision_exits_2():
    proc = plcvec("diff", "no-such-revision:vectors", "vectors")
    assert proc.returncode == 2
    assert "no-such-revision:vectors" in proc.stderr and "Traceback" not in proc.stderr


def test_unknown_family_exits_2(sets):
    proc = plcvec("diff", str(sets[0]), str(sets[1]), "--family", "no-such-family")
    assert proc.returncode == 2 and "no family no-such-family" in proc.stderr


def test_alternatives_are_matched_by_their_choices():
    from plcvec.output.diff import change_class, changes, path_text

    a = {"choices": {"TADD-FLAGS-OFF": "set-only"}, "final": {"devices": {"SM700": True}}}
    b = {"choices": {"TADD-EXACT-24": "carry-above-24"}, "final": {"devices": {"SM700": False}}}
    assert changes({"alternatives": [a, b]}, {"alternatives": [b, a]}) == []
    moved = dict(b, final={"devices": {"SM700": True}})
    found = changes({"alternatives": [a, b]}, {"alternatives": [moved, a]})
    assert [(path_text(p), old, new) for p, old, new in found] == \
        [("alternatives[TADD-EXACT-24=carry-above-24].final.devices.SM700", False, True)]
    assert change_class(found[0][0]) == "expectation"
    assert change_class(("steps", 0, "rlo_in")) == "inputs" and change_class(("steps", 0, "expect", "result")) == "expectation"
    assert change_class(("clauses",)) == "metadata" and change_class(("initial", "devices", "D100")) == "inputs"


# --- the upgrade report: what a new set changes for one implementation ------------------------------

SET_ONLY = f"{TA}/TADD/carry/below-wrap/flags-on-before"    # offers TADD-FLAGS-OFF=set-only


@pytest.fixture(scope="module")
def upgrade_sets(tmp_path_factory):
    """OLD without one interpretation (a new one in NEW) and with one alternative's expectation that
    NEW changes; NEW merged one id and dropped another that a known-failures file lists."""
    root = tmp_path_factory.mktemp("upgrade")
    old, new = root / "old", root / "new"
    shutil.copytree(REPO / "vectors", old)
    shutil.copytree(REPO / "vectors", new)

    def edit_old(by_id, doc):
        doc["interpretations"] = [i for i in doc["interpretations"] if i["id"] != "TADD-ERROR-ORDER"]
        alt = next(a for a in by_id[SET_ONLY]["alternatives"] if a["choices"] == {"TADD-FLAGS-OFF": "set-only"})
        device = next(d for d, v in alt["final"]["devices"].items() if v is True)
        alt["final"]["devices"][device] = False        # NEW expects another value under set-only
        for expect in alt["expect"]:
            expect["devices"].pop(device, None)
        doc["vectors"].append({**json.loads(json.dumps(by_id[EX1])), "id": f"{TA}/TADD/old/merged-away"})
    edit_family(old, TA, edit_old)
    manifest = json.loads((new / "manifest.json").read_text())
    manifest["merged"][TA] = {f"{TA}/TADD/old/merged-away": EX1}
    (new / "manifest.json").write_text(json.dumps(manifest, indent=1))
    known = root / "known.toml"
    known.write_text(f'[[known-failure]]\nid = "{f"{TA}/TADD/old/merged-away"}"\nreason = "r"\n\n'
                     f'[[known-failure]]\nid = "{TA}/TADD/gone"\nreason = "r"\n\n'
                     f'[[known-failure]]\nid = "{SET_ONLY}"\nreason = "r"\n')
    return old, new, known


def test_the_upgrade_report_lists_what_changes_under_the_declarations(upgrade_sets, capsys):
    old, new, known = upgrade_sets
    assert main(["diff", str(old), str(new), "--choose", "TADD-FLAGS-OFF=set-only",
                 "--expectations", str(known)]) == 1
    out = capsys.readouterr().out
    # The new interpretation by id, question and default, and that it is not declared.
    assert "  + TADD-ERROR-ORDER (fx5-time-add): When one execution meets both" in out
    assert "default device-range-first" in out
    assert "take their default: TADD-ERROR-ORDER=device-range-first" in out
    # Under set-only the changed alternative's vector expects something else; nothing else does.
    assert "vectors whose expectation changed for you: 1\n" in out and f"  ~ {SET_ONLY}\n" in out
    # Each known failure's fate.
    assert f"merged into {EX1}; list that id instead" in out
    assert f"  - {TA}/TADD/gone ({known}:5): no such vector in the new set; remove it" in out
    assert f"  ~ {SET_ONLY} ({known}:9): its expectation changed" in out


def test_under_the_defaults_the_changed_alternative_changes_nothing(upgrade_sets, capsys):
    old, new, _ = upgrade_sets
    main(["diff", str(old), str(new), "--choose", "TADD-EXACT-24=carry-at-24"])
    assert "vectors whose expectation changed for you: 0\n" in capsys.readouterr().out


def test_a_declared_alternative_the_new_set_lacks_is_named(upgrade_sets, capsys):
    old, new, _ = upgrade_sets
    main(["diff", str(old), str(new), "--choose", "TADD-FLAGS-OFF=sometimes"])
    assert "  ! TADD-FLAGS-OFF=sometimes" in capsys.readouterr().out


def test_brief_names_a_new_interpretation_and_prints_no_empty_header_line(upgrade_sets, capsys):
    old, new, _ = upgrade_sets
    main(["diff", str(old), str(new), "--brief"])
    out = capsys.readouterr().out
    assert "  + TADD-ERROR-ORDER (fx5-time-add): When one execution meets both" in out
    assert "  header:\n" not in out and "interpretations[" not in out
