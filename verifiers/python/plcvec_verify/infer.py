"""Which interpretation alternatives an implementation's answers follow (`plcvec verify --infer`).

A vector that depends on interpretations carries an expectation for every combination of their
alternatives (its own `steps`/`final` for the defaults, an `alternatives` entry for each other
combination). The answers of one run are judged against every offered combination; one choice of
alternatives for the whole run is then found that explains as many vectors as it can. The same
inference makes the roll-up by reading at the end of every failing run, so what a run says would
explain its failures is what `--infer` declares. verifiers/parity/TEXT.md states the procedure so
that every runner finds the same choice.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from itertools import combinations

from ._report import Report
from .compare import compare
from .verdict import ERROR, FAIL, NOT_RUN, PASS, XFAIL


@dataclass(frozen=True)
class Judged:
    """One vector with an answer: the combinations of its interpretations under which it passes."""

    id: str
    touched: tuple              # the interpretations its outcome depends on, sorted by id
    passing: frozenset          # tuples of alternatives (in `touched` order) the answer passes under
    failed: bool                # it failed under the followed alternatives


@dataclass
class Inference:
    followed: dict                                  # interpretation -> alternative the run followed
    choice: dict                                    # interpretation -> alternative that explains most
    explained: dict = field(default_factory=dict)   # failing id -> ((interpretation, alternative), ...)
    unexplained: list = field(default_factory=list)  # failing ids no offered reading explains
    known_explained: dict = field(default_factory=dict)  # known failure (xfail) id -> its smallest change
    known_unexplained: list = field(default_factory=list)  # known failures no offered reading explains
    broken: list = field(default_factory=list)      # passing ids that would fail under `choice`
    judged: int = 0                                 # vectors with an answer to judge

    @property
    def changes(self) -> dict:
        """interpretation -> alternative for each one `choice` sets otherwise than `followed`."""
        return {i: a for i, a in sorted(self.choice.items()) if self.followed.get(i) != a}

    @property
    def complete(self) -> bool:
        """Whether one choice of alternatives explains every vector of the run."""
        return not self.unexplained and not self.broken


def offered(vector: dict, defaults: dict) -> list[dict]:
    """The combinations of alternatives `vector` offers an expectation for: the defaults first (its own
    `steps`), then each `alternatives` entry in file order (only the interpretations it touches)."""
    touched = vector["outcome"].get("interpretations", ())
    combos = [{i: defaults[i] for i in touched}]
    for alt in vector.get("alternatives", ()):
        if all(i in alt["choices"] for i in touched):
            combos.append({i: alt["choices"][i] for i in touched})
    return combos


def _same_expectation(under, followed) -> bool:
    """Whether an answer that passes under the `followed` expectation passes under `under` too, known
    from the two expectations alone: every step's result is equal, and every device `under` judges is
    expected alike (value and JSON type) by both. A device `under` judges but `followed` leaves
    unjudged makes them differ: what the answer holds there is not known from `followed`."""
    if under.results != followed.results:
        return False
    if not under.unjudged and not followed.unjudged:
        return under.states == followed.states and all(
            type(x[k]) is type(y[k]) for x, y in zip(under.states, followed.states) for k in x)
    hidden = followed.left_out
    for x, y in zip(under.compared, followed.states):
        for k, v in x.items():
            if k in hidden or v != y[k] or type(v) is not type(y[k]):
                return False
    return True


def judge_all(report: Report, cpu_writes=frozenset()) -> list[Judged]:
    """Every vector of `report` with an answer (passed, failed, or a failure the expectations file
    lists), with the offered combinations under which that answer passes."""
    suite = report.suite
    known = suite.interpretations()
    defaults = {i: d["default"] for i, d in known.items()}
    followed = {i: d["alternative"] for i, d in report.interpretations.items()}
    for i, d in known.items():
        followed.setdefault(i, d["default"])
    expectations = suite.expectations
    # An interpretation no failing vector touches can gain nothing, so the inference never moves it:
    # a passing vector that touches only such ones needs no expectation under other alternatives.
    movable = set()
    for r in report.results:
        if r.status in (FAIL, XFAIL) and r.answer is not None and r.id in suite.by_id:
            movable.update(suite.by_id[r.id]["outcome"].get("interpretations", ()))
    out = []
    for r in report.results:
        answered = r.status == PASS or (r.status in (FAIL, XFAIL) and r.answer is not None)
        if not answered or r.id not in suite.by_id:
            continue
        vector = suite.by_id[r.id]
        touched = tuple(sorted(vector["outcome"].get("interpretations", ())))
        if not touched:
            out.append(Judged(r.id, (), frozenset([()]) if r.status == PASS else frozenset(), r.status != PASS))
            continue
        if r.status == PASS and movable.isdisjoint(touched):
            out.append(Judged(r.id, touched, frozenset([tuple(followed[i] for i in touched)]), False))
            continue
        mine = expectations.expected(vector, followed, defaults)
        passing = set()
        for combo in offered(vector, defaults):
            key = tuple(combo[i] for i in touched)
            exp = expectations.expected(vector, combo, defaults)
            if r.status == PASS:
                ok = _same_expectation(exp, mine)
            else:
                ok = _answer_passes(exp, r.answer, cpu_writes)
            if ok:
                passing.add(key)
        out.append(Judged(r.id, touched, frozenset(passing), r.status != PASS))
    return out


def _answer_passes(expected, steps, cpu_writes) -> bool:
    try:
        return compare(expected, steps, cpu_writes) == []
    except (AttributeError, KeyError, TypeError):   # an answer of the wrong shape passes nothing
        return False


def infer(judged: list[Judged], alternatives: dict, followed: dict, unjudging=frozenset()) -> dict:
    """The choice of alternatives (interpretation -> alternative) that explains the most vectors.

    Starting from `followed`, each interpretation in id order is given, of its alternatives in the
    order the vector files list them, the one that explains strictly the most vectors with every
    other interpretation held as it stands (the current one is kept on a tie); passes repeat until
    one changes nothing. A vector is explained when its answer passes under the choice restricted to
    the interpretations it touches. `alternatives`: interpretation -> its alternatives, in file order.

    The search runs twice: first without the alternatives that leave devices unjudged (`unjudging`,
    (interpretation, alternative) pairs), then from where it ended with every alternative. A reading
    that judges nothing of a device explains any answer there, so it is taken only for what no reading
    that judges explains; tried first, it would take the failures of another interpretation's reading
    (its id comes first) and be proposed for them.
    """
    judging = {i: [a for a in alts if (i, a) not in unjudging] for i, alts in alternatives.items()}
    first = _search(judged, judging, followed)
    return _search(judged, alternatives, first) if unjudging else first


def _search(judged: list[Judged], alternatives: dict, start: dict) -> dict:
    """infer()'s search from `start` over `alternatives` (interpretation -> those it may take)."""
    choice = dict(start)
    by_interp: dict[str, list[Judged]] = {}
    for j in judged:
        for i in j.touched:
            by_interp.setdefault(i, []).append(j)

    def score(vectors, trial):
        return sum(tuple(trial[i] for i in j.touched) in j.passing for j in vectors)

    changed = True
    while changed:
        changed = False
        for interp in sorted(alternatives):
            vectors = by_interp.get(interp, ())
            if not vectors:
                continue
            best, best_score = choice[interp], score(vectors, choice)
            for alt in alternatives[interp]:
                if alt == choice[interp]:
                    continue
                s = score(vectors, {**choice, interp: alt})
                if s > best_score:
                    best, best_score = alt, s
            if best != choice[interp]:
                choice[interp] = best
                changed = True
    return choice


