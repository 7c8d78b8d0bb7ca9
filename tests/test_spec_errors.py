"""Malformed spec files: every mistake is reported as "file:line: plain message", never as a traceback.

Each case copies the real spec folder, breaks ONE file with a text-level edit at a known line, and checks
(a) in process that load_spec raises SpecError naming that file and line with a plain message, and
(b) as a user would that `plcvec lint` exits 2 and prints "file.yaml:LINE" on stderr without a traceback.
"""
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from plcvec.errors import SpecError
from plcvec.spec.loader import load_spec

REPO = Path(__file__).resolve().parents[1]
SPEC = REPO / "spec"

TC = "fx5-time-compare.yaml"
DC = "fx5-date-compare.yaml"
TA = "fx5-time-add.yaml"
CP = "cp1e-time-compare.yaml"
HM = "fc6a-hour-meter.yaml"


# ---------------------------------------------------------------- text-level edits

def L(name, text, nth=0):
    """The 1-based line of the real spec file `name` that holds exactly `text` (stripped), the nth such:
    each case names the line it breaks by its text, so that editing the spec elsewhere moves no case."""
    lines = [k + 1 for k, line in enumerate((SPEC / name).read_text(encoding="utf-8").split("\n")) if line.strip() == text]
    assert len(lines) > nth, f"{name} has {len(lines)} lines that read {text!r}"
    return lines[nth]


def replace(line, old, new):
    """Replace `old` (which must occur exactly once) on 1-based `line` with `new`."""
    def edit(lines):
        assert lines[line - 1].count(old) == 1, f"line {line} does not hold {old!r} once: {lines[line - 1]!r}"
        lines[line - 1] = lines[line - 1].replace(old, new)
        return lines
    return edit


def insert(line, text):
    """Insert `text` as the new line `line` (what was there moves down)."""
    def edit(lines):
        lines.insert(line - 1, text)
        return lines
    return edit


def delete(line, expect):
    def edit(lines):
        assert expect in lines[line - 1], f"line {line} is {lines[line - 1]!r}"
        del lines[line - 1]
        return lines
    return edit


def whole(data):
    """Replace the file's content by `data` (str or bytes)."""
    def edit(lines):
        return data
    return edit


def apply(folder, name, edit):
    path = folder / name
    lines = path.read_text(encoding="utf-8").split("\n")
    out = edit(lines)
    if isinstance(out, list):
        out = "\n".join(out)
    path.write_bytes(out if isinstance(out, bytes) else out.encode("utf-8"))
    return path


def latin1_line(line, old, new):
    """Like replace, but writes that one line in Latin-1 so the file is no longer UTF-8."""
    def edit(lines):
        assert lines[line - 1].count(old) == 1
        lines[line - 1] = lines[line - 1].replace(old, new)
        return b"\n".join(l.encode("latin-1" if i == line - 1 else "utf-8") for i, l in enumerate(lines))
    return edit


# ---------------------------------------------------------------- the cases
# (id, file broken, edit, line the error must name, phrase the message must contain)

