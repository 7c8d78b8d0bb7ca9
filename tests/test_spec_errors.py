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

class L:
    """A line of a spec file found by its text, so that a case keeps working when lines are added above
    it: the one line that contains `text` (or, when several do, the one that is `text` once stripped),
    plus `offset`. Resolved against the file as it was before the case's edit."""

    def __init__(self, text, offset=0):
        self.text, self.offset = text, offset

    def __call__(self, lines):
        hits = [i for i, l in enumerate(lines) if self.text in l]
        if len(hits) != 1:
            hits = [i for i, l in enumerate(lines) if l.strip() == self.text.strip()]
        assert len(hits) == 1, f"{self.text!r} is on {len(hits)} lines of the file, not one"
        return hits[0] + 1 + self.offset


def replace(at, old, new):
    """Replace `old` (which must occur exactly once) on the line `at` (an L) with `new`."""
    def edit(lines):
        line = at(lines)
        assert lines[line - 1].count(old) == 1, f"line {line} does not hold {old!r} once: {lines[line - 1]!r}"
        lines[line - 1] = lines[line - 1].replace(old, new)
        return lines
    return edit


def insert(at, text):
    """Insert `text` as the new line `at` (what was there moves down)."""
    def edit(lines):
        lines.insert(at(lines) - 1, text)
        return lines
    return edit


def delete(at, expect):
    def edit(lines):
        line = at(lines)
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


def latin1_line(at, old, new):
    """Like replace, but writes that one line in Latin-1 so the file is no longer UTF-8."""
    def edit(lines):
        line = at(lines)
        assert lines[line - 1].count(old) == 1
        lines[line - 1] = lines[line - 1].replace(old, new)
        return b"\n".join(l.encode("latin-1" if i == line - 1 else "utf-8") for i, l in enumerate(lines))
    return edit


# ---------------------------------------------------------------- the cases
# (id, file broken, edit, line the error must name, phrase the message must contain)

