"""`plcvec fuzz`: the reference implementation survives it, planted bugs (fuzz_planted.py) and the
reference's mutants are caught and shrunk to minimal vectors that are valid vector files, runs are
deterministic, harness errors exit 2.
"""
import contextlib
import io
import json
import shlex
import subprocess
import sys
from pathlib import Path

import jsonschema
import pytest

import fuzz_planted
from fuzz_planted import PLANTED

REPO = Path(__file__).resolve().parents[1]
PLANTED_FILE = Path(fuzz_planted.__file__).resolve()
REFERENCE = "plcvec_reference.adapter:ReferenceAdapter"
REFERENCE_CMD = f"{shlex.quote(sys.executable)} -m plcvec_reference.adapter"


def fuzz(capsys, *args):
    from plcvec.cli import main

    code = main(["fuzz", *map(str, args)])
    out, err = capsys.readouterr()
    return code, out, err


def planted(name):
    return f"{PLANTED_FILE}:{PLANTED[name].__name__}"


def planted_cmd(name):
    return f"{shlex.quote(sys.executable)} {shlex.quote(str(PLANTED_FILE))} {name}"


def single_vector(path):
    data = json.loads(Path(path).read_text())
    schema = json.loads((REPO / "vectors" / "schema" / "vector-file.schema.json").read_text())
    jsonschema.Draft202012Validator(schema).validate(data)
    assert data["count"] == len(data["vectors"]) == 1
    return data["vectors"][0]


# -- the reference survives ---------------------------------------------------------------------

def test_reference_in_process_survives(capsys):
    code, out, err = fuzz(capsys, "--python", REFERENCE, "--examples", 200)
    assert code == 0, out + err
    assert "no disagreement" in out and "200 examples" in out
    assert "examples/s" in err


def test_reference_over_stdio_survives(capsys):
    code, out, err = fuzz(capsys, "--adapter", REFERENCE_CMD, "--examples", 200, "--seed", 1)
    assert code == 0, out + err
    assert "200 examples" in out


def _non_default(families, every):
    """--choose options: the first non-default alternative of the first interpretation of each family,
    or (every=True) of every interpretation."""
    chosen = {}
    for fam in families.values():
        for interp in fam.doc["interpretations"][:None if every else 1]:
            chosen[interp["id"]] = next(a["id"] for a in interp["alternatives"] if a["id"] != interp["default"])
    return " ".join(f"--choose {i}={a}" for i, a in sorted(chosen.items()))


def test_declared_alternatives_are_followed(capsys, families):
    """The reference following a non-default alternative in every family still agrees: the expectation
    is the one of the alternatives the adapter declares in its handshake."""
    code, out, err = fuzz(capsys, "--adapter", f"{REFERENCE_CMD} {_non_default(families, every=False)}",
                          "--examples", 300)
    assert code == 0, out + err


def test_combined_alternatives_are_followed(capsys, families):
    """Found by fuzzing: vectors once held no expectation for two non-default alternatives together."""
    code, out, err = fuzz(capsys, "--adapter", f"{REFERENCE_CMD} {_non_default(families, every=True)}",
                          "--family", "fx5-time-add", "--examples", 300)
    assert code == 0, out + err


# -- planted bugs are caught and shrunk ---------------------------------------------------------

@pytest.fixture(scope="module")
def hour_as_minute(tmp_path_factory):
    """What `plcvec fuzz --seed 8` finds in the hour-as-minute planted bug, and the file --out writes:
    (code, out, err, file), for the test of the shrunk case and the test of the same seed, which read it
    and change nothing (a fuzz run with its shrinking is a second or more of CPU)."""
    return _fuzz_to_file(tmp_path_factory.mktemp("hour-as-minute") / "found.json", "--python",
                         planted("hour-as-minute"), "--examples", 1000, "--seed", 8, "--batch-size", 64)


def _fuzz_to_file(out_file, *args):
    """`plcvec fuzz ARGS --out OUT_FILE` in process, its output captured: (code, out, err, out_file)."""
    from plcvec.cli import main

    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(["fuzz", *map(str, args), "--out", str(out_file)])
    return code, out.getvalue(), err.getvalue(), out_file


