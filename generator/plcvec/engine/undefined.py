"""Where the pages define no behaviour, an alternative may leave devices unjudged.

An interpretation's alternative that says so sets its rule parameter to UNDEFINED. An engine that
meets the state that parameter decides, and finds it UNDEFINED, calls `met(ctx, parameter)` and writes
nothing for that execution; the builder then leaves the devices the alternative names (its
`unjudged`) out of that expectation (plcvec.cases.build).
"""
UNDEFINED = "undefined"


def met(ctx, parameter):
    """Record that this run met a state the chosen reading of `parameter` leaves undefined."""
    ctx.setdefault("undefined", set()).add(parameter)
