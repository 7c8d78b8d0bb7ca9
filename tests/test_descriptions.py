"""A vector's description says what the vector shows; where it names the state of a device in words
("D2 stays off", "the error flag turns on", "a normal execution leaves it as it is"), that state is
the one the vector's own expectation (its defaults: `steps` and `final`) holds.

Each reader below reads one kind of sentence and checks it against the default expectation. A
description that uses the words of a state (turns, stays, keeps, reached ...) outside every reader's
sentence fails too: a new way of saying it needs a reader, not silence.
"""
import re

import pytest

from plcvec.spec.flags import flag_groups

# Words that say what happens to a device; each occurrence must lie in a sentence a reader reads.
STATE_WORDS = re.compile(r"\b(turns?|stays?|keeps?|keep measuring|leaves it|nothing is written|still measured|reached|reaches)\b")
# What generated descriptions say that is not a claim about the vector's expectation.
NOT_CLAIMS = ("Coverage model row:", "found by `plcvec fuzz")
ORDINALS = {"first": 0, "second": 1, "third": 2, "fourth": 3, "fifth": 4, "sixth": 5}
HMS = ("D200", "D201", "D202")


class Vector:
    """One vector's default expectation, as states after each step."""

    def __init__(self, v, error_device):
        self.v = v
        self.error_device = error_device
        state = dict(v["initial"]["devices"])
        self.initial = dict(state)
        self.before, self.after = [], []
        for step in v["steps"]:
            state.update(step.get("set") or {})
            self.before.append(dict(state))
            state.update(step["expect"]["devices"])
            self.after.append(dict(state))
        assert self.after[-1].items() >= v["final"]["devices"].items()

    def device(self, subject):
        """The device a subject of a sentence names: an operand, the error flag, or a device by name."""
        operands = self.v["initial"]["operands"]
        if subject in ("D2", "the output"):
            return operands["D2"]["device"]
        if subject.endswith("error flag"):
            return self.error_device
        return subject

    def measured(self):
        """The seconds D1 holds after each step (the HOUR family's D1 at D200)."""
        d1 = self.v["initial"]["operands"]["D1"]["device"]
        assert d1 == HMS[0]
        return [s[HMS[0]] * 3600 + s[HMS[1]] * 60 + s[HMS[2]] for s in self.after]

    def first_on(self, device):
        return next((k for k, s in enumerate(self.after) if s[device] is True), None)


def _stays(vec, m):
    device, want = vec.device(m["subj"]), m["state"] == "on"
    states = [vec.before[0][device]] + [s[device] for s in vec.after]
    return [] if all(x is want for x in states) else [f"{device} is not {m['state']} throughout: {states}"]


def _turns(vec, m):
    device, want = vec.device(m["subj"]), m["state"] == "on"
    turned = [k for k, (b, a) in enumerate(zip(vec.before, vec.after)) if b[device] is not want and a[device] is want]
    if not turned or vec.after[-1][device] is not want:
        return [f"{device} never turns {m['state']} to stay so: {[s[device] for s in vec.after]}"]
    return []


def _turns_first(vec, m):
    device = vec.device(m["subj"])
    return [] if vec.before[0][device] is False and vec.after[0][device] is True else [f"{device} is not turned on by step 0"]


def _listed_state(vec, m):
    device, want = vec.device(m["subj"]), m["state"] == "on"
    return [] if vec.after[-1][device] is want else [f"{device} is not {m['state']} at the end"]


def _still_measured(vec, m):
    unchanged = [k for k, (b, a) in enumerate(zip(vec.before, vec.after)) if all(b[d] == a[d] for d in HMS)]
    return [f"D1 does not change at steps {unchanged}"] if unchanged else []


def _reached_at(vec, m):
    d2 = vec.device("D2")
    want = ORDINALS[m["ord"]]
    return [] if vec.first_on(d2) == want else [f"D2 first on at step {vec.first_on(d2)}, not {want}"]