CASES = [
    # YAML syntax
    ("yaml-bad-indentation", TC, replace(L(TC, 'manual: fx5-time-compare-LDTM.txt'), "manual:", "  manual:"), L(TC, 'manual: fx5-time-compare-LDTM.txt'), "check the indentation"),
    ("yaml-unclosed-brace", TC,
     replace(L(TC, '- {name: hour, word: 0, lsb: 0, width: 16, encoding: signed16, min: 0, max: 23, clause: range.hour}'), "clause: range.hour}", "clause: range.hour"), L(TC, '- {name: hour, word: 0, lsb: 0, width: 16, encoding: signed16, min: 0, max: 23, clause: range.hour}'), "flow mapping that starts on this line is not closed"),
    ("yaml-unclosed-bracket", TC, replace(L(TC, 'reserved_bits: [3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14]'), "13, 14]", "13, 14"), L(TC, 'reserved_bits: [3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14]'), "flow sequence that starts on this line is not closed"),
    ("yaml-unclosed-quote", TC, replace(L(TC, 'says: The hour word (s1), (s2) holds 0 to 23.'), "says: The hour", "says: 'The hour"), L(TC, 'says: The hour word (s1), (s2) holds 0 to 23.'), "closing quote missing"),
    ("control-character", TC, replace(L(TC, 'says: The hour word (s1), (s2) holds 0 to 23.'), "hour word", "hour\x07word"), L(TC, 'says: The hour word (s1), (s2) holds 0 to 23.'), "is not allowed in a YAML file"),
    ("yaml-tab-indent", TC, replace(L(TC, 'polarity: select          # a 1 bit puts the field in the comparison'), "  polarity", "\tpolarity"), L(TC, 'polarity: select          # a 1 bit puts the field in the comparison'), "not tabs"),
    # keys
    ("duplicate-key-top", TC, insert(L(TC, 'manual: fx5-time-compare-LDTM.txt'), "family: fx5-other"), L(TC, 'manual: fx5-time-compare-LDTM.txt'), "duplicate key 'family'"),
    ("duplicate-key-flow", TC, replace(L(TC, '- {name: hour, word: 0, lsb: 0, width: 16, encoding: signed16, min: 0, max: 23, clause: range.hour}'), "max: 23,", "max: 23, max: 22,"), L(TC, '- {name: hour, word: 0, lsb: 0, width: 16, encoding: signed16, min: 0, max: 23, clause: range.hour}'), "duplicate key 'max'"),
    ("unknown-key", TC, replace(L(TC, '- {name: hour, word: 0, lsb: 0, width: 16, encoding: signed16, min: 0, max: 23, clause: range.hour}'), "clause: range.hour}", "clause: range.hour, unit: h}"), L(TC, '- {name: hour, word: 0, lsb: 0, width: 16, encoding: signed16, min: 0, max: 23, clause: range.hour}'),
     "unknown key 'unit'"),
    ("unknown-top-key", TA, insert(L(TA, ''), "commentary: none"), L(TA, ''), "unknown key 'commentary'"),
    ("key-not-allowed-for-kind", TC, insert(L(TC, '', 8), "errors: {registers: {devices: [SD0]}, checks: []}"), L(TC, '', 8),
     "not allowed for this kind"),
    ("selector-in-clock-add", TA, insert(L(TA, '', 4), "selector: {operand: s1}"), L(TA, '', 4), "not allowed for this kind"),
    ("merge-key", TC, replace(L(TC, '- {name: minute, word: 1, lsb: 0, width: 16, encoding: signed16, min: 0, max: 59, clause: range.minute}'), "{name: minute,", "{<<: {word: 1}, name: minute,"), L(TC, '- {name: minute, word: 1, lsb: 0, width: 16, encoding: signed16, min: 0, max: 59, clause: range.minute}'), "merge keys"),
    # types and required values
    ("wrong-type-min", TC, replace(L(TC, '- {name: hour, word: 0, lsb: 0, width: 16, encoding: signed16, min: 0, max: 23, clause: range.hour}'), "min: 0,", "min: zero,"), L(TC, '- {name: hour, word: 0, lsb: 0, width: 16, encoding: signed16, min: 0, max: 23, clause: range.hour}'), "expected integer"),
    ("wrong-type-quoted-int", TA, replace(L(TA, '- {check: device_range, operands: [s1, s2, d], code: 0x2820, clause: error.2820}'), "code: 0x2820", 'code: "0x2820"'), L(TA, '- {check: device_range, operands: [s1, s2, d], code: 0x2820, clause: error.2820}'), "expected integer"),
    ("impossible-date", TC, insert(L(TC, 'R: 32768'), "    checked: 2026-02-30"), L(TC, 'R: 32768'), "bad value '2026-02-30'"),
    ("alternatives-set-different-parameters", TA,
     replace(L(TA, '- {id: set-only, says: "An execution only turns flags on; a flag already on stays on.", sets: {written: set_only}}'), "sets: {written: set_only}", "sets: {written: set_only, extra: 1}"), L(TA, '- {id: set-only, says: "An execution only turns flags on; a flag already on stays on.", sets: {written: set_only}}'),
     "alternatives must set the same parameters"),
    ("clause-without-source", TC, delete(L(TC, 'source: {section: Processing details, quote: "These instructions compare the time data in the device specified by (s1) with the time data in the device specified by (s2) in accordance with the conditions set by (s3)."}'), "source:"), L(TC, '- id: purpose'), "clauses.0: 'source' is required but missing"),
    ("source-without-quote", TC,
     replace(L(TC, 'source: {section: Ladder diagram, quote: \'("=", "<>", ">", "<=", "<", ">=" enters □.)\'}'), """, quote: '("=", "<>", ">", "<=", "<", ">=" enters □.)'}""", "}"), L(TC, 'source: {section: Ladder diagram, quote: \'("=", "<>", ">", "<=", "<", ">=" enters □.)\'}'),
     "'quote' is required but missing"),
    ("interpretation-quote-without-quote", TA,
     replace(L(TA, '- {section: Processing details, quote: "If the result is 0 (0:00:00), the zero flag turns on."}'), ', quote: "If the result is 0 (0:00:00), the zero flag turns on."}', "}"), L(TA, '- {section: Processing details, quote: "If the result is 0 (0:00:00), the zero flag turns on."}'),
     "'quote' is required but missing"),
    # field ranges and encodings
    ("field-min-greater-than-max", TC, replace(L(TC, '- {name: minute, word: 1, lsb: 0, width: 16, encoding: signed16, min: 0, max: 59, clause: range.minute}'), "min: 0, max: 59", "min: 60, max: 59"), L(TC, '- {name: minute, word: 1, lsb: 0, width: 16, encoding: signed16, min: 0, max: 59, clause: range.minute}'),
     "min 60 is greater than max 59"),
    ("signed16-range-too-large", TC, replace(L(TC, '- {name: hour, word: 0, lsb: 0, width: 16, encoding: signed16, min: 0, max: 23, clause: range.hour}'), "max: 23", "max: 40000"), L(TC, '- {name: hour, word: 0, lsb: 0, width: 16, encoding: signed16, min: 0, max: 23, clause: range.hour}'), "does not fit signed16"),
    ("bcd-range-too-large", CP, replace(L(CP, '- {name: year, word: 2, lsb: 8, width: 8, encoding: bcd, min: 0, max: 99, clause: layout.year}'), "max: 99", "max: 100"), L(CP, '- {name: year, word: 2, lsb: 8, width: 8, encoding: bcd, min: 0, max: 99, clause: layout.year}'), "does not fit bcd"),
    ("bcd-width-not-digits", CP, replace(L(CP, '- {name: day, word: 1, lsb: 8, width: 8, encoding: bcd, min: 1, max: 31, clause: layout.day}'), "width: 8", "width: 6"), L(CP, '- {name: day, word: 1, lsb: 8, width: 8, encoding: bcd, min: 1, max: 31, clause: layout.day}'), "width 6 is not a whole number of 4-bit BCD digits"),
    ("field-overlap-word", TC, replace(L(TC, '- {name: minute, word: 1, lsb: 0, width: 16, encoding: signed16, min: 0, max: 59, clause: range.minute}'), "word: 1", "word: 0"), L(TC, '- {name: minute, word: 1, lsb: 0, width: 16, encoding: signed16, min: 0, max: 59, clause: range.minute}'), "overlaps field 'hour'"),
    ("field-overlap-bits", CP, replace(L(CP, '- {name: month, word: 2, lsb: 0, width: 8, encoding: bcd, min: 1, max: 12, clause: layout.month}'), "lsb: 0", "lsb: 4"), L(CP, '- {name: month, word: 2, lsb: 0, width: 8, encoding: bcd, min: 1, max: 12, clause: layout.month}'), "overlaps field 'year'"),
    # references
    ("unknown-clause", TC, replace(L(TC, '- {name: hour, word: 0, lsb: 0, width: 16, encoding: signed16, min: 0, max: 23, clause: range.hour}'), "clause: range.hour}", "clause: range.hours}"), L(TC, '- {name: hour, word: 0, lsb: 0, width: 16, encoding: signed16, min: 0, max: 23, clause: range.hour}'),
     "unknown clause 'range.hours'"),
    ("unknown-clause-in-erratum", TA, replace(L(TA, 'clause: carry'), "clause: carry", "clause: carry.flag"), L(TA, 'clause: carry'),
     "unknown clause 'carry.flag'"),
    ("unknown-interpretation", TC, replace(L(TC, 'scope: {interpretation: FX5-SM709-SCOPE}'), "FX5-SM709-SCOPE", "FX5-SM709-SCOP"), L(TC, 'scope: {interpretation: FX5-SM709-SCOPE}'),
     "unknown interpretation 'FX5-SM709-SCOP'"),
    ("interpretation-default-not-alternative", TC, replace(L(TC, 'default: selected-fields'), "default: selected-fields", "default: selected"),
     L(TC, 'default: selected-fields'), "default 'selected' is not one of the alternatives"),
    ("alternative-does-not-set-parameter", TC, replace(L(TC, '- {id: all-words, says: "All three words of (s1) and, unless (s2) is ignored, of (s2) are checked whenever the instruction executes.", sets: {scope: all}}'), "sets: {scope: all}", "sets: {scop: all}"), L(TC, '- {id: all-words, says: "All three words of (s1) and, unless (s2) is ignored, of (s2) are checked whenever the instruction executes.", sets: {scope: all}}'),
     "does not set 'scope'"),
    ("duplicate-clause-id", TC, replace(L(TC, '- id: mnemonics'), "- id: mnemonics", "- id: purpose"), L(TC, '- id: mnemonics'), f"duplicate clause id 'purpose' (first used on line {L(TC, '- id: purpose')})"),
    ("duplicate-interpretation-id", TA, replace(L(TA, '- id: TADD-EXACT-24'), "id: TADD-EXACT-24", "id: TADD-FLAGS-OFF"), L(TA, '- id: TADD-EXACT-24'),
     "duplicate interpretation id 'TADD-FLAGS-OFF'"),
    # selector bits
    ("selector-field-bit-is-reserved", TC, replace(L(TC, 'reserved_bits: [3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14]'), "[3, 4,", "[2, 3, 4,"), L(TC, 'reserved_bits: [3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14]'), "bit 2 is assigned twice"),
    ("selector-two-fields-one-bit", TC, replace(L(TC, 'field_bits: {second: 0, minute: 1, hour: 2}'), "minute: 1", "minute: 0"), L(TC, 'field_bits: {second: 0, minute: 1, hour: 2}'), "bit 0 is assigned twice"),
    ("selector-clock-bit-is-reserved", DC, replace(L(DC, 'source_bit: {bit: 15, clause: s3.current-clock}'), "bit: 15,", "bit: 14,"), L(DC, 'source_bit: {bit: 15, clause: s3.current-clock}'),
     f"bit 14 is assigned twice (current-clock bit here, reserved on line {L(DC, 'reserved_bits: [3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14]')})"),
    # whole files
    ("empty-file", TC, whole(""), 1, "empty"),
    ("comments-only-file", TC, whole("# nothing here yet\n"), 1, "empty"),
    ("top-level-list", TC, whole("- family: fx5-time-compare\n- kind: masked_compare\n"), 1,
     "must be a mapping at the top level"),
    ("top-level-scalar", TC, whole("fx5-time-compare\n"), 1, "must be a mapping at the top level"),
    ("not-utf8", TC, latin1_line(L(TC, 'says: The hour word (s1), (s2) holds 0 to 23.'), "hour word", "hour wörd"), L(TC, 'says: The hour word (s1), (s2) holds 0 to 23.'), "not UTF-8"),
    ("same-family-in-two-files", TC, replace(L(TC, 'family: fx5-time-compare'), "family: fx5-time-compare", "family: fx5-date-compare"), L(TC, 'family: fx5-time-compare'),
     "also defined in fx5-date-compare.yaml"),
    # unsafe YAML: a Python tag is refused, never constructed
    ("python-object-tag-scalar", TC,
     replace(L(TC, '- {name: hour, word: 0, lsb: 0, width: 16, encoding: signed16, min: 0, max: 23, clause: range.hour}'), "clause: range.hour}", "clause: !!python/object/apply:os.system [echo pwned]}"), L(TC, '- {name: hour, word: 0, lsb: 0, width: 16, encoding: signed16, min: 0, max: 23, clause: range.hour}'),
     "not allowed"),
    ("python-name-tag", TC, replace(L(TC, 'family: fx5-time-compare'), "family: fx5-time-compare", "family: !!python/name:os.system"), L(TC, 'family: fx5-time-compare'),
     "not allowed"),
    ("python-object-tag-mapping", TC,
     replace(L(TC, 'source: {section: Processing details, quote: "These instructions compare the time data in the device specified by (s1) with the time data in the device specified by (s2) in accordance with the conditions set by (s3)."}'), "source: {", "source: !!python/object:plcvec.errors.SpecError {"), L(TC, 'source: {section: Processing details, quote: "These instructions compare the time data in the device specified by (s1) with the time data in the device specified by (s2) in accordance with the conditions set by (s3)."}'), "not allowed"),
    ("recursive-alias", TC, insert(L(TC, 'device_sizes:'), "  loop: &a [*a]"), L(TC, 'device_sizes:'), "alias"),
    # the coverage model
    ("model-unknown-derivation", TC, replace(L(TC, '- {id: form, derive: forms, says: "The contact form: LD starts a rung, AND is in series, OR in parallel."}'), "derive: forms,", "derive: form,"), L(TC, '- {id: form, derive: forms, says: "The contact form: LD starts a rung, AND is in series, OR in parallel."}'),
     "unknown derivation 'form' for kind masked_compare"),
    ("model-derivation-of-another-kind", TA, replace(L(TA, '- {id: sum, derive: sum, says: "Where the sum falls against 24:00:00: zero, below, exactly at, above; or no sum made."}'), "derive: sum,", "derive: conditions,"), L(TA, '- {id: sum, derive: sum, says: "Where the sum falls against 24:00:00: zero, below, exactly at, above; or no sum made."}'),
     "unknown derivation 'conditions' for kind clock_add"),
    ("model-derivation-needs-a-fact", CP, insert(L(CP, '- {id: ordering, derive: orderings, says: "The ordering of the unmasked data the execution found, or none when it compared nothing."}'), '      - {id: source, derive: source-bit, says: "Bit 15."}'), L(CP, '- {id: ordering, derive: orderings, says: "The ordering of the unmasked data the execution found, or none when it compared nothing."}'),
     "needs selector.source_bit"),
    ("model-when-names-later-dimension", TC, replace(L(TC, '- {id: logic, derive: preceding-logic, when: {form: [AND, OR]}, says: "The preceding logic state an AND or OR form combines with."}'), "when: {form: [AND, OR]}", "when: {condition: ['=']}"), L(TC, '- {id: logic, derive: preceding-logic, when: {form: [AND, OR]}, says: "The preceding logic state an AND or OR form combines with."}'),
     "depends on 'condition', which is not a dimension defined before it"),
    ("model-when-unknown-class", TC, replace(L(TC, '- {id: logic, derive: preceding-logic, when: {form: [AND, OR]}, says: "The preceding logic state an AND or OR form combines with."}'), "when: {form: [AND, OR]}", "when: {form: [AND, XOR]}"), L(TC, '- {id: logic, derive: preceding-logic, when: {form: [AND, OR]}, says: "The preceding logic state an AND or OR form combines with."}'),
     "'XOR' names no class of dimension 'form'"),
    ("model-product-unknown-dimension", TC, replace(L(TC, '- dimensions: [form, logic, condition, ordering]'), "[form, logic, condition, ordering]", "[form, logic, condition, order]"), L(TC, '- dimensions: [form, logic, condition, ordering]'),
     "unknown dimension 'order'"),
    ("model-product-class-unknown", TC, replace(L(TC, 'classes: {ordering: [lt, eq, gt]}'), "[lt, eq, gt]", "[lt, eq, ge]"), L(TC, 'classes: {ordering: [lt, eq, gt]}'),
     "'ge' names no class of dimension 'ordering'"),
    ("model-exclude-pattern-matches-nothing", TC, replace(L(TC, '- classes: {source: operands, data: "dummy-*"}'), '"dummy-*"', '"dummy-s3.*"'), L(TC, '- classes: {source: operands, data: "dummy-*"}'),
     "'dummy-s3.*' names no class of dimension 'data'"),
    ("model-unknown-strength", TC, replace(L(TC, 'strength: pairwise'), "strength: pairwise", "strength: triples"), L(TC, 'strength: pairwise'), "strength"),
    ("nonexistent-calendar-unknown-field", DC, replace(L(DC, 'calendar: {year: year, month: month, day: day}'), "day: day}", "day: date}"), L(DC, 'calendar: {year: year, month: month, day: day}'), "calendar day names no field 'date'"),
    ("model-duplicate-dimension", TC, replace(L(TC, '- {id: logic, derive: preceding-logic, when: {form: [AND, OR]}, says: "The preceding logic state an AND or OR form combines with."}'), "{id: logic,", "{id: form,"), L(TC, '- {id: logic, derive: preceding-logic, when: {form: [AND, OR]}, says: "The preceding logic state an AND or OR form combines with."}'), "dimension 'form' is defined twice"),
]

