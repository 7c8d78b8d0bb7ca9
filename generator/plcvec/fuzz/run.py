"""Running fuzz vectors through the implementation under test and judging its answers.

The judging is plcvec_verify's own (the handshake, the interpretation alternatives the adapter
declares, the expectation under them, the field-by-field comparison), so a disagreement found here
is exactly a failure `plcvec verify` would report for the same vector.
"""
import random
from dataclasses import dataclass, field

from plcvec_verify.adapters import result_message
from plcvec_verify.compare import compare
from plcvec_verify.expect import expected_of, request_of
from plcvec_verify.protocol import hello_request, result_errors
from plcvec_verify.runner import resolve_choices
from plcvec_verify.suite import Suite

from plcvec import SCHEMA_VERSION, __version__
from plcvec.spec.instructions import instruction_list
from plcvec.fuzz.seeded import draw_seeded
from plcvec.output.golden import family_header
from plcvec.spec.loader import spec_hash


def spec_suite(families, source):
    """The suite as a runner announces it in the handshake, worked out from the spec in process:
    fuzzing follows the spec it is given, not whatever vector files happen to be on disk."""
    headers = {}
    for fam in families:
        header = family_header(fam, [])
        header["instructions"] = sorted(i["name"] for i in instruction_list(fam))
        headers[fam.name] = header
    return Suite(vectors=[], headers=headers, source=str(source), suite_version=__version__,
                 schema_version=SCHEMA_VERSION, spec_sha256=spec_hash(families))


@dataclass
class Verdict:
    differs: bool
    lines: list = field(default_factory=list)   # what differs: Problem.line() each, or the adapter's fault
    skipped: str = ""                           # the adapter's reason for not running the vector


class Target:
    """The implementation under test, after the handshake: what it supports and which readings it follows."""

    def __init__(self, adapter, suite, families, choose):
        self.adapter = adapter
        names = sorted(fam.name for fam in families)
        hello = adapter.hello(hello_request(suite, names))
        self.name = hello["adapter"]
        self.interpretations = resolve_choices(suite, names, hello.get("interpretations", {}), choose)
        self.choices = {i: d["alternative"] for i, d in self.interpretations.items()}
        self.defaults = {i: d["default"] for i, d in suite.interpretations().items()}
        self.supported = set(hello["instructions"])
        self.requests = 0
        self.skipped = 0

    def judge(self, vectors, ids=None):
        """A Verdict per vector, in order. Each request gets an id of its own, `<vector id>@<n>`, so that
        what the adapter writes (stderr notes, faults) names the very run, though shrinking runs one
        vector many times."""
        sent = {}
        for i, vector in enumerate(vectors):
            self.requests += 1
            request = request_of(vector)
            request["id"] = ids[i] if ids else f"{vector['id']}@{self.requests}"
            sent[request["id"]] = (vector, request)
        verdicts = {}
        for answer in self.adapter.answers([request for _, request in sent.values()]):
            rid = answer[0]     # an Answer, or a plain tuple of its fields (adapters.result_message)
            if rid in sent:
                verdicts[rid] = self._verdict(sent[rid][0], answer)
        return [verdicts.get(rid) or Verdict(True, ["the adapter gave no answer"]) for rid in sent]

    def _verdict(self, vector, answer):
        fault = answer[2]
        if fault:
            return Verdict(True, [fault])
        msg = result_message(answer)
        errors = result_errors(msg)
        if errors:
            return Verdict(True, ["the result does not match result.schema.json: " + "; ".join(errors)])
        if "skip" in msg:
            self.skipped += 1
            return Verdict(False, skipped=msg["skip"])
        if "error" in msg:
            return Verdict(True, [f"the adapter reported an error: {msg['error']}"])
        problems = compare(expected_of(vector, self.choices, self.defaults), msg["steps"])
        return Verdict(bool(problems), [p.line() for p in problems])

    def differs(self, vector):
        return self.judge([vector])[0].differs

    def close(self):
        self.adapter.close()


@dataclass
class Found:
    examples: int                  # examples drawn up to and including the first disagreement
    choices: tuple | None = None   # hypothesis' choices for that example (None: no disagreement)


def search(space, target, examples, seed, batch_size):
    """Draw `examples` cases from `seed` and run them, `batch_size` to a request; stop at the first
    disagreement. The draws depend on the seed alone, never on the answers, so the count and the
    example found do not depend on the batch size either."""
    rng = random.Random(seed)
    done = 0
    while done < examples:
        batch = [draw_seeded(space.strategy, rng) for _ in range(min(batch_size, examples - done))]
        verdicts = target.judge([space.vector(case) for case, _ in batch])
        for i, ((_, choices), verdict) in enumerate(zip(batch, verdicts)):
            if verdict.differs:
                return Found(done + i + 1, choices)
        done += len(batch)
    return Found(done)
