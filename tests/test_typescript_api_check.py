"""verifiers/typescript/api/check.py's comparison of two API Extractor reports: a member moved up into
a base it extends is still there, a member gone is a change, and a change counts as announced when
CHANGES.md names it under Breaking or Deprecated of the version or of [Unreleased]."""
import importlib.util
from collections import Counter

from conftest import REPO

spec = importlib.util.spec_from_file_location("ts_api_check", REPO / "verifiers" / "typescript" / "api" / "check.py")
check = importlib.util.module_from_spec(spec)
spec.loader.exec_module(check)

BEFORE = """\
export interface CaseOptions {
    readonly filter?: string;
}

export interface VectorTestOptions extends CaseOptions {
    readonly maxSkipped?: number;
    readonly name?: string;
}
"""


def test_a_member_moved_into_the_base_it_extends_is_no_change():
    after = BEFORE.replace("    readonly filter?: string;\n", "    readonly filter?: string;\n    readonly maxSkipped?: number;\n", 1)
    after = after.replace("    readonly maxSkipped?: number;\n    readonly name", "    readonly name")
    before, now = check.declarations(BEFORE), check.declarations(after)
    assert ("VectorTestOptions.maxSkipped", "readonly maxSkipped?: number;") in before - now
    assert check.unannounced(before, now, "") == []


def test_a_member_gone_or_retyped_is_a_change_unless_named():
    gone = check.declarations(BEFORE.replace("    readonly maxSkipped?: number;\n", ""))
    retyped = check.declarations(BEFORE.replace("maxSkipped?: number", "maxSkipped?: string"))
    for after in (gone, retyped):
        assert check.unannounced(check.declarations(BEFORE), after, "") == ["VectorTestOptions.maxSkipped"]
        assert check.unannounced(check.declarations(BEFORE), after, "- `VectorTestOptions.maxSkipped` removed") == []


def test_a_member_in_an_unrelated_type_does_not_count():
    after = BEFORE.replace("    readonly maxSkipped?: number;\n", "") + "\nexport interface Other {\n    readonly maxSkipped?: number;\n}\n"
    assert check.unannounced(check.declarations(BEFORE), check.declarations(after), "") == ["VectorTestOptions.maxSkipped"]


def test_the_unreleased_section_is_announced_with_the_version(tmp_path, monkeypatch):
    (tmp_path / "CHANGES.md").write_text(
        "# Changes\n\n## [Unreleased]\n\n### Deprecated\n\n- `TaddMachine` is now `Fx5TimeAdd`.\n\n"
        "### Added\n\n- `Added` is not an announcement of a change.\n\n"
        "## [0.2.0] - 2026-11-27\n\n### Breaking\n\n- `VectorResult` renamed.\n\n"
        "## [0.1.0] - 2026-11-01\n\n### Breaking\n\n- `Older`.\n", encoding="utf-8")
    monkeypatch.setattr(check, "REPO", tmp_path)
    text = check.announced("0.2.0")
    assert "`TaddMachine`" in text and "`VectorResult`" in text
    assert "`Added`" not in text and "`Older`" not in text
