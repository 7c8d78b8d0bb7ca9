"""The exhaustive tier: every value of the selector/mask word for every condition, as JSON Lines.

Written on demand, never committed. Lines are streamed one at a time, so memory stays flat however
many are written. Each line is a vector in the golden format, for the LD form, under one fixed set of
interpretation choices (the defaults unless --choose says otherwise), named in the file's first line.
"""
import json
import time
from operator import itemgetter

from plcvec import SCHEMA_VERSION
from plcvec.cases.build import GeneratorBug, VectorBuilder
from plcvec.cases.masked_compare_cases import CompareCases
from plcvec.errors import PlcvecError
from plcvec.output.canonical import dumps_value

WORD_VALUES = 1 << 16


def _check_choices(families, choices):
    known = {iid: fam for fam in families for iid in fam.interpretations}
    for iid, alt in choices.items():
        if iid not in known:
            raise PlcvecError(f"--choose: no interpretation {iid!r} (known: {', '.join(sorted(known))})")
        alts = [a["id"] for a in known[iid].interpretations[iid]["alternatives"]]
        if alt not in alts:
            raise PlcvecError(f"--choose: {iid} has no alternative {alt!r} (it has: {', '.join(alts)})")


def stream_exhaustive(families, out_dir, only=None, choices=None, selectors=None):
    """Write `<family>.exhaustive.jsonl` for each chosen family; (lines written, seconds).

    `selectors` limits the selector values written (all 65,536 by default), in the order given.
    """
    choices = choices or {}
    _check_choices(families, choices)
    chosen = [f for f in families if f.kind == "masked_compare" and (not only or f.name in only)]
    if only:
        unknown = set(only) - {f.name for f in families}
        if unknown:
            raise PlcvecError(f"--family: unknown family {', '.join(sorted(unknown))}")
    if not chosen:
        raise PlcvecError("no family with a selector word was chosen for the exhaustive tier")
    out_dir.mkdir(parents=True, exist_ok=True)
    count, start = 0, time.perf_counter()
    for fam in chosen:
        count += _write_family(fam, out_dir / f"{fam.name}.exhaustive.jsonl",
                               {k: v for k, v in choices.items() if k in fam.interpretations},
                               range(WORD_VALUES) if selectors is None else selectors)
    return count, time.perf_counter() - start


# Stands in for the selector's value in a dumped state, where the template takes the line's value:
# a device value no operand holds, so it occurs once.
_MARKER = -12345


def _write_family(fam, path, choices, selectors):
    builder = VectorBuilder(fam)
    cases = CompareCases(fam, builder)
    full_choices = dict(fam.default_choices(), **choices)
    engine = builder.engine(full_choices)
    # One data pattern in which every field differs, alternating in direction, so that different
    # field subsets give different orderings; in current-clock mode the clock holds (s2)'s values.
    a = cases.ops.values()
    b = {n: cases.ops.mid(n, 1 if i % 2 else -1) for i, n in enumerate(cases.names)}
    devices = cases.outputs()
    place = cases.place
    cases.ops.place(devices, place[cases.first], cases.ops.words(a))
    cases.ops.place(devices, place[cases.second], cases.ops.words(b))
    sel_head = place[cases.selop]
    operands = {cases.first: {"device": place[cases.first]}, cases.second: {"device": place[cases.second]},
                cases.selop: {"device": sel_head}}
    sizes = builder.sizes
    loads = [(name, instr) for name, instr in builder.instructions.items() if instr["form"]["logic"] == "load"]
    header = {"exhaustive": fam.name, "schema_version": SCHEMA_VERSION, "choices": full_choices,
              "spec_sha256": fam.sha256, "instructions": [name for name, _ in loads],
              "note": "One vector per line after this one: the LD form, every selector value, every condition."}
    conditions = {c["symbol"]: c for c in fam.doc["instructions"]["conditions"]}
    source_bit = cases.clock_bit["bit"] if cases.clock_bit else None
    devices[sel_head] = _MARKER
    block = _Blocks(fam, engine, loads, conditions, devices, sel_head, operands, sizes, cases.selop, b)
    initial = devices.items()
    clock_step = {"clock": b}
    tmp = path.with_name(f".{path.name}.partial")
    n = 0
    with open(tmp, "wb", buffering=1 << 20) as out:
        out.write((json.dumps(header, sort_keys=True) + "\n").encode("utf-8"))
        templates, width = block.templates, len(loads)
        for sel in selectors:
            # Only the engine's answer depends on the line; the text around it is built once per
            # distinct answer (a few dozen) and filled in with the selector value.
            state = dict(devices)
            state[sel_head] = sel
            step = clock_step if source_bit is not None and sel >> source_bit & 1 else {}
            ctx = {"device_sizes": sizes}
            trace = set()
            outcome = engine.evaluate(operands, state, step, ctx, trace)
            state[sel_head] = _MARKER
            # The state's values in its (fixed) key order stand for the whole state: the engine
            # writes only devices the state holds (a state with another device is a key never seen,
            # and make() refuses it).
            error = ctx.get("error")
            key = (outcome, frozenset(trace), tuple(state.values()), bool(step),
                   None if error is None else tuple(sorted(error.items())))
            template = templates.get(key)
            if template is None:
                template = block.make(key, trace, state, initial, error, step)
            parts, pick = template
            parts[1::2] = pick((b"%04X" % sel, b"%d" % sel))
            out.write(b"".join(parts))
            n += width
    tmp.replace(path)
    return n


