"""The quick check of a document against a JSON Schema (plcvec_verify/quick_schema.py) gives
jsonschema's answer to "valid?": on the committed vector files, on many damaged copies of their
vectors and of the protocol's messages, keyword by keyword; a schema it cannot read in full is left
to jsonschema."""
import copy
import json
import random

import jsonschema
import pytest

from plcvec_verify.protocol import PROTOCOL_VERSION, message_errors, quick_check, schema_errors
from plcvec_verify.quick_schema import compile_schema, json_equal

from conftest import REPO

SCHEMA = json.loads((REPO / "vectors" / "schema" / "vector-file.schema.json").read_text(encoding="utf-8"))
FILES = sorted((REPO / "vectors").glob("*.json"))
FAMILY_FILES = [p for p in FILES if p.name != "manifest.json"]


@pytest.fixture(scope="module")
def quick():
    check = compile_schema(SCHEMA)
    assert check is not None, "the vector-file schema uses a keyword the quick check does not know"
    return check


@pytest.fixture(scope="module")
def judge():
    return jsonschema.validators.validator_for(SCHEMA)(SCHEMA)


@pytest.mark.parametrize("path", FAMILY_FILES, ids=lambda p: p.stem)
def test_every_committed_file_is_shown_valid(path, quick):
    assert quick(json.loads(path.read_text(encoding="utf-8")))


# Values a damaged file may hold where another was: each JSON type, the edges of a word, a float
# JSON Schema calls an integer (1.0) and ones it does not, a bool where an integer goes.
ODD_VALUES = [None, True, False, 0, 1, -1, 65535, 65536, 1.0, 65535.0, 0.5, float("nan"), "", "D100", "x", [], [1], {}, {"a": 1},
              {"device": "D100"}, {"constant": 5}, {"device": "D-1"}, "value", "error", 2 ** 70]


def _places(node, path=()):
    """Every (container, key) in a JSON tree."""
    if isinstance(node, dict):
        for k, v in node.items():
            yield node, k
            yield from _places(v, path + (k,))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield node, i
            yield from _places(v, path + (i,))


def _damaged(doc, rng):
    """A copy of `doc` with one thing changed: a value replaced, a key removed or added, an item doubled."""
    doc = copy.deepcopy(doc)
    container, key = rng.choice(list(_places(doc)))
    how = rng.randrange(4)
    if how == 0 or (how == 1 and isinstance(container, list)):
        container[key] = copy.deepcopy(rng.choice(ODD_VALUES))
    elif how == 1:
        del container[key]
    elif how == 2 and isinstance(container, dict):
        container[rng.choice(["surprise", "D7", "constant", "device", "skip", "$ref"])] = rng.choice(ODD_VALUES)
    else:
        target = container[key]
        if isinstance(target, list) and target:
            target.append(copy.deepcopy(target[0]))
        else:
            container[key] = [target]
    return doc


def _one_vector_files(count, rng):
    """`count` files of one vector each, drawn from every family's committed file."""
    families = [json.loads(p.read_text(encoding="utf-8")) for p in FAMILY_FILES]
    for _ in range(count):
        data = rng.choice(families)
        yield {**{k: v for k, v in data.items() if k != "vectors"}, "vectors": [rng.choice(data["vectors"])]}


@pytest.mark.parametrize("count", [400, pytest.param(1500, marks=pytest.mark.slow)])
def test_the_same_answer_as_jsonschema_on_damaged_vectors(count, quick, judge):
    rng = random.Random(count)
    shown_valid = refused = 0
    for doc in _one_vector_files(count, rng):
        damaged = _damaged(doc, rng)
        # The same answer as jsonschema, both ways (jsonschema still judges every "no", in validate.py).
        assert quick(damaged) is judge.is_valid(damaged), json.dumps(damaged)[:2000]
        if quick(damaged):
            shown_valid += 1
        else:
            refused += 1
    # Neither side empty: damage the schema allows (a word changed within range) and damage it refuses.
    assert shown_valid > count // 10 and refused > count // 10, (shown_valid, refused)


@pytest.mark.parametrize("a, b, equal", [
    (True, 1, False), (False, 0, False), (1, 1.0, True), ([1, True], [1, True], True), ([1], [True], False),
    ({"a": 1}, {"a": 1.0}, True), ({"a": 1}, {"b": 1}, False), ("1", 1, False), (None, False, False),
])
def test_equality_is_json_schemas(a, b, equal):
    assert json_equal(a, b) is equal