def test_hour_read_as_minute_is_shrunk_to_small_values(hour_as_minute):
    code, out, err, out_file = hour_as_minute
    assert code == 1, out + err
    v = single_vector(out_file)
    assert v["family"] == "fx5-time-compare" and "fuzz" in v["tags"]
    assert v["id"] in out and "What differs" in out and "step 0 result" in out
    # Minimal: one scan, the data at most 1 apart, a plain selector (no reserved or clock bit)
    # that compares the hour, and the data in range.
    assert len(v["steps"]) == 1
    words = {k: w for k, w in v["initial"]["devices"].items() if k.startswith("D") and k != "D300"}
    assert all(w <= 1 for w in words.values()), words
    selector = v["initial"]["operands"]["s3"].get("constant", v["initial"]["devices"].get("D300"))
    assert selector & 0b100 and selector < 8
    assert "invalid-range" not in v["tags"]
    assert "fx5-time-compare#s3.bit.hour" in v["clauses"] and "fx5-time-compare#s3.bit.hour" in out


@pytest.fixture(scope="module")
def every_scan(tmp_path_factory):
    """What `plcvec fuzz` finds in the every-scan planted bug, and the file --out writes: (code, out, err,
    file), for the tests of the shrunk case and of the file, which read it and change nothing."""
    return _fuzz_to_file(tmp_path_factory.mktemp("every-scan") / "found.json", "--python",
                         planted("every-scan"), "--examples", 1000)


def test_pulse_form_on_every_scan_is_shrunk_to_two_scans(every_scan):
    code, out, err, out_file = every_scan
    assert code == 1, out + err
    v = single_vector(out_file)
    assert v["instruction"] == "TADDP"
    assert [s["en"] for s in v["steps"]] == [True, True]
    assert "same-device" in v["tags"]  # the only way a second addition shows without changing (s2)
    values = [w for k, w in v["initial"]["devices"].items() if k[:1] == "D" and isinstance(w, int)]
    assert sorted(values)[-1] == 1 and sum(values) == 1
    assert "fx5-time-add#pulse" in v["clauses"]


def test_the_printed_vector_is_ready_to_run(every_scan):
    """The file --out writes runs under `plcvec verify`: it fails the buggy adapter and the reference
    passes it, so it is a regression test as it stands."""
    code, _, _, out_file = every_scan
    assert code == 1
    from plcvec.cli import main

    assert main(["verify", "--vectors", str(out_file), "--python", planted("every-scan"), "-q"]) == 1
    assert main(["verify", "--vectors", str(out_file), "--python", REFERENCE, "-q"]) == 0


def test_a_crash_is_a_disagreement(capsys):
    code, out, err = fuzz(capsys, "--python", f"{PLANTED_FILE}:CrashOnConstantPreset", "--family", "fc6a-hour-meter",
                          "--examples", 500)
    assert code == 1, out + err
    assert "raised RuntimeError: constant presets are not supported" in out
    assert '"S1": {"constant": 0}' in out   # the smallest constant


@pytest.mark.slow   # a process restart per case that kills it; by default: the crash in process, above
def test_a_dying_process_is_a_disagreement(capsys):
    """Each case that kills the adapter process costs a restart, during the search and the shrinking.
    The default run takes the same disagreement and shrinking in process (test_a_crash_is_a_disagreement)
    and an adapter's death before it answers under `plcvec verify` (test_verify_faults.py)."""
    code, out, err = fuzz(capsys, "--adapter", planted_cmd("exit-on-constant-preset"), "--family", "fc6a-hour-meter",
                          "--examples", 500)
    assert code == 1, out + err
    assert "the adapter exited with status 3 before answering" in out
    assert '"S1": {"constant": 0}' in out


def test_instruction_filter(capsys):
    code, out, err = fuzz(capsys, "--python", planted("hour-as-minute"), "--instruction", "LDTM<",
                          "--examples", 1000)
    assert code == 1, out + err
    assert "/LDTM</fuzz/" in out
    code, out, err = fuzz(capsys, "--python", planted("hour-as-minute"), "--family", "fx5-date-compare",
                          "--examples", 300)
    assert code == 0, out + err


