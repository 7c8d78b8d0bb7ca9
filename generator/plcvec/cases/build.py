"""Turn a case (instruction, initial state, steps) into a vector with its expectations.

The engine runs the case under the default reading of every interpretation, then under the other
alternatives of each interpretation an execution consulted (see plcvec.engine); an interpretation
whose alternatives give different expectations "touches" the vector, and the vector then carries
the expectation of every combination of the touched ones.
"""
import functools
import itertools
from typing import NamedTuple

from plcvec.cases.unjudged import Unjudged
from plcvec.coverage.derive import CLASSIFIERS
from plcvec.coverage.model import model_of
from plcvec.engine import make_engine
from plcvec.spec.instructions import instruction_list
from plcvec.spec.knobs import Resolver

STEP_INPUTS = ("set", "rlo_in", "clock", "en", "input", "elapsed_ms")
_MEMO_SIZE = 4096   # distinct device lists a builder remembers the reported order of


class GeneratorBug(Exception):
    """A case the generator built wrongly (duplicate id, undeclared device): a bug, not a user error."""


class Run(NamedTuple):
    """One execution of a case under one set of choices."""
    expects: list      # per step: {"result"?, "devices": changed devices}
    final: dict        # every device but the scratch ones, after the last step
    outcome: dict      # {"category": "value"} or {"category": "error", "errors": [...]}
    trace: set         # clause ids the engine cited
    consulted: frozenset  # interpretation ids whose chosen value the execution read
    # {interpretation id: sorted devices} the choices leave unjudged, left out of expects and final
    unjudged: dict = {}