def unjudging_alternatives(suite) -> frozenset:
    """(interpretation, alternative) for each alternative some vector's entry leaves devices unjudged under."""
    return frozenset((i, alt["choices"][i]) for v in suite.vectors for alt in v.get("alternatives", ())
                     for i in alt.get("unjudged", ()))


def inference(report: Report, cpu_writes=frozenset()) -> Inference:
    """The inference over one run: the choice, and what it explains of the run's failures."""
    known = report.suite.interpretations()
    followed = {i: d["alternative"] for i, d in report.interpretations.items()}
    for i, d in known.items():
        followed.setdefault(i, d["default"])
    alternatives = {i: known[i]["alternatives"] for i in report.interpretations}
    judged = judge_all(report, cpu_writes)
    choice = infer(judged, alternatives, followed, unjudging_alternatives(report.suite))
    result = Inference(followed=followed, choice=choice, judged=len(judged))
    by_id = {j.id: j for j in judged}
    statuses = {r.id: r.status for r in report.results}
    for r in report.results:
        if r.status not in (FAIL, ERROR, NOT_RUN, XFAIL):
            continue
        explained, unexplained = ((result.known_explained, result.known_unexplained) if r.status == XFAIL
                                  else (result.explained, result.unexplained))
        j = by_id.get(r.id)
        if j is None or tuple(choice[i] for i in j.touched) not in j.passing:
            unexplained.append(r.id)
        else:
            explained[r.id] = _smallest_change(j, followed, choice)
    for j in judged:
        if statuses.get(j.id) == PASS and tuple(choice[i] for i in j.touched) not in j.passing:
            result.broken.append(j.id)
    return result


def declaration_lines(report: Report, inferred: Inference) -> list[str]:
    """What `--infer` prints after the roll-up: the alternatives found, the `--choose` line and the
    hello declaration that give them, and whether one choice explains every vector (TEXT.md)."""
    lines = [f"INFERRED from {inferred.judged} judged vectors:"]
    for interp, alt in sorted(inferred.choice.items()):
        if interp not in report.interpretations:
            continue
        followed = report.interpretations[interp]
        if alt != followed["alternative"]:
            how = f"inferred; followed {followed['alternative']}"
        else:
            how = "declared" if followed["declared"] else "default"
        lines.append(f"    {interp}={alt} ({how})")
    chosen = {i: a for i, a in sorted(inferred.choice.items()) if i in report.interpretations}
    lines.append("choose: " + " ".join(f"--choose {i}={a}" for i, a in chosen.items()))
    lines.append('hello: "interpretations": {' + ", ".join(f'"{i}": "{a}"' for i, a in chosen.items()) + "}")
    if inferred.complete:
        lines.append("one choice of alternatives explains every vector")
    else:
        lines.append(f"no one choice of alternatives explains every vector: {len(inferred.unexplained)} failing "
                     f"vectors not explained, {len(inferred.broken)} passing vectors would fail")
    return lines


def _smallest_change(j: Judged, followed: dict, choice: dict) -> tuple:
    """The fewest interpretations (first in id order among as few) whose change to `choice` makes
    failing vector `j` pass: what explains it."""
    flipped = [i for i in j.touched if choice[i] != followed[i]]
    for size in range(1, len(flipped) + 1):
        for subset in combinations(flipped, size):
            trial = {**followed, **{i: choice[i] for i in subset}}
            if tuple(trial[i] for i in j.touched) in j.passing:
                return tuple((i, choice[i]) for i in subset)
    return tuple((i, choice[i]) for i in flipped)


__all__ = ["Inference", "Judged", "inference", "infer", "judge_all", "offered", "declaration_lines"]