CASES = [
    # YAML syntax
    ("yaml-bad-indentation", TC, replace(L('manual: fx5-time-com'), "manual:", "  manual:"), L('manual: fx5-time-com'), "check the indentation"),
    ("yaml-unclosed-brace", TC, replace(L('- {name: hour, word:'), "clause: range.hour}", "clause: range.hour"), L('- {name: hour, word:'), "flow mapping that starts on this line is not closed"),
    ("yaml-unclosed-bracket", TC, replace(L('reserved_bits: [3, 4'), "13, 14]", "13, 14"), L('reserved_bits: [3, 4'), "flow sequence that starts on this line is not closed"),
    ("yaml-unclosed-quote", TC, replace(L('says: The hour word '), "says: The hour", "says: 'The hour"), L('says: The hour word '), "closing quote missing"),
    ("control-character", TC, replace(L('says: The hour word '), "hour word", "hour\x07word"), L('says: The hour word '), "is not allowed in a YAML file"),
    ("yaml-tab-indent", TC, replace(L('polarity: select    '), "  polarity", "\tpolarity"), L('polarity: select    '), "not tabs"),
    # keys
    ("duplicate-key-top", TC, insert(L('manual: fx5-time-com'), "family: fx5-other"), L('manual: fx5-time-com'), "duplicate key 'family'"),
    ("duplicate-key-flow", TC, replace(L('- {name: hour, word:'), "max: 23,", "max: 23, max: 22,"), L('- {name: hour, word:'), "duplicate key 'max'"),
    ("unknown-key", TC, replace(L('- {name: hour, word:'), "clause: range.hour}", "clause: range.hour, unit: h}"), L('- {name: hour, word:'),
     "unknown key 'unit'"),
    ("unknown-top-key", TA, insert(L('kind: clock_add', 1), "commentary: none"), L('kind: clock_add', 1), "unknown key 'commentary'"),
    ("key-not-allowed-for-kind", TC, insert(L('logic: {interpretation: FX5-AND-OR-WHEN-OFF}', 1), "errors: {registers: {devices: [SD0]}, checks: []}"), L('logic: {interpretation: FX5-AND-OR-WHEN-OFF}', 1),
     "not allowed for this kind"),
    ("selector-in-clock-add", TA, insert(L('  order_clause: layout', 1), "selector: {operand: s1}"), L('  order_clause: layout', 1), "not allowed for this kind"),
    ("merge-key", TC, replace(L('- {name: minute, wor'), "{name: minute,", "{<<: {word: 1}, name: minute,"), L('- {name: minute, wor'), "merge keys"),
    # types and required values
    ("wrong-type-min", TC, replace(L('- {name: hour, word:'), "min: 0,", "min: zero,"), L('- {name: hour, word:'), "expected integer"),
    ("wrong-type-quoted-int", TA, replace(L('- {check: device_ran'), "code: 0x2820", 'code: "0x2820"'), L('- {check: device_ran'), "expected integer"),
    ("impossible-date", TC, insert(L('R: 32768'), "    checked: 2026-02-30"), L('R: 32768'), "bad value '2026-02-30'"),
    ("alternatives-set-different-parameters", TA, replace(L('- {id: set-only, say'), "sets: {written: set_only}", "sets: {written: set_only, extra: 1}"), L('- {id: set-only, say'),
     "alternatives must set the same parameters"),
    ("clause-without-source", TC, delete(L('source: {section: Processing details, quote: "Thes'), "source:"), L('- id: purpose'), "clauses.0: 'source' is required but missing"),
    ("source-without-quote", TC, replace(L('source: {section: La'), """, quote: '("=", "<>", ">", "<=", "<", ">=" enters □.)'}""", "}"), L('source: {section: La'),
     "'quote' is required but missing"),
    ("interpretation-quote-without-quote", TA, replace(L('- {section: Processing details, quote: "If the r'), ', quote: "If the result is 0 (0:00:00), the zero flag turns on."}', "}"), L('- {section: Processing details, quote: "If the r'),
     "'quote' is required but missing"),
    # field ranges and encodings
    ("field-min-greater-than-max", TC, replace(L('- {name: minute, wor'), "min: 0, max: 59", "min: 60, max: 59"), L('- {name: minute, wor'),
     "min 60 is greater than max 59"),
    ("signed16-range-too-large", TC, replace(L('- {name: hour, word:'), "max: 23", "max: 40000"), L('- {name: hour, word:'), "does not fit signed16"),
    ("bcd-range-too-large", CP, replace(L('- {name: year, word:'), "max: 99", "max: 100"), L('- {name: year, word:'), "does not fit bcd"),
    ("bcd-width-not-digits", CP, replace(L('- {name: day, word: '), "width: 8", "width: 6"), L('- {name: day, word: '), "width 6 is not a whole number of 4-bit BCD digits"),
    ("field-overlap-word", TC, replace(L('- {name: minute, wor'), "word: 1", "word: 0"), L('- {name: minute, wor'), "overlaps field 'hour'"),
    ("field-overlap-bits", CP, replace(L('- {name: month, word'), "lsb: 0", "lsb: 4"), L('- {name: month, word'), "overlaps field 'year'"),
    # references
    ("unknown-clause", TC, replace(L('- {name: hour, word:'), "clause: range.hour}", "clause: range.hours}"), L('- {name: hour, word:'),
     "unknown clause 'range.hours'"),
    ("unknown-clause-in-erratum", TA, replace(L('clause: carry'), "clause: carry", "clause: carry.flag"), L('clause: carry'),
     "unknown clause 'carry.flag'"),
    ("unknown-interpretation", TC, replace(L('scope: {interpretati'), "FX5-SM709-SCOPE", "FX5-SM709-SCOP"), L('scope: {interpretati'),
     "unknown interpretation 'FX5-SM709-SCOP'"),
    ("interpretation-default-not-alternative", TC, replace(L('default: selected-fi'), "default: selected-fields", "default: selected"),
     L('default: selected-fi'), "default 'selected' is not one of the alternatives"),
    ("alternative-does-not-set-parameter", TC, replace(L('- {id: all-words, sa'), "sets: {scope: all}", "sets: {scop: all}"), L('- {id: all-words, sa'),
     "does not set 'scope'"),
    ("duplicate-clause-id", TC, replace(L('- id: mnemonics'), "- id: mnemonics", "- id: purpose"), L('- id: mnemonics'), ("duplicate clause id 'purpose' (first used on line {})", L("- id: purpose"))),
    ("duplicate-interpretation-id", TA, replace(L('- id: TADD-EXACT-24'), "id: TADD-EXACT-24", "id: TADD-FLAGS-OFF"), L('- id: TADD-EXACT-24'),
     "duplicate interpretation id 'TADD-FLAGS-OFF'"),
    # selector bits
    ("selector-field-bit-is-reserved", TC, replace(L('reserved_bits: [3, 4'), "[3, 4,", "[2, 3, 4,"), L('reserved_bits: [3, 4'), "bit 2 is assigned twice"),
    ("selector-two-fields-one-bit", TC, replace(L('field_bits: {second:'), "minute: 1", "minute: 0"), L('field_bits: {second:'), "bit 0 is assigned twice"),
    ("selector-clock-bit-is-reserved", DC, replace(L('source_bit: {bit: 15'), "bit: 15,", "bit: 14,"), L('source_bit: {bit: 15'),
     ("bit 14 is assigned twice (current-clock bit here, reserved on line {})", L("reserved_bits: [3, 4, 5, 6, 7, 8, 9"))),
    # whole files
    ("empty-file", TC, whole(""), 1, "empty"),
    ("comments-only-file", TC, whole("# nothing here yet\n"), 1, "empty"),
    ("top-level-list", TC, whole("- family: fx5-time-compare\n- kind: masked_compare\n"), 1,
     "must be a mapping at the top level"),
    ("top-level-scalar", TC, whole("fx5-time-compare\n"), 1, "must be a mapping at the top level"),
    ("not-utf8", TC, latin1_line(L('says: The hour word '), "hour word", "hour wörd"), L('says: The hour word '), "not UTF-8"),
    ("same-family-in-two-files", TC, replace(L('family: fx5-time-com'), "family: fx5-time-compare", "family: fx5-date-compare"), L('family: fx5-time-com'),
     "also defined in fx5-date-compare.yaml"),
    # unsafe YAML: a Python tag is refused, never constructed
    ("python-object-tag-scalar", TC, replace(L('- {name: hour, word:'), "clause: range.hour}", "clause: !!python/object/apply:os.system [echo pwned]}"), L('- {name: hour, word:'),
     "not allowed"),
    ("python-name-tag", TC, replace(L('family: fx5-time-com'), "family: fx5-time-compare", "family: !!python/name:os.system"), L('family: fx5-time-com'),
     "not allowed"),
    ("python-object-tag-mapping", TC, replace(L('source: {section: Processing details, quote: "Thes'), "source: {", "source: !!python/object:plcvec.errors.SpecError {"), L('source: {section: Processing details, quote: "Thes'), "not allowed"),
    ("recursive-alias", TC, insert(L('device_sizes:'), "  loop: &a [*a]"), L('device_sizes:'), "alias"),
    # the coverage model
    ("model-unknown-derivation", TC, replace(L('- {id: form, derive:'), "derive: forms,", "derive: form,"), L('- {id: form, derive:'),
     "unknown derivation 'form' for kind masked_compare"),
    ("model-derivation-of-another-kind", TA, replace(L('- {id: sum, derive: '), "derive: sum,", "derive: conditions,"), L('- {id: sum, derive: '),
     "unknown derivation 'conditions' for kind clock_add"),
    ("model-derivation-needs-a-fact", CP, insert(L('- {id: ordering, der'), '      - {id: source, derive: source-bit, says: "Bit 15."}'), L('- {id: ordering, der'),
     "needs selector.source_bit"),
    ("model-when-names-later-dimension", TC, replace(L('- {id: logic, derive'), "when: {form: [AND, OR]}", "when: {condition: ['=']}"), L('- {id: logic, derive'),
     "depends on 'condition', which is not a dimension defined before it"),
    ("model-when-unknown-class", TC, replace(L('- {id: logic, derive'), "when: {form: [AND, OR]}", "when: {form: [AND, XOR]}"), L('- {id: logic, derive'),
     "'XOR' names no class of dimension 'form'"),
    ("model-product-unknown-dimension", TC, replace(L('- dimensions: [form,'), "[form, logic, condition, ordering]", "[form, logic, condition, order]"), L('- dimensions: [form,'),
     "unknown dimension 'order'"),
    ("model-product-class-unknown", TC, replace(L('classes: {ordering: [lt, eq, gt]}'), "[lt, eq, gt]", "[lt, eq, ge]"), L('classes: {ordering: [lt, eq, gt]}'),
     "'ge' names no class of dimension 'ordering'"),
    ("model-exclude-pattern-matches-nothing", TC, replace(L('- classes: {source: o'), '"dummy-*"', '"dummy-s3.*"'), L('- classes: {source: o'),
     "'dummy-s3.*' names no class of dimension 'data'"),
    ("model-unknown-strength", TC, replace(L('strength: pairwise'), "strength: pairwise", "strength: triples"), L('strength: pairwise'), "strength"),
    ("nonexistent-calendar-unknown-field", DC, replace(L('calendar: {year: yea'), "day: day}", "day: date}"), L('calendar: {year: yea'), "calendar day names no field 'date'"),
    ("model-duplicate-dimension", TC, replace(L('- {id: logic, derive'), "{id: logic,", "{id: form,"), L('- {id: logic, derive'), "dimension 'form' is defined twice"),
    # An alternative that leaves devices unjudged (HOUR-D1-OUT-OF-RANGE=undefined and its like).
    ("unjudged-unknown-operand", HM, replace(L('sets: {measured_invalid: undefined}'), "[D1, D2]", "[D1, D9]"),
     L('sets: {measured_invalid: undefined}'), "unknown operand 'D9'"),
    ("unjudged-unknown-flag", HM, replace(L('sets: {measured_invalid: undefined}'), "flags: [error]", "flags: [carry]"),
     L('sets: {measured_invalid: undefined}'), "unknown flag 'carry' (known: error)"),
    ("unjudged-without-undefined", HM, replace(L('sets: {measured_invalid: undefined}'), "measured_invalid: undefined}", "measured_invalid: error}"),
     L('sets: {measured_invalid: undefined}'), "leaves devices unjudged but sets no parameter to 'undefined'"),
    ("undefined-without-unjudged", HM, replace(L('sets: {constant_range: undefined}'), ", unjudged: {operands: [D1, D2], flags: [error]}", ""),
     L('sets: {constant_range: undefined}'), "sets 'undefined' but does not say which devices it leaves unjudged"),
    ("unjudged-default", HM, replace(L('    default: accepted'), "accepted", "undefined"), L('sets: {special_output: undefined}'),
     "the default of 'HOUR-D2-SPECIAL' leaves devices unjudged"),
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
    pristine = (folder / name).read_text(encoding="utf-8").split("\n")
    line = line(pristine) if isinstance(line, L) else line
    if isinstance(phrase, tuple):       # a message that names another line: (format, L)
        phrase = phrase[0].format(phrase[1](pristine))
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
    apply(folder, TC, replace(L("- {name: hour, word:"), "clause: range.hour}",
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
