"""plcvec_verify: run plcvec vectors against an implementation and judge the answers.

    from plcvec_verify import Suite, Selection, InProcess, StdioAdapter, run
    suite = Suite.load("vectors")
    report = run(suite, StdioAdapter("./my-emulator --plcvec"), Selection(tags=("boundary",)))
    report.exit_code   # 0 passed, 1 failures, 2 the adapter could not be driven, 5 nothing tested

The contract an implementation follows is verifiers/CONTRACT.md; the process protocol is
verifiers/PROTOCOL.md. This package needs only the vector files, not the generator.
"""
from .adapters import Answer, InProcess, load_python_adapter
from .errors import VerifyError
from .gate import NOTHING_TESTED, Gate
from .known import KnownFailures
from .runner import FAILING, STATUSES, Plan, RunReport, VectorResult, run
from .stdio import StdioAdapter
from .suite import Selection, Suite, parse_shard, shard_of

__all__ = ["Suite", "Selection", "InProcess", "StdioAdapter", "run", "Plan", "RunReport", "VectorResult",
           "KnownFailures", "VerifyError", "Answer", "load_python_adapter", "parse_shard", "shard_of",
           "STATUSES", "FAILING", "Gate", "NOTHING_TESTED"]
