"""`plcvec bench-native --common-vectors`: the vectors two revisions judge alike, each in its own format."""
import hashlib
import json

import pytest

from plcvec.common_vectors import describe, write_common
from plcvec.errors import PlcvecError


def _vector(vid, result, description="x"):
    return {"id": vid, "family": "fam", "instruction": "TADD", "description": description, "tags": ["t"],
            "clauses": [], "initial": {"devices": {"D0": 1}}, "steps": [{"expect": {"result": result}}],
            "outcome": {"category": "value"}, "final": {"devices": {"D0": 1}}}


def _folder(path, vectors, version):
    path.mkdir(parents=True)
    family = {"schema_version": version, "family": "fam", "count": len(vectors), "vectors": vectors}
    data = json.dumps(family).encode()
    (path / "fam.json").write_bytes(data)
    manifest = {"schema_version": version, "total": len(vectors), "csv": {"file": "vectors.csv"},
                "families": {"fam": {"file": "fam.json", "count": len(vectors), "sha256": "0" * 64,
                                     "outcomes": {"value": len(vectors)}}}}
    (path / "manifest.json").write_text(json.dumps(manifest))


def test_only_the_vectors_judged_alike_are_kept_each_in_its_revisions_form(tmp_path):
    # Baseline: a, b, c. Today: a with other words (judged alike), b with another expectation, d new.
    _folder(tmp_path / "base" / "vectors", [_vector("a", True), _vector("b", True), _vector("c", False)], "1.0.0")
    _folder(tmp_path / "now", [_vector("a", True, "reworded"), _vector("b", False), _vector("d", True)], "1.1.0")
    kept = write_common(tmp_path / "base", tmp_path / "now", tmp_path / "out-now", tmp_path / "out-base")
    assert kept == {"fam": (1, 3, 3)}
    assert describe(kept) == "1 vectors judged alike by both revisions: fam 1 of 3 (baseline 3)"
    for side, version, words in (("out-now", "1.1.0", "reworded"), ("out-base", "1.0.0", "x")):
        raw = (tmp_path / side / "fam.json").read_bytes()
        family = json.loads(raw)
        assert family["schema_version"] == version and family["count"] == 1
        assert [(v["id"], v["description"]) for v in family["vectors"]] == [("a", words)]
        manifest = json.loads((tmp_path / side / "manifest.json").read_text())
        entry = manifest["families"]["fam"]
        # The manifest holds what was written: count, total and hash; no figure of the whole set.
        assert entry["count"] == 1 and manifest["total"] == 1 and "outcomes" not in entry and "csv" not in manifest
        assert entry["sha256"] == hashlib.sha256(raw).hexdigest()


def test_nothing_in_common_is_refused(tmp_path):
    _folder(tmp_path / "base" / "vectors", [_vector("a", True)], "1.0.0")
    _folder(tmp_path / "now", [_vector("a", False)], "1.1.0")
    with pytest.raises(PlcvecError, match="no vector of .* judges alike at the baseline"):
        write_common(tmp_path / "base", tmp_path / "now", tmp_path / "o1", tmp_path / "o2")


def test_common_vectors_is_for_a_baseline_and_excludes_same_vectors(capsys, tmp_path):
    from plcvec.cli import main

    assert main(["bench-native", "--common-vectors"]) == 2
    assert "--common-vectors is for --baseline" in capsys.readouterr().err
    assert main(["bench-native", "--baseline", "HEAD", "--same-vectors", "--common-vectors"]) == 2
    assert "--same-vectors and --common-vectors each choose the vectors both sides judge" in capsys.readouterr().err


def test_a_manifest_family_without_a_file_is_named(tmp_path):
    _folder(tmp_path / "base" / "vectors", [_vector("a", True)], "1.0.0")
    _folder(tmp_path / "now", [_vector("a", True)], "1.1.0")
    manifest = json.loads((tmp_path / "now" / "manifest.json").read_text())
    del manifest["families"]["fam"]["file"]
    (tmp_path / "now" / "manifest.json").write_text(json.dumps(manifest))
    with pytest.raises(PlcvecError, match=r"manifest.json: family fam names no `file`"):
        write_common(tmp_path / "base", tmp_path / "now", tmp_path / "o1", tmp_path / "o2")
