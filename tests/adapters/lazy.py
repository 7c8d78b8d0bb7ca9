"""Adapters that try to pass the gate by doing nothing, for the gate tests.

    plcvec verify --python tests/adapters/lazy.py:SupportsNothing   # declares no instruction
    plcvec verify --python tests/adapters/lazy.py:SkipsEverything   # answers `skip` to every vector
    plcvec verify --python tests/adapters/lazy.py:OnlyTadd          # the reference, TADD only
    plcvec verify --adapter "python3 tests/adapters/lazy.py SkipsEverything"   # the same as a process
"""
import sys

from plcvec_reference.adapter import ReferenceAdapter
from plcvec_verify.implementation import skip
from plcvec_verify.serve import serve


class SupportsNothing(ReferenceAdapter):
    def hello(self, request):
        return dict(super().hello(request), instructions=[])


class SkipsEverything(ReferenceAdapter):
    def run(self, request):
        return skip("not implemented yet")


class OnlyTadd(ReferenceAdapter):
    def hello(self, request):
        return dict(super().hello(request), instructions=["TADD"])


if __name__ == "__main__":
    sys.exit(serve(globals()[sys.argv[1]]()))
