"""The reference following interpretation alternatives it does not declare, as an emulator whose
author never read the interpretations would: `--infer` must find them from the answers alone.

PLCVEC_TEST_FOLLOW holds the alternatives, `ID=alt,ID=alt`.
"""
import os

from plcvec_reference.adapter import ReferenceAdapter


class Undeclared(ReferenceAdapter):
    def __init__(self, follow: str | None = None):
        text = os.environ.get("PLCVEC_TEST_FOLLOW", "") if follow is None else follow
        super().__init__(choices=dict(item.split("=", 1) for item in text.split(",") if item))

    def hello(self, request):
        answer = super().hello(request)
        answer["interpretations"] = {}
        return answer
