"""The protocol's messages: the schemas themselves, the transcript in PROTOCOL.md, and the cheap
check the runner uses for result messages, which must never accept what the schema rejects."""
import json
import re
import subprocess
import sys

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from plcvec_verify import Suite
from plcvec_verify.expect import request_of
from plcvec_verify.protocol import PROTOCOL_VERSION, SCHEMAS, hello_request, result_looks_valid, schema_errors, validator

from conftest import REPO

PROTOCOL_MD = REPO / "verifiers" / "PROTOCOL.md"

# Values near every boundary the schema draws: JSON types, word range, empty strings, extra keys.
scalars = st.one_of(st.booleans(), st.integers(-2, 2), st.integers(65534, 65537), st.just(1.0), st.just(1.5),
                    st.none(), st.just(""), st.text(max_size=3))
devices = st.dictionaries(st.one_of(st.just(""), st.sampled_from(["D100", "SM709", "P_EQ"])), scalars, max_size=3)
steps = st.lists(st.fixed_dictionaries({}, optional={"devices": st.one_of(devices, scalars),
                                                     "result": scalars, "extra": scalars}), max_size=2)
messages = st.fixed_dictionaries({}, optional={
    "type": st.sampled_from(["result", "hello", "Result"]), "id": st.one_of(st.text(max_size=2), st.integers()),
    "steps": st.one_of(steps, scalars), "skip": scalars, "error": scalars, "extra": scalars})


