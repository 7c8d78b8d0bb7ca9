"""Which vectors of a loaded set a run takes (VOCABULARY.md: `selection`).

Filters by family, instruction, tag, id glob, interpretation and shard; a name the set does not have
is refused rather than selecting nothing (a gate must never pass by accident). A loaded set (suite.Suite)
is read only through its `names()`, `by_id`, `vectors` and `source`, and not imported: suite.py
names these for the users of 0.1.0, who import them from there.
"""
from __future__ import annotations

import fnmatch
import zlib
from dataclasses import dataclass

from .errors import VerifyError
from .vector import touched_interpretations


@dataclass(frozen=True)
class Selection:
    """Filters; each list is OR within itself, and the filters are AND together."""

    families: tuple = ()
    instructions: tuple = ()
    tags: tuple = ()
    ids: tuple = ()                  # glob patterns (fnmatch) on the id
    interpretations: tuple = ()      # vectors whose outcome depends on one of these
    shard: tuple | None = None       # (k, n), 1 <= k <= n

    def matches(self, v: dict) -> bool:
        if self.families and v["family"] not in self.families:
            return False
        if self.instructions and v["instruction"] not in self.instructions:
            return False
        if self.tags and not set(self.tags) & set(v.get("tags", ())):
            return False
        if self.ids and not any(fnmatch.fnmatchcase(v["id"], p) for p in self.ids):
            return False
        if self.interpretations and not set(self.interpretations) & touched_interpretations(v):
            return False
        if self.shard and shard_of(v["id"], self.shard[1]) != self.shard[0]:
            return False
        return True

    @property
    def everything(self) -> bool:
        """Whether the selection has no filter at all (every vector is selected)."""
        return not (self.families or self.instructions or self.tags or self.ids or self.interpretations
                    or self.shard)

    def apply(self, vectors: list[dict]) -> list[dict]:
        if self.everything:     # the usual gate run: no per-vector test to pay for
            return list(vectors)
        return [v for v in vectors if self.matches(v)]

    def check(self, suite, option_prefix: str = "--", labels: dict | None = None) -> None:
        """Refuse names the suite does not have, listing those it has, and id globs that match nothing.

        An unknown name would select nothing, and a gate that selects nothing must not look like one
        that passed; a usage error says which word was mistyped. `labels` names where a kind of
        filter came from when not from an option (`{"family": "PLCVEC_FAMILY"}`).
        """
        labels = labels or {}
        named = (("family", self.families), ("instruction", self.instructions), ("tag", self.tags),
                 ("interpretation", self.interpretations))
        # The names are gathered from every vector: only when a name was given to check.
        known = suite.names() if any(given for _, given in named) else {}
        for kind, given in named:
            label = labels.get(kind, f"{option_prefix}{kind}")
            for name in given:
                if name not in known[kind]:
                    what = "an empty name is not a filter" if not name.strip() else \
                        f"{suite.source} has no such {kind}"
                    shown = f"{label}={','.join(given)}" if not name.strip() else f"{label} {name}"
                    raise VerifyError(f"{shown}: {what}; known: {', '.join(known[kind]) or '(none)'}")
        label = labels.get("id", f"{option_prefix}id")
        for pattern in self.ids:
            if not any(fnmatch.fnmatchcase(vid, pattern) for vid in suite.by_id):
                example = next(iter(suite.by_id), "")
                raise VerifyError(f"{label} {pattern}: matches no vector id in {suite.source} "
                                  f"(ids look like {example}; a glob matches the whole id)")


def select(suite, selection: Selection = Selection()) -> list[dict]:
    """The vectors of `suite` that `selection` takes, in the set's order, after refusing a name the set
    does not have or an id glob that matches nothing (`Selection.check`)."""
    selection.check(suite)
    return suite.vectors if selection.everything else selection.apply(suite.vectors)


def shard_of(vector_id: str, n: int) -> int:
    """The shard (1..n) a vector belongs to.

    A hash of the id rather than its position: adding a vector to the suite moves no other vector
    to another shard, so a CI job's history stays comparable.
    """
    return zlib.crc32(vector_id.encode("utf-8")) % n + 1


def parse_shard(text: str, option: str = "--shard") -> tuple[int, int]:
    try:
        k, n = (int(x) for x in text.split("/"))
    except ValueError:
        raise VerifyError(f"{option} takes K/N (e.g. 2/4), got {text!r}")
    if not 1 <= k <= n:
        raise VerifyError(f"{option} {text}: K must be between 1 and N")
    return k, n


__all__ = ["Selection", "select", "shard_of", "parse_shard"]