def _reached_when(vec, m):
    """D2 on exactly at the steps after which D1 holds at least the threshold."""
    threshold = int(m["n"]) + (int(m["h"]) * 3600 + int(m["mi"]) * 60 + int(m["s"]) if m["h"] else 0)
    d2 = vec.device("D2")
    got = [s[d2] for s in vec.after]
    want = [t >= threshold for t in vec.measured()]
    return [] if got == want else [f"D2 after each step {got}, but D1 reaches {threshold} s at {want}"]


def _new_cycle(vec, m):
    return [] if vec.after[-1][vec.device("D2")] is True else ["D2 is not on at the end"]


def _keep_measuring(vec, m):
    seconds = vec.measured()
    wrapped = any(b > a for b, a in zip(seconds, seconds[1:]))
    problems = [] if vec.after[-1][vec.device("D2")] is True else ["D2 is not on at the end"]
    return problems + ([] if wrapped and seconds[-1] > 0 else [f"D1 does not wrap and go on: {seconds}"])


def _check_again(vec, m):
    k, device = ORDINALS[m["ord"]], vec.error_device
    if vec.before[k][device] is False and vec.after[k][device] is True:
        return []
    return [f"{device} before step {k} {vec.before[k][device]}, after it {vec.after[k][device]}"]


def _program_turns_off(vec, m):
    device = vec.device(m["subj"])
    steps = [ORDINALS[m["ord"]]] if m["ord"] else range(len(vec.v["steps"]))
    ok = any((vec.v["steps"][k].get("set") or {}).get(device) is False for k in steps)
    return [] if ok else [f"no step's set turns {device} off"]


def _already_on(vec, m):
    device = m["subj"]
    want = m["what"] == "leaves it as it is"
    if vec.initial[device] is not True:
        return [f"{device} is not on initially"]
    return [] if vec.after[0][device] is want else [f"{device} is {vec.after[0][device]} after the execution"]


def _stays_as_it_was(vec, m):
    device = vec.error_device
    return [] if vec.after[-1][device] == vec.before[-1][device] else [f"the last step changes {device}"]


def _keep_code(vec, m):
    code = int(m["code"], 16)
    return [f"{d} does not hold {m['code']}H before and after" for d in (m["a"], m["b"])
            if not vec.initial[d] == vec.after[-1][d] == code]


def _nothing_written(vec, m):
    steps = vec.v["steps"]
    written = [k for k, s in enumerate(steps) if s["expect"]["devices"] or s.get("en") is not False]
    return [f"steps {written} have EN on or write devices"] if written else []


def _already_reached(vec, m):
    """The step that writes a valid preset (its `set`) turns D2 on: D1 is past it already."""
    d2 = vec.device("D2")
    k = next(k for k, step in enumerate(vec.v["steps"]) if step.get("set"))
    return [] if vec.before[k][d2] is False and vec.after[k][d2] is True else [f"D2 is not turned on by step {k}"]


def _not_a_claim(vec, m):
    return []


