"""The spec engine: a few generic rule kinds that the YAML parameterizes.

Nothing here names an instruction, a range, a bit or an error code: those all come from the
resolved spec document handed to each kind.
"""
from plcvec.engine.clock_add import ClockAdd
from plcvec.engine.hour_meter import HourMeter
from plcvec.engine.masked_compare import MaskedCompare

KINDS = {"masked_compare": MaskedCompare, "clock_add": ClockAdd, "hour_meter": HourMeter}


def make_engine(resolved_doc):
    return KINDS[resolved_doc["kind"]](resolved_doc)
