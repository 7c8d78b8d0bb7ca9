"""plcvec_verify: run plcvec vectors against an implementation and judge the answers.

    from plcvec_verify import Suite, Selection, InProcess, StdioAdapter, run
    suite = Suite.load("vectors")
    report = run(suite, StdioAdapter("./my-emulator --plcvec"), Selection(tags=("boundary",)))
    report.exit_code   # 0 passed, 1 failures, 2 the adapter could not be driven, 5 nothing tested

The contract an implementation follows is verifiers/CONTRACT.md; the process protocol is
verifiers/PROTOCOL.md. This package needs only the vector files, not the generator.
"""
from __future__ import annotations

import importlib
from typing import TYPE_CHECKING

from ._renamed import old_names

# Each name is imported from its module when first used, not with the package: an adapter process
# (plcvec_verify.serve), `plcvec lint` and every other command that imports one submodule would
# otherwise load the runner, the gate, the stdio driver and the known-failures reader at start-up.
_WHERE = {
    "Answer": "adapters", "InProcess": "adapters", "load_python_adapter": "adapters",
    "VerifyError": "errors",
    "NOTHING_TESTED": "gate", "Gate": "gate",
    "KnownFailures": "known",
    "FAILING": "runner", "STATUSES": "runner", "Plan": "runner", "Report": "runner", "Verdict": "runner",
    "run": "runner",
    "StdioAdapter": "stdio",
    "Selection": "suite", "Suite": "suite", "parse_shard": "suite", "shard_of": "suite",
}

# RENAMED: 0.1.0's names, deprecated until 0.4.0 (old -> new). They stay in __all__, so that
# `from plcvec_verify import *` still gives them, with the warning.
RENAMED = {"RunReport": "Report", "VectorResult": "Verdict"}

__all__ = ["Suite", "Selection", "InProcess", "StdioAdapter", "run", "Plan", "Report", "Verdict",
           "KnownFailures", "VerifyError", "Answer", "load_python_adapter", "parse_shard", "shard_of",
           "STATUSES", "FAILING", "Gate", "NOTHING_TESTED", *RENAMED]


def _lazy(name: str):
    if name not in _WHERE:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(f".{_WHERE[name]}", __name__), name)
    globals()[name] = value
    return value


# An old name is never kept in globals(), so that every use warns.
__getattr__ = old_names(__name__, RENAMED, _lazy)


def __dir__():
    return sorted(set(globals()) | set(__all__))


if TYPE_CHECKING:
    from .adapters import Answer, InProcess, load_python_adapter
    from .errors import VerifyError
    from .gate import NOTHING_TESTED, Gate
    from .known import KnownFailures
    from .runner import FAILING, STATUSES, Plan, Report, RunReport, Verdict, VectorResult, run
    from .stdio import StdioAdapter
    from .suite import Selection, Suite, parse_shard, shard_of
