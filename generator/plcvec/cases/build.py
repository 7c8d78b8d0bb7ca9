"""Turn a case (instruction, initial state, steps) into a vector with its expectations.

The engine runs the case under the default reading of every interpretation, then under each other
alternative; an interpretation whose alternatives give different expectations "touches" the vector,
and the vector then carries the expectation of every combination of the touched ones.
"""
import itertools

from plcvec.engine import make_engine
from plcvec.spec.knobs import resolve

STEP_INPUTS = ("set", "rlo_in", "clock", "en", "input", "elapsed_ms")


class GeneratorBug(Exception):
    """A case the generator built wrongly (duplicate id, undeclared device): a bug, not a user error."""


def instruction_list(fam):
    """Every instruction of a family, with the names the manual gives it."""
    doc = fam.doc
    if fam.kind == "masked_compare":
        ins, naming = doc["instructions"], doc["instructions"]["naming"]
        out = []
        for form in ins["forms"]:
            for cond in ins["conditions"]:
                names = {"form_mnemonic": form["mnemonic"], "symbol": cond["symbol"],
                         "form_st": form["st"], "condition_st": cond["st"]}
                item = {"name": naming["ladder"].format(**names), "st": naming["st"].format(**names),
                        "form": form, "symbol": cond["symbol"], "naming_clause": naming["clause"]}
                if "function_code" in cond:
                    item["function_code"] = cond["function_code"]
                out.append(item)
        return out
    return [dict(i, name=i["mnemonic"]) for i in doc["instructions"]]


class VectorBuilder:
    def __init__(self, fam):
        self.fam = fam
        self.sizes = {k: v for k, v in fam.doc["assumptions"]["device_sizes"].items() if k != "why"}
        self.instructions = {i["name"]: i for i in instruction_list(fam)}
        self._engines = {}
        self.ids = set()
        self.defaults = fam.default_choices()
        coverage = fam.doc.get("coverage", {})
        # Clauses the spec says every vector embodies (names, operand types, encoding), and those a
        # vector cites because the generator tagged it for that reason.
        self.every_vector = set(coverage.get("every_vector", []))
        self.by_tag = coverage.get("by_tag", {})

    def engine(self, choices):
        key = tuple(sorted(choices.items()))
        if key not in self._engines:
            self._engines[key] = make_engine(resolve(self.fam.doc, dict(choices)))
        return self._engines[key]

    def run(self, instr, operands, devices, steps, scratch, choices):
        engine = self.engine(choices)
        state = dict(devices)
        ctx = {"device_sizes": self.sizes}
        trace, expects, errors = set(), [], []
        for index, step in enumerate(steps):
            state.update(step.get("set", {}))
            before = dict(state)
            result = engine.execute(instr, operands, state, step, ctx, trace)
            if set(state) != set(before):
                raise GeneratorBug(f"engine wrote {sorted(set(state) - set(before))} not in the initial state")
            expect = {}
            if result is not None:
                expect["result"] = result
            expect["devices"] = {k: state[k] for k in sorted(state) if state[k] != before[k] and k not in scratch}
            expects.append(expect)
            if "error" in ctx:
                errors.append(dict(step=index, **ctx.pop("error")))
        final = {k: state[k] for k in sorted(state) if k not in scratch}
        outcome = {"category": "error", "errors": errors} if errors else {"category": "value"}
        trace.discard(None)
        return expects, final, outcome, trace

    def vector(self, instruction, key, *, tags, description, operands, devices, steps,
               scratch=(), clauses=(), printed=None):
        instr = self.instructions[instruction]
        vid = f"{self.fam.name}/{instruction}/{key}"
        if vid in self.ids:
            raise GeneratorBug(f"duplicate vector id {vid}")
        self.ids.add(vid)
        for error in _errors_in_code(operands):
            raise GeneratorBug(f"{vid}: {error}")
        # Run the vector under every combination of the family's alternatives (at most a few dozen):
        # checking one interpretation at a time would miss a result that changes only when two
        # non-default alternatives are taken together.
        names = list(self.fam.interpretations)
        options = [[a["id"] for a in self.fam.interpretations[i]["alternatives"]] for i in names]
        results = {combo: self.run(instr, operands, devices, steps, scratch, dict(zip(names, combo)))
                   for combo in itertools.product(*options)}
        expects, final, outcome, trace = results[tuple(self.defaults[i] for i in names)]
        # An interpretation touches the vector when changing it alone, anywhere in the grid,
        # changes the result; the result is then a function of the touched ones only.
        touched = [iid for k, iid in enumerate(names)
                   if any(results[c][:3] != results[c[:k] + (alt,) + c[k + 1:]][:3]
                          for c in results for alt in options[k] if alt != c[k])]
        alternatives = []
        if touched:
            for combo in itertools.product(*(options[names.index(i)] for i in touched)):
                choice = dict(zip(touched, combo))
                if all(choice[i] == self.defaults[i] for i in touched):
                    continue
                key = tuple(choice.get(i, self.defaults[i]) for i in names)
                a_expects, a_final, a_outcome, a_trace = results[key]
                trace |= a_trace
                alternatives.append({"choices": choice, "expect": a_expects, "final": {"devices": a_final},
                                     "outcome": a_outcome})
            outcome = {"category": "implementation-defined", "interpretations": touched,
                       "default": outcome,
                       "reason": " ".join(self.fam.interpretations[i]["question"] for i in touched)}
        vector = {
            "id": vid,
            "family": self.fam.name,
            "instruction": instruction,
            "st": instr.get("st", instruction),
            "description": description,
            "tags": sorted(set(tags)),
            "clauses": sorted(self.fam.clause_ref(c) for c in trace | set(clauses) | self._cited(instr, operands, tags)),
            "assumes": {"device_sizes": self.sizes},
            "initial": {"operands": operands, "devices": dict(sorted(devices.items()))},
            "steps": [dict({k: s[k] for k in STEP_INPUTS if k in s}, expect=e) for s, e in zip(steps, expects)],
            "final": {"devices": final},
            "outcome": outcome,
        }
        if scratch:
            vector["initial"]["scratch"] = sorted(scratch)
        if alternatives:
            vector["alternatives"] = alternatives
        if printed is not None:
            vector["printed"] = printed
        return vector


    def _cited(self, instr, operands, tags):
        """Clauses a vector exercises by what it is, whatever the engine does with it: the clause of each
        operand it uses, the naming of its instruction, and the spec's coverage section."""
        cited = {self.fam.doc["operands"][name]["clause"] for name in operands}
        cited |= {instr["naming_clause"]} if "naming_clause" in instr else set()
        return cited | self.every_vector | {self.by_tag[t] for t in tags if t in self.by_tag}


def _errors_in_code(operands):
    for name, op in operands.items():
        if not ("device" in op) ^ ("constant" in op):
            yield f"operand {name} must be either a device or a constant"
