"""Regression cases: inputs that once exposed a bug in an implementation, kept as golden vectors.

`spec/regressions/<family>.yaml` is a list of cases. Each gives the inputs of one vector (instruction,
operands, initial devices, scratch devices, steps: the shapes a vector uses) and a `note` saying why
it exists; never an expectation, which `plcvec generate` computes with the engine as for any vector.
The cases are not facts of the manual, so they live beside the family files, not inside them.
"""
import hashlib
import json

import jsonschema

from plcvec.errors import SpecError
from plcvec.spec.files import line_of, read_text, schema_path, validate
from plcvec.spec.instructions import instruction_list
from plcvec.spec.yaml_lines import load_with_lines

INPUTS = ("instruction", "operands", "devices", "scratch", "steps")
TAG = "regression"

_validator = None


class Regressions:
    """One family's regression file: its cases, the line of every value, and its hash."""

    def __init__(self, path, cases, lines, text):
        self.path, self.cases, self.lines = path, cases, lines
        self.sha256 = hashlib.sha256(text.encode()).hexdigest()

    def line_of(self, *where):
        return line_of(self.lines, where)

    def error(self, where, message):
        return SpecError(self.path, self.line_of(*where), message)


def case_key(case):
    """What a regression vector's id has after `<family>/<instruction>/`: a short hash of the case's
    inputs, not of its note, so rewording a note or adding cases renames nothing."""
    inputs = {k: case[k] for k in INPUTS if case.get(k)}
    if "scratch" in inputs:
        inputs["scratch"] = sorted(inputs["scratch"])
    return f"{TAG}/" + hashlib.sha256(json.dumps(inputs, sort_keys=True).encode()).hexdigest()[:12]


def case_of(vector):
    """A vector's inputs as a regression case (without its note)."""
    initial = vector["initial"]
    case = {"instruction": vector["instruction"], "operands": initial["operands"], "devices": initial["devices"]}
    if initial.get("scratch"):
        case["scratch"] = initial["scratch"]
    case["steps"] = [{k: v for k, v in step.items() if k != "expect"} for step in vector["steps"]]
    return case


def load_regressions(folder, families):
    """Attach each spec/regressions/<family>.yaml in `folder` to its family ({name: Family})."""
    if not folder.is_dir():
        return
    for path in sorted(folder.glob("*.yaml")):
        fam = families.get(path.stem)
        if fam is None:
            raise SpecError(path, 1, f"no spec family {path.stem!r}: a regression file is named after the family "
                                     f"of its cases ({', '.join(sorted(families))})")
        fam.regressions = parse_regressions(path, read_text(path), fam)


def parse_regressions(path, text, fam):
    """The Regressions of `text` (the content of `path`), or a SpecError at the line of its first mistake."""
    global _validator
    if _validator is None:
        _validator = jsonschema.Draft202012Validator(json.loads(schema_path("regressions.schema.json").read_text()))
    cases, lines = load_with_lines(path, text)
    if not isinstance(cases, list):
        raise SpecError(path, 1, "a regression file is a list of cases (each starting with '- note:')")
    validate(path, cases, lines, _validator)
    regs = Regressions(path, cases, lines, text)
    _check_cases(fam, regs)
    return regs


def _check_cases(fam, regs):
    names = [i["name"] for i in instruction_list(fam)]
    operands = fam.doc["operands"]
    seen = {}
    for i, case in enumerate(regs.cases):
        if case["instruction"] not in names:
            raise regs.error((i, "instruction"), f"instruction {case['instruction']!r} is not one of family "
                                                 f"{fam.name}'s ({', '.join(names)})")
        for name, op in case["operands"].items():
            if name not in operands:
                raise regs.error((i, "operands", name), f"{name!r} is not an operand of {case['instruction']} "
                                                        f"(its operands: {', '.join(operands)})")
            if "constant" in op and not operands[name].get("constant"):
                raise regs.error((i, "operands", name), f"operand {name} cannot be a constant in family {fam.name}")
        missing = [name for name in operands if name not in case["operands"]]
        if missing:
            raise regs.error((i, "operands"), f"operand {missing[0]} of {case['instruction']} is missing")
        for k, device in enumerate(case.get("scratch", [])):
            if device not in case["devices"]:
                raise regs.error((i, "scratch", k), f"scratch device {device} is not among the case's devices")
        for j, step in enumerate(case["steps"]):
            for device in step.get("set", {}):
                if device not in case["devices"]:
                    raise regs.error((i, "steps", j, "set", device),
                                     f"step {j} sets {device}, which is not among the case's devices")
        key = case_key(case)
        if key in seen:
            raise regs.error((i,), f"the same inputs as the case on line {regs.line_of(seen[key])}; "
                                   "a note can say both reasons")
        seen[key] = i


def stanza(note, case):
    """A regression case as YAML text to append to its family's file: one line per value, written as
    JSON (which YAML reads as flow collections), so the same case gives the same bytes."""
    def value(v):
        return json.dumps(v, sort_keys=True, ensure_ascii=False)

    lines = [f"- note: {value(note)}"]
    lines += [f"  {k}: {value(case[k])}" for k in INPUTS[:-1] if k in case]
    lines.append("  steps:")
    lines += [f"    - {value(step)}" for step in case["steps"]]
    return "\n".join(lines) + "\n"

