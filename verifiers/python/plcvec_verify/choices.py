"""Interpretation choices (VOCABULARY.md: `choices`): the alternatives an implementation declares, and
the ones a run follows.

An implementation declares, in its handshake, the alternative it follows for some interpretations;
a user may give others on the command line (`--choose`). A run follows, for every interpretation of
the families it runs, the declared alternative or else the default; a verdict records the ones its
vector depends on (its `choices`, the `judged_by` of the other runners).
"""
from __future__ import annotations

from .errors import VerifyError

# interpretation id -> alternative id, as declared (hello) or given (--choose).
Choices = dict[str, str]
# interpretation id -> {"alternative", "declared": bool, "families"}: what a run follows (Report).
Followed = dict[str, dict]


def defaults_of(suite) -> Choices:
    """Every interpretation of a loaded set with its default alternative."""
    return {i: d["default"] for i, d in suite.interpretations().items()}


def resolve_choices(suite, families, declared: Choices, cli: Choices) -> Followed:
    """interpretation -> {"alternative", "declared", "families"} for every interpretation of `families`.

    An interpretation or alternative the set does not define is refused, by its source, and so is a
    `--choose` that contradicts what the adapter declares: a run must not judge by a reading nobody
    follows.
    """
    known = suite.interpretations()
    for source, choices in (("the adapter declares", declared), ("--choose gives", cli)):
        for interp, alt in choices.items():
            if interp not in known:
                raise VerifyError(f"{source} interpretation {interp!r}, which no vector file defines "
                                  f"(known: {', '.join(sorted(known))})")
            if alt not in known[interp]["alternatives"]:
                raise VerifyError(f"{source} {interp}={alt}, but {interp} has the alternatives "
                                  f"{', '.join(known[interp]['alternatives'])}")
    for interp, alt in cli.items():
        if interp in declared and declared[interp] != alt:
            raise VerifyError(f"--choose {interp}={alt}, but the adapter declares {interp}={declared[interp]}")
    out = {}
    for interp, d in sorted(known.items()):
        if not set(d["families"]) & set(families):
            continue
        chosen = declared.get(interp, cli.get(interp))
        out[interp] = {"alternative": chosen or d["default"], "declared": chosen is not None,
                       "families": d["families"]}
    return out


def followed_alternatives(followed: Followed) -> Choices:
    """interpretation -> the alternative a run follows."""
    return {i: d["alternative"] for i, d in followed.items()}


def applied_choices(vector: dict, choices: Choices, defaults: Choices) -> Choices:
    """interpretation -> the alternative `vector` is judged by: those it touches, declared or default."""
    return {i: choices.get(i, defaults.get(i)) for i in vector["outcome"].get("interpretations", ())}


__all__ = ["Choices", "Followed", "defaults_of", "resolve_choices", "followed_alternatives", "applied_choices"]