@pytest.mark.parametrize("mutant, tag", [
    ("cp1e-bcd-read-as-binary", "invalid-range"),    # needs raw words no value encodes (a nibble above 9)
    ("fx5-device-range-unchecked", "device-range"),  # needs an operand at the top of its device range
    ("tadd-no-wrap-at-24", "wrap"),                  # needs a sum of exactly 24:00:00
    ("hour-output-above-preset", None),              # needs D1 to land exactly on the preset
])
def test_widened_draws_catch_the_mutants_they_are_for(capsys, tmp_path, mutant, tag):
    """Each of these single-bug mutants of the reference needs a case independent draws from the
    ranges almost never give; the draws tied to the spec's boundaries find each in a few hundred."""
    out_file = tmp_path / "found.json"
    code, out, err = fuzz(capsys, "--adapter", f"{REFERENCE_CMD} --mutant {mutant}", "--examples", 500,
                          "--out", out_file)
    assert code == 1, out + err
    v = single_vector(out_file)
    assert tag is None or tag in v["tags"], v["tags"]


# -- deterministic ------------------------------------------------------------------------------

def test_same_seed_same_output(hour_as_minute, tmp_path):
    """The same seed finds and prints the same case, whatever the batch size (how many cases go to a
    request, not what is found): the run of hour_as_minute (64 a batch) again with 7 a batch."""
    code, out, _, out_file = hour_as_minute
    again = _fuzz_to_file(tmp_path / "found.json", "--python", planted("hour-as-minute"), "--examples", 1000,
                          "--seed", 8, "--batch-size", 7)
    assert code == again[0] == 1
    assert again[1].replace(str(again[3]), "FILE") == out.replace(str(out_file), "FILE")
    assert again[3].read_bytes() == out_file.read_bytes()


@pytest.mark.slow   # a second whole fuzz run in a fresh process; beside it by default: the stdio path
                    # (test_reference_over_stdio_survives) and the same output for the same seed
def test_stdio_prints_what_in_process_prints(capsys):
    """The same seed through a process gives the same bytes as in process: the fuzzer in a fresh
    process of its own (so nothing depends on what this one has imported), its adapter over stdio."""
    in_process = fuzz(capsys, "--python", planted("every-scan"), "--examples", 1000, "--seed", 5)
    assert in_process[0] == 1
    over_stdio = subprocess.run([sys.executable, "-m", "plcvec", "fuzz", "--adapter", planted_cmd("every-scan"),
                                 "--examples", "1000", "--seed", "5"], capture_output=True, text=True, cwd=REPO,
                                timeout=600)
    assert over_stdio.returncode == 1 and over_stdio.stdout == in_process[1]


# -- harness and usage errors -------------------------------------------------------------------

def test_bad_adapter_command_exits_2(capsys):
    code, out, err = fuzz(capsys, "--adapter", "/nonexistent/emulator --plcvec", "--examples", 10)
    assert code == 2
    assert err.strip().count("\n") == 0 and "cannot start it" in err and "Traceback" not in err


def test_adapter_dying_in_the_handshake_exits_2(capsys):
    code, out, err = fuzz(capsys, "--adapter", f"{shlex.quote(sys.executable)} -c 'import sys; sys.exit(3)'",
                          "--examples", 10)
    assert code == 2
    assert "no handshake" in err and "status 3" in err and "Traceback" not in err


def test_usage_errors_exit_2(capsys):
    assert fuzz(capsys, "--python", REFERENCE, "--family", "no-such-family")[0] == 2
    assert fuzz(capsys, "--python", REFERENCE, "--instruction", "NOPE")[0] == 2
    code, _, err = fuzz(capsys, "--python", REFERENCE, "--examples", 0)
    assert code == 2 and "--examples" in err
    code, _, err = fuzz(capsys, "--python", "no_such_module:Adapter")
    assert code == 2 and "cannot import" in err