def drawn(given_test, examples, **options):
    """Two tests of one property (a @given function): drawn `examples` times, marked slow (CI runs it), and
    a tenth as often for the default run."""
    def with_draws(n):
        return settings(max_examples=n, suppress_health_check=[HealthCheck.too_slow], database=None,
                        derandomize=True, **options)(given_test())
    return pytest.mark.slow(with_draws(examples)), with_draws(examples // 10)


def cheap_check_never_accepts_what_the_schema_rejects():
    @given(messages)
    def check(msg):
        if result_looks_valid(msg):
            assert schema_errors("result", msg) == [], msg
    return check


test_cheap_check_never_accepts_what_the_schema_rejects, test_cheap_check_never_accepts_what_the_schema_rejects_sample \
    = drawn(cheap_check_never_accepts_what_the_schema_rejects, 3000)


def test_cheap_check_accepts_the_usual_answers():
    ok = {"type": "result", "id": "x", "steps": [{"result": True, "devices": {"D100": 65535, "SM709": False}}]}
    assert result_looks_valid(ok) and not schema_errors("result", ok)
    assert result_looks_valid({"type": "result", "id": "x", "skip": "no TADDP"})
    for bad in ({"type": "result", "id": "x", "steps": [{"devices": {"D100": 65536}}]},
                {"type": "result", "id": "x", "steps": [{"devices": {"D100": 1}, "result": 1}]},
                {"type": "result", "id": "x", "skip": "a", "error": "b"},
                {"type": "result", "id": "x"}):
        assert not result_looks_valid(bad) and schema_errors("result", bad), bad


def test_every_schema_is_a_valid_json_schema():
    for name in SCHEMAS:
        validator(name)   # check_schema raises on a broken schema


def _one_of_each_kind(vectors):
    """The first vector of each family, instruction, set of tags and outcome category: every shape a
    request takes, in about one vector of seven (schema validation is what costs here)."""
    kinds = {}
    for v in vectors:
        kinds.setdefault((v["family"], v["instruction"], tuple(sorted(v["tags"])), v["outcome"]["category"]), v)
    return list(kinds.values())


@pytest.mark.parametrize("pick", [pytest.param(list, id="every-vector", marks=pytest.mark.slow),
                                  pytest.param(_one_of_each_kind, id="one-of-each-kind")])
def test_requests_and_hello_match_their_schemas(pick):
    suite = Suite.load(REPO / "vectors")
    assert schema_errors("hello-request", hello_request(suite, sorted(suite.headers))) == []
    batch = {"type": "run", "batch": 0, "vectors": [request_of(v) for v in pick(suite.vectors)]}
    assert len(batch["vectors"]) > 100
    assert schema_errors("run-request", batch) == []


def _transcript():
    """The `>` (runner) and `<` (adapter) lines of the worked transcript in PROTOCOL.md."""
    text = PROTOCOL_MD.read_text()
    block = re.search(r"<!-- transcript -->\n```\n(.*?)```", text, re.S).group(1)
    return [(line[0], json.loads(line[2:])) for line in block.splitlines() if line[:2] in ("> ", "< ")]


def test_the_documented_transcript_is_valid_and_is_what_the_reference_answers():
    lines = _transcript()
    kinds = {"hello": ("hello-request", "hello-response"), "run": ("run-request", None), "result": (None, "result"),
             "bye": ("bye", None)}
    for direction, msg in lines:
        schema = kinds[msg["type"]][0 if direction == ">" else 1]
        assert schema and schema_errors(schema, msg) == [], (direction, msg)
    # Replaying the runner's lines to the reference adapter gives the adapter's lines.
    sent = "".join(json.dumps(m) + "\n" for d, m in lines if d == ">")
    proc = subprocess.run([sys.executable, "-m", "plcvec_reference.adapter"], input=sent, capture_output=True,
                          text=True, timeout=60)
    got = [json.loads(x) for x in proc.stdout.splitlines()]
    assert got == [m for d, m in lines if d == "<"]
    assert proc.returncode == 0 and lines[0][1]["protocol"] == PROTOCOL_VERSION


def an_answer_the_comparison_accepts_is_valid_against_the_schema():
    """The runner validates fully only answers that differ; so an accepted answer must be valid."""
    @given(data=st.data())
    def check(data):
        from plcvec_verify.compare import compare
        from plcvec_verify.expect import expected_of
        from plcvec_verify.protocol import result_shape_ok

        suite = _suite()
        v = data.draw(_sampled_vectors(suite))
        exp = expected_of(v, {}, {})
        steps = []
        for state, result in zip(exp.states, exp.results):
            devices = {k: data.draw(_kept_or_scalar(val)) for k, val in state.items()}
            step = {"devices": devices}
            if result is not None:
                step["result"] = data.draw(_kept_or_scalar(result))
            steps.append(step)
        msg = {"type": "result", "id": v["id"], "steps": steps}
        if result_shape_ok(msg) and compare(exp, steps) == []:
            assert schema_errors("result", msg) == [], msg
    return check


# deadline=None: the first example loads the vector set; time is not what is tested.
test_an_answer_the_comparison_accepts_is_valid_against_the_schema, \
    test_an_answer_the_comparison_accepts_is_valid_against_the_schema_sample \
    = drawn(an_answer_the_comparison_accepts_is_valid_against_the_schema, 1500, deadline=None)


_SUITE = []
_STRATEGIES = {}


def _kept_or_scalar(value):
    """The expected value itself or any scalar: one strategy object per value, made once.

    Hypothesis validates and labels each new strategy object when it is first drawn from, which
    cost most of this test's time when a fresh one was built for every device of every example;
    a kept object draws from the same definition. (The key holds the type: True == 1, but they
    are different answers.)"""
    key = (type(value), value)
    if key not in _STRATEGIES:
        _STRATEGIES[key] = st.one_of(st.just(value), scalars)
    return _STRATEGIES[key]


def _sampled_vectors(suite):
    """Every 37th vector of the set, the same strategy object for every example."""
    if "vectors" not in _STRATEGIES:
        _STRATEGIES["vectors"] = st.sampled_from(suite.vectors[:: 37])
    return _STRATEGIES["vectors"]


def _suite():
    if not _SUITE:
        _SUITE.append(Suite.load(REPO / "vectors"))
    return _SUITE[0]