SUBJECT = r"(?P<subj>D2|the output|(?:the )?error flag|\b(?!EN\b)[A-Z][A-Z_]*\d*)"
READERS = [
    (re.compile(SUBJECT + r" stays (?P<state>on|off)"), _stays),
    (re.compile(r"(?:first execution|one scan) turns (?P<subj>the output|D2) on"), _turns_first),
    (re.compile(SUBJECT + r" turns (?P<state>on|off)"), _turns),
    (re.compile(r"(?:: |, )(?P<subj>D2|(?:the )?error flag) (?P<state>on|off)(?=,|\.|$)"), _listed_state),
    (re.compile(r"D1 still measured"), _still_measured),
    (re.compile(r"it turns on when the preset of (?P<n>\d+) s is reached()(?P<h>)(?P<mi>)(?P<s>)"), _reached_when),
    (re.compile(r"the preset of \d+ s is reached at the (?P<ord>\w+)"), _reached_at),
    (re.compile(r"reached only at (?P<n>\d+) s(?P<h>)(?P<mi>)(?P<s>)"), _reached_when),
    (re.compile(r"reached after (?P<n>\d+) s from (?P<h>\d+):(?P<mi>\d\d):(?P<s>\d\d)"), _reached_when),
    (re.compile(r"which reaches the preset of [\d:]+ in the new cycle"), _new_cycle),
    (re.compile(r"Reach the largest preset, wrap, and keep measuring"), _keep_measuring),
    (re.compile(r"the (?P<ord>second|third) check turns (?:it|the error flag) on again"), _check_again),
    (re.compile(r"the program turns " + SUBJECT + r" off(?: before the (?P<ord>second|third))?"), _program_turns_off),
    (re.compile(r"(?P<subj>[A-Z][A-Z_]*\d*) is already on and the data are valid: a normal execution "
                r"(?P<what>leaves it as it is|turns it off)"), _already_on),
    (re.compile(r"the error flag stays as it was"), _stays_as_it_was),
    (re.compile(r"then a valid one already reached"), _already_reached),
    (re.compile(r"(?P<a>SD\d+), (?P<b>SD\d+) hold (?P<code>[0-9A-F]+)H from an earlier error; a valid addition "
                r"stores no error code, so they keep it"), _keep_code),
    (re.compile(r"EN stays off: nothing is written"), _nothing_written),
    (re.compile(r"whether it stays on until cleared is the spec's latch rule for this flag"), _not_a_claim),
]


def read(vec):
    """(problems, the spans of the description some reader read)."""
    text, problems, spans = vec.v["description"], [], []
    for pattern, check in READERS:
        for m in pattern.finditer(text):
            spans.append(m.span())
            problems += [f"{vec.v['id']}: {m.group(0)!r}: {p}" for p in check(vec, m)]
    return problems, spans


def _vectors(golden, families):
    for name, data in sorted(golden.items()):
        error = next(g["devices"][0] for g in flag_groups(families[name].doc) if g["name"] in ("error", "error code"))
        for v in data["vectors"]:
            if not v["description"].startswith(NOT_CLAIMS) and NOT_CLAIMS[1] not in v["description"]:
                yield Vector(v, error)


def test_every_description_that_names_a_device_state_agrees_with_the_default_expectation(golden, families):
    problems, unread, read_any = [], [], 0
    for vec in _vectors(golden, families):
        found, spans = read(vec)
        problems += found
        read_any += bool(spans)
        for m in STATE_WORDS.finditer(vec.v["description"]):
            if not any(a <= m.start() < b for a, b in spans):
                unread.append(f"{vec.v['id']}: {m.group(0)!r} in {vec.v['description']!r}")
    assert not unread, "state words no reader reads (add a reader):\n" + "\n".join(unread[:10])
    assert not problems, "\n".join(problems[:20])
    assert read_any >= 40   # the readers do read the golden set's descriptions


def test_each_reader_reads_some_vector(golden, families):
    used = set()
    for vec in _vectors(golden, families):
        for k, (pattern, _) in enumerate(READERS):
            if pattern.search(vec.v["description"]):
                used.add(k)
    assert used == set(range(len(READERS))), [READERS[k][0].pattern for k in set(range(len(READERS))) - used]


@pytest.mark.parametrize("description, wrong", [
    ("P_ER is already on and the data are valid: a normal execution leaves it as it is.", "after the execution"),
    ("Preset minute = 60 (over 59) before D2 turned on: error flag off, D1 still measured, D2 stays on.", "not"),
])
def test_a_description_that_disagrees_is_found(description, wrong, golden, families):
    """The readers catch the known disagreement (CP1E's P_ER, which its default turns off) and a
    description turned around."""
    ids = {"P_ER": "cp1e-time-compare/LD =DT/latch/already-on-valid-data",
           "Preset": "fc6a-hour-meter/HOUR/invalid-preset/minute=60/before-output"}
    vid = ids[description.split(" ", 1)[0]]
    vec = next(x for x in _vectors(golden, families) if x.v["id"] == vid)
    vec.v = dict(vec.v, description=description)
    problems, _ = read(vec)
    assert problems and all(wrong in p for p in problems), problems