# Where a line holds the selector value, in hex (0000 to FFFF) or in decimal: a NUL, which JSON text
# never holds raw (inside a string it is written \u0000), so the marks cannot clash with the text.
_HEX, _DEC = "\x00h", "\x00d"
_KINDS = b"hd"   # the byte after a mark -> index of the value in (hex, decimal)


class _Blocks:
    """The lines of one selector value, for each distinct answer of the engine, as a template.

    A template is (parts, pick): the UTF-8 pieces of the lines with every other slot left for the
    selector value, and a function that, given (hex, decimal) as bytes, returns the value of each slot
    in order. The value is formatted once per selector value and the lines joined in one call; a
    %-template read its format and looked up each of its 24 marks anew for every line.
    """

    def __init__(self, fam, engine, loads, conditions, devices, sel_head, operands, sizes, selop, clock):
        self.fam, self.engine, self.templates, self.sel_head = fam, engine, {}, sel_head
        pre, post = dumps_value(dict(sorted(devices.items()))).split(str(_MARKER))
        self.common = (f'"tags": ["exhaustive"], "assumes": {{"device_sizes": {dumps_value(sizes)}}}, '
                       f'"initial": {{"operands": {dumps_value(operands)}, "devices": {pre}{_DEC}{post}}}, ')
        self.clock = f'"clock": {dumps_value(clock)}, '
        self.description = f'"description": {json.dumps(selop + " = ")[:-1]}{_HEX}H", '
        self.names = [(json.dumps(f"{fam.name}/{name}/exhaustive/")[:-1], json.dumps(name),
                       json.dumps(instr["st"]), instr["symbol"],
                       {instr["form"]["clause"], conditions[instr["symbol"]]["clause"]})
                      for name, instr in loads]
        self.family = json.dumps(fam.name)

    def make(self, key, trace, state, initial, error, step):
        outcome = key[0]
        trace.discard(None)
        if state.keys() != initial.mapping.keys():
            raise GeneratorBug(f"engine wrote {sorted(state.keys() - initial.mapping.keys())} not in the initial state")
        # Equal values count as unchanged, as 1 == True.
        changed = dumps_value(dict(sorted(state.items() - initial)))
        result_outcome = ('{"category": "error", "errors": [%s]}' % dumps_value(dict(step=0, **error))) if error \
            else '{"category": "value"}'
        pre, post = dumps_value(dict(sorted(state.items()))).split(str(_MARKER))
        final = f"{pre}{_DEC}{post}"
        clock = self.clock if step else ""
        lines = []
        for vid, name, st, symbol, own in self.names:
            result = "true" if self.engine.contact(symbol, outcome) else "false"
            clauses = json.dumps(sorted(self.fam.clause_ref(c) for c in trace | own))
            lines.append(f'{{"id": {vid}{_HEX}H", "family": {self.family}, "instruction": {name}, "st": {st}, '
                         f'{self.description}"clauses": {clauses}, {self.common}'
                         f'"steps": [{{{clock}"expect": {{"devices": {changed}, "result": {result}}}}}], '
                         f'"final": {{"devices": {final}}}, "outcome": {result_outcome}}}\n')
        first, *marked = "".join(lines).encode("utf-8").split(b"\x00")
        parts, kinds = [first], []
        for piece in marked:
            kinds.append(_KINDS.index(piece[0]))
            parts += [None, piece[1:]]
        # Every line has four marks, so there are always several: itemgetter then returns a tuple.
        template = self.templates[key] = (parts, itemgetter(*kinds))
        return template