@pytest.mark.parametrize("schema, instance, valid", [
    ({"type": "integer"}, True, False),                 # a bool is no integer in JSON
    ({"type": "integer"}, 1.0, True),                   # and 1.0 is one in JSON Schema
    ({"type": "integer"}, float("inf"), False),
    ({"minimum": 0}, float("nan"), True),               # as jsonschema words a bound: `instance < minimum`
    ({"const": 1}, True, False),
    ({"const": 1}, 1.0, True),
    ({"enum": [0, "x"]}, False, False),
    ({"uniqueItems": True}, [1, True], True),
    ({"uniqueItems": True}, [1, 1.0], False),
    ({"oneOf": [{"type": "integer"}, {"minimum": 0}]}, 5, False),   # two branches hold: not one of
    ({"oneOf": [{"type": "integer"}, {"type": "boolean"}]}, True, True),
    ({"oneOf": [{"type": "integer"}, {"type": "number"}]}, 1.0, False),    # a stricter branch would pass it
    ({"not": {"type": "integer"}}, 1.0, False),
    ({"if": {"type": "integer"}, "then": {"minimum": 5}}, 1.0, False),
    ({"if": {"properties": {"k": {"const": "error"}}}, "then": {"required": ["errors"]}}, {"k": "error"}, False),
    ({"if": {"properties": {"k": {"const": "error"}}}, "then": {"required": ["errors"]}}, {"k": "value"}, True),
    ({"properties": {"a": {"type": "string"}}, "additionalProperties": False}, {"a": "x", "b": 1}, False),
    ({"propertyNames": {"pattern": "^[A-Z]+[0-9]+$"}}, {"D1": 0, "d-1": 0}, False),
    ({"pattern": "^D[0-9]+$"}, "D12", True),
    ({"minimum": 0}, "not a number", True),             # a keyword applies to its own type only
    ({"allOf": [{"maxItems": 2}, {"minItems": 1}]}, [1, 2, 3], False),
    ({"anyOf": [{"maxProperties": 0}, {"required": ["a"]}]}, {"a": 1}, True),
    ({"maxLength": 2}, "abc", False),
    ({"$ref": "#/$defs/w", "$defs": {"w": {"maximum": 65535}}}, 65536, False),
])
def test_each_keyword_as_jsonschema_checks_it(schema, instance, valid):
    check = compile_schema(schema)
    assert check is not None and check(instance) is valid
    assert jsonschema.Draft202012Validator(schema).is_valid(instance) is valid


@pytest.mark.parametrize("schema", [
    {"format": "date"}, {"dependentRequired": {"a": ["b"]}}, {"$ref": "other.json#/x"}, {"$ref": "#/$defs/missing"},
    {"if": {"type": "string"}, "else": {"minimum": 0}}, {"items": [{"type": "string"}]}, {"type": "strnig"},
    {"patternProperties": {"^x": {}}, "additionalProperties": False},
])
def test_a_schema_it_cannot_read_in_full_is_left_to_jsonschema(schema):
    assert compile_schema(schema) is None


# -- the protocol's messages (plcvec_verify/protocol.py: message_errors) ------------------------------

def _real_messages():
    """The reference's handshake answer, as serve.py sends it, and results of vectors of each family."""
    from plcvec_reference.adapter import ReferenceAdapter
    from plcvec_verify import Suite
    from plcvec_verify.protocol import hello_request
    from plcvec_verify.vector import request_of

    suite = Suite.load(REPO / "vectors")
    adapter = ReferenceAdapter()
    hello = {"type": "hello", "protocol": PROTOCOL_VERSION,
             **adapter.hello(hello_request(suite, sorted(suite.headers))),
             "cpu_writes": ["SM8020"]}
    firsts = {v["family"]: v for v in reversed(suite.vectors)}
    results = []
    for v in firsts.values():
        answer = adapter.run(request_of(v))
        results.append({"type": "result", "id": v["id"], **answer})
    return hello, results


@pytest.mark.parametrize("name", ["hello-response", "result", "bye", "fatal"])
def test_the_messages_of_every_run_have_a_quick_check(name):
    assert quick_check(name) is not None


def test_the_quick_check_of_a_message_gives_jsonschemas_answer():
    hello, results = _real_messages()
    assert message_errors("hello-response", hello) == [] == schema_errors("hello-response", hello)
    assert len(results) == 5 and all(quick_check("result")(r) and not schema_errors("result", r) for r in results)
    rng = random.Random(5)
    shown_valid = 0
    for name, message in [("hello-response", hello)] * 150 + [("result", r) for r in results] * 50:
        damaged = _damaged(message, rng)
        assert quick_check(name)(damaged) is (schema_errors(name, damaged) == []), (name, damaged)
        if quick_check(name)(damaged):
            shown_valid += 1
        assert message_errors(name, damaged) == schema_errors(name, damaged)
    assert shown_valid > 40, shown_valid


# -- the spec's schema (generator/plcvec/spec/loader.py) ----------------------------------------------

@pytest.mark.parametrize("count", [50, pytest.param(200, marks=pytest.mark.slow)])
def test_the_quick_check_of_a_spec_file_gives_jsonschemas_answer(count):
    import yaml

    from plcvec.spec.files import schema_path

    schema = json.loads(schema_path("spec.schema.json").read_text(encoding="utf-8"))
    quick, judge = compile_schema(schema), jsonschema.Draft202012Validator(schema)
    assert quick is not None, "the spec schema uses a keyword the quick check does not know"
    docs = [yaml.safe_load(p.read_text(encoding="utf-8")) for p in sorted((REPO / "spec").glob("*.yaml"))]
    assert docs and all(quick(d) and judge.is_valid(d) for d in docs)
    rng = random.Random(7)
    refused = 0
    for _ in range(count):
        damaged = _damaged(rng.choice(docs), rng)
        assert quick(damaged) is judge.is_valid(damaged), json.dumps(damaged, default=str)[:2000]
        refused += not quick(damaged)
    assert refused > count // 10, refused
