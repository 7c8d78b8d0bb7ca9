"""The exhaustive tier: every value of the selector/mask word for every condition, as JSON Lines.

Written on demand, never committed. Lines are streamed one at a time, so memory stays flat however
many are written. Each line is a vector in the golden format, for the LD form, under one fixed set of
interpretation choices (the defaults unless --choose says otherwise), named in the file's first line.
"""
import json
import time

from plcvec import SCHEMA_VERSION
from plcvec.cases.build import VectorBuilder
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


def stream_exhaustive(families, out_dir, only=None, choices=None):
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
                               {k: v for k, v in choices.items() if k in fam.interpretations})
    return count, time.perf_counter() - start


def _write_family(fam, path, choices):
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
    # Every line is built from constant pieces around the few values that vary: the selector value,
    # what the comparison wrote, and the result. The selector device is set to a marker and split on.
    marker = -12345
    state0 = dict(devices)
    state0[sel_head] = marker
    common = (f'"tags": ["exhaustive"], "assumes": {{"device_sizes": {dumps_value(sizes)}}}, '
              f'"initial": {{"operands": {dumps_value(operands)}, "devices": ')
    pre_init, post_init = dumps_value(dict(sorted(state0.items()))).split(str(marker))
    clock_part = f'"clock": {dumps_value(b)}, '
    conditions = {c["symbol"]: c for c in fam.doc["instructions"]["conditions"]}
    names = [(json.dumps(f"{fam.name}/{name}/exhaustive/"), json.dumps(name), json.dumps(instr["st"]), instr["symbol"],
              {instr["form"]["clause"], conditions[instr["symbol"]]["clause"]})
             for name, instr in loads]
    selop = cases.selop
    clause_cache = {}
    source_bit = cases.clock_bit["bit"] if cases.clock_bit else None
    tmp = path.with_name(f".{path.name}.partial")
    n = 0
    with open(tmp, "w", encoding="utf-8") as out:
        out.write(json.dumps(header, sort_keys=True) + "\n")
        for sel in range(WORD_VALUES):
            state = dict(devices)
            state[sel_head] = sel
            step = {"clock": b} if source_bit is not None and sel >> source_bit & 1 else {}
            ctx = {"device_sizes": sizes}
            before = dict(state)
            trace = set()
            outcome = engine.evaluate(operands, state, step, ctx, trace)
            trace.discard(None)
            traced = frozenset(trace)
            changed = dumps_value({k: v for k, v in sorted(state.items()) if before[k] != v})
            error = ctx.get("error")
            result_outcome = ('{"category": "error", "errors": [%s]}' % dumps_value(dict(step=0, **error))) if error else '{"category": "value"}'
            tail_state = dumps_value(dict(sorted(state.items())))
            initial = f"{pre_init}{sel}{post_init}"
            clock = clock_part if step else ""
            sel_id = f"{sel:04X}H"
            description = f'"description": "{selop} = {sel_id}", '
            for vid, name, st, symbol, own in names:
                result = "true" if engine.contact(symbol, outcome) else "false"
                key = (traced, symbol)
                clauses = clause_cache.get(key)
                if clauses is None:  # few distinct clause sets: format each once
                    clauses = clause_cache[key] = json.dumps(sorted(fam.clause_ref(c) for c in trace | own))
                out.write(f'{{"id": {vid[:-1]}{sel_id}", "family": "{fam.name}", "instruction": {name}, "st": {st}, '
                          f'{description}"clauses": {clauses}, {common}{initial}}}, '
                          f'"steps": [{{{clock}"expect": {{"devices": {changed}, "result": {result}}}}}], '
                          f'"final": {{"devices": {tail_state}}}, "outcome": {result_outcome}}}\n')
                n += 1
    tmp.replace(path)
    return n