class VectorBuilder:
    def __init__(self, fam):
        self.fam = fam
        self.sizes = {k: v for k, v in fam.doc["assumptions"]["device_sizes"].items() if k != "why"}
        self.instructions = {i["name"]: i for i in instruction_list(fam)}
        self._resolver = Resolver(fam.doc)   # the spec resolved under each set of choices an engine needs
        self._engines = {}
        self._consulting = {}
        self.executions = 0   # runs of a case under one set of choices, for the benchmark and its tests
        self.ids = set()
        self.defaults = fam.default_choices()
        self._unjudged = Unjudged(fam)
        self.order = list(fam.interpretations)
        self.options = {i: [a["id"] for a in fam.interpretations[i]["alternatives"]] for i in self.order}
        coverage = fam.doc.get("coverage", {})
        # Clauses the spec says every vector embodies (names, operand types, encoding), and those a
        # vector cites because the generator tagged it for that reason.
        self.every_vector = set(coverage.get("every_vector", []))
        self.by_tag = coverage.get("by_tag", {})
        # The coverage model's cells each vector exercises, under any reading: {vector id: frozenset}.
        self.model = model_of(fam)
        self.classifier = CLASSIFIERS[fam.kind](fam.doc, self.sizes) if self.model else None
        self.cells = {}
        self._cell_memo, self._cells_seen = {}, set()
        self._cited_memo = {}
        self._shown_memo = {}
        self._refs = functools.lru_cache(maxsize=None)(fam.clause_ref)   # a few dozen ids, cited by thousands

    def engine(self, choices):
        """The engine under `choices` (interpretation id -> alternative id), as plain as it can be."""
        key = tuple(sorted(choices.items()))
        if key not in self._engines:
            self._engines[key] = make_engine(self._resolver.resolve(dict(choices)))
        return self._engines[key]

    def _consulting_engine(self, choices):
        """(engine, sink, interpretations read while it was built) for `choices`: the engine reads its
        parameters from a document that records each chosen value read into `sink`."""
        key = tuple(choices.items())   # the builder's own runs name every interpretation, in one order
        entry = self._consulting.get(key)
        if entry is None:
            sink = set()
            engine = make_engine(self._resolver.resolve(dict(choices), consulted=sink))
            entry = self._consulting[key] = (engine, sink, frozenset(sink))
        return entry

    def run(self, instr, operands, devices, steps, scratch, choices):
        """(expects, final, outcome, trace) of the case under `choices`."""
        return self.execute(instr, operands, devices, steps, scratch, choices)[:4]

    def execute(self, instr, operands, devices, steps, scratch, choices):
        """The Run of the case under `choices`, with the interpretations it consulted."""
        engine, sink, at_build = self._consulting_engine(choices)
        sink.clear()
        self.executions += 1
        state = dict(devices)
        # The devices a step's expectation and the final state report, in their order: the state's
        # keys never change during a step (checked below), only a step's "set" may add one.
        shown = self._shown(state, scratch)
        ctx = {"device_sizes": self.sizes}
        trace, expects, errors = set(), [], []
        for index, step in enumerate(steps):
            if "set" in step:
                state.update(step["set"])
                if len(state) != len(devices):
                    shown = self._shown(state, scratch)
            before = dict(state)
            result = engine.execute(instr, operands, state, step, ctx, trace)
            if self.classifier is not None:
                self._cells_seen.add(self._cell(index, instr, operands, before, step, ctx["exercised"][-1]))
            if len(state) != len(before):
                raise GeneratorBug(f"engine wrote {sorted(set(state) - set(before))} not in the initial state")
            devices_changed = {k: state[k] for k in shown if state[k] != before[k]}
            expects.append({"devices": devices_changed} if result is None else {"result": result, "devices": devices_changed})
            if "error" in ctx:
                errors.append(dict(step=index, **ctx.pop("error")))
        final = {k: state[k] for k in shown}
        outcome = {"category": "error", "errors": errors} if errors else {"category": "value"}
        trace.discard(None)
        unjudged = {}
        if "undefined" in ctx:
            unjudged = self.unjudged(ctx["undefined"], choices, operands, devices)
            expects, final = leave_out(expects, final, {d for ds in unjudged.values() for d in ds})
        return Run(expects, final, outcome, trace, frozenset(sink) | at_build, unjudged)

    def unjudged(self, parameters, choices, operands, devices):
        """{interpretation id: devices} the chosen alternatives leave unjudged, where an engine found the
        rule `parameters` undefined: each device listed in the initial state (so a write to it is no
        stray write), and never under the defaults."""
        unjudged = self._unjudged.devices(parameters, choices, operands)
        for iid, listed in unjudged.items():
            if not listed or not set(listed) <= set(devices) or choices[iid] == self.defaults[iid]:
                raise GeneratorBug(f"{iid}={choices[iid]} leaves {listed} unjudged, which is not a non-empty "
                                   "list of the vector's initial devices under a reading other than the default")
        return unjudged

    def runs(self, instr, operands, devices, steps, scratch):
        """[(choices, Run)]: the case under every combination of alternatives, in as few runs as it takes.

        Each entry's choices name some interpretations; its Run is the result under every combination
        that agrees with them, and the entries' choices split the set of all combinations between them.
        A run that consulted an interpretation not yet fixed is split into one entry per combination of
        those interpretations' alternatives (the one that keeps the defaults is the run itself).
        """
        defaults, order, options = self.defaults, self.order, self.options
        done, pending = [], [{}]
        while pending:
            fixed = pending.pop()
            run = self.execute(instr, operands, devices, steps, scratch, dict(defaults, **fixed))
            open_ = [i for i in order if i in run.consulted and i not in fixed]
            if not open_:   # nothing unfixed was read: the run stands for every combination of the rest
                done.append((dict(fixed), run))
                continue
            ran = tuple(defaults[i] for i in open_)
            for combo in itertools.product(*(options[i] for i in open_)):
                choice = dict(fixed)
                choice.update(zip(open_, combo))
                if combo == ran:
                    done.append((choice, run))  # the choices just run: nothing unfixed was read
                else:
                    pending.append(choice)
        return done

    def _cell(self, index, instr, operands, before, step, record):
        """The model cell of one execution; the same inputs recur under every reading of a vector."""
        # The memo is emptied for each vector, and before its first step every reading starts from the
        # same state: there the record alone tells executions apart.
        key = (0, tuple(record.values())) if index == 0 else (index, tuple(before.items()), tuple(record.values()))
        if key not in self._cell_memo:
            self._cell_memo[key] = self.model.cell(self.classifier.classify(instr, operands, before, step, record))
        return self._cell_memo[key]

    def vector(self, instruction, key, *, tags, description, operands, devices, steps,
               scratch=(), clauses=(), printed=None):
        instr = self.instructions[instruction]
        vid = f"{self.fam.name}/{instruction}/{key}"
        if vid in self.ids:
            raise GeneratorBug(f"duplicate vector id {vid}")
        self.ids.add(vid)
        for error in _errors_in_code(operands):
            raise GeneratorBug(f"{vid}: {error}")
        self._cell_memo, self._cells_seen = {}, set()
        expects, final, outcome, trace, touched, alternatives = self.expectations(instr, operands, devices, steps, scratch)
        # What the vector exercises for the coverage model, under every reading it carries: the runs
        # cover every behaviour (a combination not run reads nothing that would change it).
        self.cells[vid] = frozenset(self._cells_seen)
        if touched:
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
            "clauses": sorted(map(self._refs, trace.union(clauses, self._cited(instr, operands, tags)))),
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

    def expectations(self, instr, operands, devices, steps, scratch):
        """(expects, final, outcome, trace, touched, alternatives) of a case over every combination of
        the family's alternatives: checking one interpretation at a time would miss a result that
        changes only when two non-default alternatives are taken together.

        An interpretation touches the case when changing it alone, anywhere in the grid of combinations,
        changes the result; the result is then a function of the touched ones only. Only the
        interpretations some run consulted can touch it, so the grid is that of the consulted ones.
        """
        defaults = self.defaults
        runs = self.runs(instr, operands, devices, steps, scratch)
        if len(runs) == 1:  # nothing consulted: the result of every combination is this one
            (_, root), = runs
            return root.expects, root.final, root.outcome, set(root.trace), [], []
        consulted = [i for i in self.order if any(i in choice for choice, _ in runs)]
        options = [self.options[i] for i in consulted]
        # Runs with equal results share a class, so the grid compares small integers.
        classes, distinct = [], []
        for _, run in runs:
            same = next((k for k, other in enumerate(distinct)
                         if other[:3] == run[:3] and other.unjudged == run.unjudged), None)
            if same is None:
                same = len(distinct)
                distinct.append(run)
            classes.append(same)
        if len(distinct) == 1:   # every combination gives one result: none touches it
            root = next(run for choice, run in runs if all(choice[i] == defaults[i] for i in choice))
            return root.expects, root.final, root.outcome, set(root.trace), [], []
        grid = {}
        for (choice, run), cls in zip(runs, classes):
            free = [k for k, i in enumerate(consulted) if i not in choice]
            for combo in itertools.product(*(options[k] for k in free)):
                full = dict(choice, **{consulted[k]: alt for k, alt in zip(free, combo)})
                grid[tuple(full[i] for i in consulted)] = (cls, run)
        touched = [iid for k, iid in enumerate(consulted)
                   if any(grid[c][0] != grid[c[:k] + (alt,) + c[k + 1:]][0]
                          for c in grid for alt in options[k] if alt != c[k])]
        root = grid[tuple(defaults[i] for i in consulted)][1]
        trace = set(root.trace)
        alternatives = []
        for combo in itertools.product(*(options[consulted.index(i)] for i in touched)):
            choice = dict(zip(touched, combo))
            if all(choice[i] == defaults[i] for i in touched):
                continue
            run = grid[tuple(choice.get(i, defaults[i]) for i in consulted)][1]
            trace |= run.trace
            entry = {"choices": choice, "expect": run.expects, "final": {"devices": run.final}, "outcome": run.outcome}
            if run.unjudged:
                if not set(run.unjudged) <= set(choice):
                    raise GeneratorBug(f"{sorted(run.unjudged)} leave devices unjudged but are not all among {sorted(choice)}")
                entry["unjudged"] = run.unjudged
            alternatives.append(entry)
        return root.expects, root.final, root.outcome, trace, touched, alternatives

    def _shown(self, state, scratch):
        """The devices of `state` a vector reports (all but the scratch ones), sorted: the same few lists
        for every execution of every vector (bounded, as a fuzzing run meets new devices without end)."""
        key = (tuple(state), tuple(scratch))
        shown = self._shown_memo.get(key)
        if shown is None:
            if len(self._shown_memo) >= _MEMO_SIZE:
                self._shown_memo.clear()
            shown = self._shown_memo[key] = [k for k in sorted(state) if k not in scratch]
        return shown

    def _cited(self, instr, operands, tags):
        """Clauses a vector exercises by what it is, whatever the engine does with it: the clause of each
        operand it uses, the naming of its instruction, and the spec's coverage section (the same few
        sets for thousands of vectors: worked out once per instruction, operand names and tags)."""
        key = (instr["name"], tuple(operands), tuple(tags))
        cited = self._cited_memo.get(key)
        if cited is None:
            cited = self._cited_memo[key] = frozenset(self._cite(instr, operands, tags))
        return cited

    def _cite(self, instr, operands, tags):
        cited = {self.fam.doc["operands"][name]["clause"] for name in operands}
        cited |= {instr["naming_clause"]} if "naming_clause" in instr else set()
        return cited | self.every_vector | {self.by_tag[t] for t in tags if t in self.by_tag}


def leave_out(expects, final, devices):
    """(expects, final) without `devices`: what an entry that leaves them unjudged lists."""
    expects = [dict(e, devices={k: v for k, v in e["devices"].items() if k not in devices}) for e in expects]
    return expects, {k: v for k, v in final.items() if k not in devices}


def _errors_in_code(operands):
    for name, op in operands.items():
        if not ("device" in op) ^ ("constant" in op):
            yield f"operand {name} must be either a device or a constant"