IDS = [c[0] for c in CASES]


def test_enough_cases():
    assert len(CASES) >= 18
    assert len(set(IDS)) == len(IDS)


@pytest.fixture
def broken(tmp_path, request):
    """A copy of spec/ with one file broken; returns (folder, broken file, line, phrase)."""
    case_id, name, edit, line, phrase = request.param
    folder = tmp_path / "spec"
    shutil.copytree(SPEC, folder)
    path = apply(folder, name, edit)
    return folder, path, line, phrase


@pytest.mark.parametrize("broken", CASES, ids=IDS, indirect=True)
def test_load_spec_names_file_and_line(broken):
    folder, path, line, phrase = broken
    with pytest.raises(SpecError) as info:
        load_spec(folder)
    err = info.value
    assert Path(err.path).name == path.name, str(err)
    assert err.line == line, str(err)
    assert phrase in err.message, str(err)
    assert str(err) == f"{err.path}:{line}: {err.message}"
    # A plain sentence: one line, no Python object reprs.
    for noise in ("\n", "Traceback", "False schema", "object at 0x", "<unicode string>", "tag:yaml.org"):
        assert noise not in err.message, str(err)


# A few cases run `plcvec lint` as a process, as a user does (exit status, stderr, stdout); the others
# call the command's entry point in this process (`python -m plcvec` and the `plcvec` script exit with
# what plcvec.cli.main returns, having printed the same), which spares a Python start per case.
AS_A_PROCESS = {"yaml-tab-indent", "unknown-key", "python-object-tag-scalar", "recursive-alias"}


