"""The spec engine: a few generic rule kinds that the YAML parameterizes.

Nothing here names an instruction, a range, a bit or an error code: those all come from the
resolved spec document handed to each kind.

Each kind has `execute(instr, operands, state, step, ctx, trace)`: one execution (scan), which updates
`state` (device -> value), adds to `trace` the ids of the clauses it applies, and records an error
in ctx["error"].

Which interpretations an execution consulted is recorded the same way, by the document it reads:
`VectorBuilder.execute(instr, operands, devices, steps, scratch, choices)` (plcvec.cases.build)
returns a Run whose `consulted` is the frozenset of the interpretation ids whose chosen value the
execution read (spec.knobs.Consulting does the recording). A result depends only on the
interpretations it consulted, so the builder runs a case under the combinations of those alone
(`VectorBuilder.runs`). For that to hold, a kind:
- reads a parameter an interpretation may set where it uses it, not in __init__: what is read while
  the engine is built counts as consulted by every execution (exact, but every case then runs under
  every alternative of it);
- asks a parameter only when its value can change the outcome (e.g. the scope of a range check only
  when some value is out of range), so that cases it cannot affect are not run again for it;
- keeps no state between executions except in `ctx` and `state`.
"""
from plcvec.engine.clock_add import ClockAdd
from plcvec.engine.hour_meter import HourMeter
from plcvec.engine.masked_compare import MaskedCompare

KINDS = {"masked_compare": MaskedCompare, "clock_add": ClockAdd, "hour_meter": HourMeter}


def make_engine(resolved_doc):
    return KINDS[resolved_doc["kind"]](resolved_doc)
