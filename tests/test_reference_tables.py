"""The reference tables of verifiers/CONTRACT.md and each native README, rendered by `plcvec export`.

What the tables must hold is read off the manual pages by hand (TADDP is TADD's pulse form, HOUR's D2
is a bit, the FX5 hour field is 0 to 23, CP1E's fields are BCD bytes, the flags' device names).
"""
import pytest

from plcvec.cli import main
from plcvec.export.reference import BEGIN, END, NATIVE

from conftest import REPO

FILES = ["verifiers/CONTRACT.md"] + [f"verifiers/{lang}/README.md" for lang in NATIVE]


def tables(rel):
    text = (REPO / rel).read_text(encoding="utf-8")
    assert text.count(BEGIN) == 1 and text.count(END) == 1, rel
    return text.split(BEGIN, 1)[1].split(END, 1)[0]


@pytest.mark.parametrize("rel", FILES)
def test_every_file_carries_the_same_tables(rel):
    assert tables(rel) == tables("verifiers/CONTRACT.md")


def test_the_tables_say_what_the_pages_say():
    text = tables("verifiers/CONTRACT.md")
    # TADD (P): every scan; its pulse form on the rising edge; neither is a contact.
    assert "| `TADD` | `TADD` | (none) | (none) | every-scan |" in text
    assert "| `TADDP` | `TADDP` | (none) | (none) | rising-edge |" in text
    # LDTM□ with "<=" entering □, ST name LDTM_LE; CP1E "LD" with <=DT.
    assert "| `LDTM<=` | `LDTM_LE` | LD | `<=` | every-scan |" in text
    assert "| `OR <>DT` | `OR <>DT` | OR | `<>` | every-scan |" in text
    # HOUR: the page gives no structured-text form; D2 is the comparison output, one bit.
    assert "| `HOUR` | (none on the page) | (none) | (none) | every-scan |" in text
    assert "| `D2` | output | bit | 1 bit | no |" in text
    assert "| `S1` | preset | word | 3 words | yes |" in text
    # "Set the "hour" data ... within the range 0 to 23"; CP1E: "Year (00 to 99, BCD)" in bits 08-15.
    assert "| `hour` | 0 | 0-15 | signed16 | 0 to 23 |" in text
    assert "| `year` | 2 | 8-15 | bcd | 0 to 99 |" in text
    # Flags and error devices named on the pages (SM700/SM8022 carry, SM8020 zero, SD0/SD8067, SM709, M8004).
    for row in ("| carry | `SM700`, `SM8022` |", "| zero | `SM8020` |", "| error code | `SD0`, `SD8067` |",
                "| error | `SM709` |", "| error | `M8004` |", "| error | `P_ER` |"):
        assert row in text


def test_every_interpretation_is_listed_with_its_default(families):
    text = tables("verifiers/CONTRACT.md")
    for fam in families.values():
        for iid, interp in fam.interpretations.items():
            assert f"| `{iid}` | " in text
            assert f"`{interp['default']}` (default): " in text


@pytest.mark.slow   # six whole exports; the default run checks the tables themselves (above)
def test_check_fails_on_edited_tables_and_on_missing_markers(repo, tmp_path, capsys, monkeypatch):
    from plcvec.export import command

    def fake_render(lang, model, templates=None):   # the languages' own files are not what is tested here
        from plcvec.export.targets import Target
        return Target(lang, tmp_path, {}, [])

    monkeypatch.setattr(command, "render", fake_render)
    root = tmp_path / "root"
    for rel in FILES:
        (root / rel).parent.mkdir(parents=True, exist_ok=True)
        (root / rel).write_text((repo / rel).read_text(encoding="utf-8"), encoding="utf-8")
    args = ["export", "--all", "--vectors", str(repo / "vectors"), "--root", str(root)]
    assert main(args + ["--check"]) == 0
    go = root / "verifiers/go/README.md"
    go.write_text(go.read_text(encoding="utf-8").replace("| `TADDP` | `TADDP` |", "| `TADDP` | `TADD_P` |"),
                  encoding="utf-8")
    capsys.readouterr()
    assert main(args + ["--check"]) == 1
    assert f"{go}: the reference tables differ from what the spec gives" in capsys.readouterr().err
    assert main(args) == 0 and main(args + ["--check"]) == 0
    java = root / "verifiers/java/README.md"
    java.write_text(java.read_text(encoding="utf-8").replace(END, ""), encoding="utf-8")
    capsys.readouterr()
    assert main(args + ["--check"]) == 1
    assert f"{java}: needs the line {BEGIN}" in capsys.readouterr().err
    assert main(args) == 2          # nothing to write the tables between: a user's mistake, named