def lint(folder, cwd, as_a_process, capsys):
    """(exit status, stdout, stderr) of `plcvec lint --spec-dir FOLDER`."""
    if as_a_process:
        proc = subprocess.run([sys.executable, "-m", "plcvec", "lint", "--spec-dir", str(folder)],
                              capture_output=True, text=True, cwd=cwd, timeout=120)
        return proc.returncode, proc.stdout, proc.stderr
    from plcvec.cli import main

    code = main(["lint", "--spec-dir", str(folder)])
    out = capsys.readouterr()
    return code, out.out, out.err


def test_some_cases_run_as_a_process():
    assert AS_A_PROCESS < set(IDS)


@pytest.mark.parametrize("broken", CASES, ids=IDS, indirect=True)
def test_lint_exits_2_with_file_and_line(broken, tmp_path, request, capsys):
    folder, path, line, phrase = broken
    code, out, err = lint(folder, tmp_path, request.node.callspec.id in AS_A_PROCESS, capsys)
    assert code == 2, err
    assert "Traceback" not in err
    assert f"{path.name}:{line}: " in err
    assert phrase in err
    assert err.startswith("plcvec: ")
    assert out == ""


def test_python_tag_is_never_executed(tmp_path):
    """A !!python/object/apply tag would run a command under yaml.load; the loader must refuse it."""
    folder = tmp_path / "spec"
    shutil.copytree(SPEC, folder)
    marker = tmp_path / "pwned"
    apply(folder, TC, replace(106, "clause: range.hour}",
                              f"clause: !!python/object/apply:os.system ['touch {marker}']}}"))
    with pytest.raises(SpecError) as info:
        load_spec(folder)
    assert "tag" in info.value.message
    proc = subprocess.run([sys.executable, "-m", "plcvec", "lint", "--spec-dir", str(folder)],
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 2 and "Traceback" not in proc.stderr
    assert not marker.exists()


def test_loader_uses_safe_yaml():
    """The YAML loader class is PyYAML's SafeLoader (or a subclass of it), never Loader/UnsafeLoader."""
    import yaml

    from plcvec.spec import yaml_lines

    source = Path(yaml_lines.__file__).read_text()
    assert "UnsafeLoader" not in source and "FullLoader" not in source and "yaml.load(" not in source
    with pytest.raises(SpecError):
        yaml_lines.load_with_lines("x.yaml", "a: !!python/object/new:dict {}\n")
    data, lines = yaml_lines.load_with_lines("x.yaml", "a: 1\nb: [x, y]\n")
    assert data == {"a": 1, "b": ["x", "y"]} and lines[("b",)] == 2
    assert issubclass(yaml_lines._SpecLoader, yaml.SafeLoader)
    # libyaml only composes (nodes); values are built by SafeLoader's constructor as above.
    assert yaml_lines._FastLoader in (None, getattr(yaml, "CSafeLoader", None))


def test_libyaml_and_pyyaml_read_every_spec_file_alike(monkeypatch):
    """The fast reader (libyaml) gives the same values and the same lines as PyYAML's own parser."""
    from plcvec.spec import yaml_lines

    files = sorted(SPEC.rglob("*.yaml"))
    fast = [yaml_lines.load_with_lines(p, p.read_text(encoding="utf-8")) for p in files]
    assert all(yaml_lines._fast_node(p.read_text(encoding="utf-8"))[0] for p in files) == \
        (yaml_lines._FastLoader is not None)
    monkeypatch.setattr(yaml_lines, "_FastLoader", None)
    slow = [yaml_lines.load_with_lines(p, p.read_text(encoding="utf-8")) for p in files]
    assert len(files) >= 10 and fast == slow


@pytest.mark.parametrize("text, phrase, line", [
    ("a: &x 1\nb: *x\n", "aliases (*x) are not allowed", 2),
    ("a: [1, 2\nb: 3\n", "not closed", 1),
    ("a: 1\n\tb: 2\n", "YAML syntax error", 2),
    ("a: 1\nb: \x07\n", "not allowed in a YAML file", 2),
])
def test_what_libyaml_declines_is_read_again_for_the_message(text, phrase, line):
    from plcvec.spec import yaml_lines

    assert not yaml_lines._fast_node(text)[0]
    with pytest.raises(SpecError) as info:
        yaml_lines.load_with_lines("x.yaml", text)
    assert phrase in str(info.value) and info.value.line == line, str(info.value)


def test_the_real_spec_still_lints(tmp_path):
    proc = subprocess.run([sys.executable, "-m", "plcvec", "lint", "--spec-dir", str(SPEC)],
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.count(": ok (") == len(list(SPEC.glob("*.yaml")))
