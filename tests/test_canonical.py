"""The canonical JSON writer: its texts are json.dumps' with the canonical options, however they are
put together (one C encoder built once, an object from texts already encoded, a vector's texts
reused for the CSV)."""
import csv
import io
import json

import pytest

from plcvec.output.canonical import dumps_object, dumps_value, dumps_vector_file, vector_texts
from plcvec.output.golden import CSV_COLUMNS, csv_export, csv_field


def reference(value):
    return json.dumps(value, sort_keys=True, ensure_ascii=False, separators=(", ", ": "))


VALUES = [
    {"b": 1, "a": [True, None, -3, 2.5, 1e16, float("inf")], "é": "naïve \"quoted\"\n\t\u0001"},
    [], {}, "plain", "ünïcode", 7, 0.1, None, False,
    {"z": {"y": {"x": [{"b": 2, "a": 1}]}}, "D100": 0x1234, "D2": 65535},
]


@pytest.mark.parametrize("value", VALUES)
def test_dumps_value_is_json_dumps_with_the_canonical_options(value):
    assert dumps_value(value) == reference(value)


def test_a_circular_value_is_refused_and_the_encoder_still_works_after():
    loop = {"a": []}
    loop["a"].append(loop)
    with pytest.raises(ValueError, match="Circular"):
        dumps_value(loop)
    shared = [1]
    assert dumps_value({"x": shared, "y": shared}) == '{"x": [1], "y": [1]}'
    with pytest.raises(TypeError):
        dumps_value({"set": {1}})
    assert dumps_value([shared, shared]) == "[[1], [1]]"


def test_an_object_from_texts_already_encoded_is_the_object_encoded_whole():
    obj = {"operands": {"s1": {"device": "D0"}}, "devices": {"D1": 2, "D0": 1}, "scratch": ["D9"]}
    assert dumps_object(obj) == reference(obj)
    assert dumps_object(obj, {"devices": reference(obj["devices"])}) == reference(obj)
    assert dumps_object({}) == "{}"


def test_a_vectors_texts_are_its_values_and_their_parts_encoded():
    vector = {"id": "f/I/k", "initial": {"operands": {"s1": {"constant": 3}}, "devices": {"D1": 1, "D0": 0}},
              "steps": [{"expect": {"devices": {}}}], "final": {"devices": {"D0": 0}}, "tags": ["é"]}
    texts = vector_texts(vector)
    for key, value in vector.items():
        assert texts[key] == reference(value)
    assert texts["initial", "operands"] == reference(vector["initial"]["operands"])
    assert texts["initial", "devices"] == reference(vector["initial"]["devices"])
    assert texts["final", "devices"] == reference(vector["final"]["devices"])
    header = {"family": "f", "count": 1}
    assert dumps_vector_file(header, [vector], [texts]) == dumps_vector_file(header, [vector])
    # The file's lines: one per top-level key, in the vector's own order, each value canonical; the
    # vector's "{" opens its first line and its "}" closes its last.
    lines = dumps_vector_file(header, [vector]).splitlines()
    body = [f'"{k}": {reference(v)}' for k, v in vector.items()]
    assert lines[4:9] == ["  {" + body[0] + ","] + [f"   {b}," for b in body[1:-1]] + [f"   {body[-1]}}}"]
    assert json.loads(dumps_vector_file(header, [vector])) == dict(header, vectors=[vector])


CSV_FIELDS = ["plain", "", "a,b", 'say "hi"', '""', '{"D0": 1, "D1": 2}', "two\nlines", "crlf\r\n",
              " leading and trailing ", "semi;colon", "tab\there", "é,\"ü\"", ",", '"', "\n"]


@pytest.mark.parametrize("text", CSV_FIELDS)
def test_a_csv_field_is_quoted_as_the_csv_module_quotes_it(text):
    out = io.StringIO()
    csv.writer(out, lineterminator="\n").writerow([text, "x"])
    assert csv_field(text) + ",x\n" == out.getvalue()


def test_a_csv_field_with_a_lone_carriage_return_is_quoted():
    # RFC 4180 quotes any line break; csv.writer with "\n" ending its rows leaves a lone "\r" bare
    # on some Python versions, which readers then take for the end of a row.
    assert csv_field("cr\rhere") == '"cr\rhere"'
    assert next(csv.reader(io.StringIO(csv_field("cr\rhere") + ",x\n"))) == ["cr\rhere", "x"]


def test_the_csv_export_reads_back_as_the_vectors_values():
    vector = {"id": "f/I/a,b", "family": "f", "instruction": 'LD"=DT', "tags": ["x", "y"],
              "outcome": {"category": "value"}, "clauses": ["c1", "c2"],
              "initial": {"operands": {"s1": {"device": "D0"}}, "devices": {"D0": 1, "D1": 2}},
              "steps": [{"expect": {"devices": {"D1": 3}, "result": True}}], "final": {"devices": {"D0": 1, "D1": 3}}}
    text = csv_export([vector, vector])
    rows = list(csv.reader(io.StringIO(text)))
    assert rows[0] == list(CSV_COLUMNS)
    assert rows[1] == rows[2] == [
        "f/I/a,b", "f", 'LD"=DT', "x y", "value", "c1 c2", reference(vector["initial"]["operands"]),
        reference(vector["initial"]["devices"]), reference(vector["steps"]), reference(vector["final"]["devices"])]
    assert text.endswith("\n") and not text.endswith("\n\n")


def test_a_vectors_texts_are_the_same_without_the_c_encoder(monkeypatch):
    from plcvec.output import canonical

    vector = {"id": "f/I/ü", "initial": {"scratch": ["D9"], "operands": {"s1": {"constant": 3}}, "devices": {"D1": 1, "D0": 0}},
              "steps": [{"set": {"D1": 2}, "expect": {"result": True, "devices": {}}}], "final": {"devices": {"D0": 0}},
              "outcome": {"category": "value"}, "tags": ["é"], "count": 7, "none": None}
    with_c = vector_texts(vector)
    monkeypatch.setattr(canonical, "_pieces", lambda value, _level: (canonical._ENCODER.encode(value),))
    assert vector_texts(vector) == with_c
    assert with_c["initial"] == reference(vector["initial"]) and with_c["count"] == "7" and with_c["none"] == "null"
