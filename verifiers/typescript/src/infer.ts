/**
 * Which interpretation alternatives an implementation's answers follow: the inference behind the
 * roll-up by reading (verifiers/parity/TEXT.md, "The inference"), the same procedure as
 * `plcvec verify --infer`, so that every runner finds the same choice.
 *
 * A vector that depends on interpretations carries an expectation for every combination of their
 * alternatives. The answers of one run are judged against every offered combination; one choice
 * of alternatives for the whole run is then found that explains as many vectors as it can.
 */
import { compare } from "./compare.js";
import { expectedOf, type Expected } from "./expect.js";
import type { Suite } from "./suite.js";
import { ERROR, FAIL, offered, PASS, XFAIL, type Verdict } from "./verdict.js";
import type { Vector } from "./vector.js";

/** One vector with an answer: the combinations of its interpretations under which it passes. */
interface Judged {
  readonly id: string;
  /** The interpretations its outcome depends on, sorted. */
  readonly touched: readonly string[];
  /** Keys of the combinations (alternatives in `touched` order) it passes under. */
  readonly passing: ReadonlySet<string>;
}

export interface Inference {
  /** Interpretation -> the alternative the run followed. */
  readonly followed: Readonly<Record<string, string>>;
  /** Interpretation -> the alternative that explains the most vectors. */
  readonly choice: Readonly<Record<string, string>>;
  /** Failing id -> its smallest change, as [interpretation, alternative] pairs. */
  readonly explained: ReadonlyMap<string, readonly (readonly [string, string])[]>;
  /** Failing ids no offered reading explains, in run order. */
  readonly unexplained: readonly string[];
  /** Known failure (xfail) id -> its smallest change. */
  readonly knownExplained: ReadonlyMap<string, readonly (readonly [string, string])[]>;
  /** Known failures no offered reading explains, in run order. */
  readonly knownUnexplained: readonly string[];
  /** Passing ids that would fail under `choice`. */
  readonly broken: readonly string[];
  readonly judged: number;
}

const keyOf = (touched: readonly string[], combo: Readonly<Record<string, string>>): string => touched.map((i) => combo[i]).join("\u0000");

/**
 * Whether a vector that passes under the followed expectation also passes under `c`: the same
 * result at every step, and every device judged under `c` expected alike (value and JSON type)
 * under both; a device judged under `c` but unjudged under the followed one makes them differ
 * (its answer is not known to the expectation). A device `c` leaves unjudged is not compared.
 */
export function sameExpectation(c: Expected, followed: Expected): boolean {
  if (c.results.length !== followed.results.length || c.results.some((r, i) => r !== followed.results[i])) return false;
  const has = Object.prototype.hasOwnProperty;
  return c.states.every((s, i) => {
    const t = followed.states[i]!;
    for (const k in s) if (!has.call(t, k) || s[k] !== t[k]) return false;
    for (const k in t) if (!has.call(s, k) && !c.ignored.has(k)) return false;
    return true;
  });
}

function judgeAll(verdicts: readonly Verdict[], suite: Suite, followed: Readonly<Record<string, string>>, defaults: Readonly<Record<string, string>>, cpuWrites: ReadonlySet<string>): Judged[] {
  const out: Judged[] = [];
  for (const v of verdicts) {
    const answered = v.status === PASS || ((v.status === FAIL || v.status === XFAIL) && v.answer !== undefined);
    const vector: Vector | undefined = suite.byId.get(v.id);
    if (!answered || vector === undefined) continue;
    const touched = [...(vector.outcome.interpretations ?? [])].sort();
    if (touched.length === 0) {
      out.push({ id: v.id, touched, passing: new Set(v.status === PASS ? [""] : []) });
      continue;
    }
    const mine = expectedOf(vector, followed, defaults);
    const passing = new Set<string>();
    for (const combo of offered(vector, defaults)) {
      const expected = expectedOf(vector, combo, defaults);
      let ok: boolean;
      if (v.status === PASS) ok = sameExpectation(expected, mine);
      else {
        try {
          ok = compare(expected, v.answer!, cpuWrites).length === 0;
        } catch {
          ok = false; // an answer of the wrong shape passes nothing
        }
      }
      if (ok) passing.add(keyOf(touched, combo));
    }
    out.push({ id: v.id, touched, passing });
  }
  return out;
}

/**
 * The choice that explains the most vectors: starting from `followed`, each interpretation in id
 * order is given, of its alternatives in file order, the one that explains strictly the most vectors
 * with every other interpretation as it stands (a tie keeps the current one); rounds repeat until
 * one changes nothing. The rounds run twice (TEXT.md, step 4): first without the alternatives that
 * leave devices unjudged (`unjudging`), then with every one, from where the first ended: a reading
 * that judges nothing of a device explains any answer there, so it is taken only for what no reading
 * that judges explains.
 */
function choose(
  judged: readonly Judged[],
  alternatives: ReadonlyMap<string, readonly string[]>,
  followed: Readonly<Record<string, string>>,
  unjudging: ReadonlySet<string>,
): Record<string, string> {
  const choice: Record<string, string> = { ...followed };
  const byInterp = new Map<string, Judged[]>();
  for (const j of judged) for (const i of j.touched) (byInterp.get(i) ?? byInterp.set(i, []).get(i)!).push(j);
  const score = (vectors: readonly Judged[], trial: Readonly<Record<string, string>>): number =>
    vectors.reduce((n, j) => n + (j.passing.has(keyOf(j.touched, trial)) ? 1 : 0), 0);
  for (const allowed of [(i: string, alt: string) => !unjudging.has(`${i}=${alt}`), () => true]) {
    for (let changed = true; changed; ) {
      changed = false;
      for (const interp of [...alternatives.keys()].sort()) {
        const vectors = byInterp.get(interp);
        if (vectors === undefined) continue;
        let best = choice[interp]!;
        let bestScore = score(vectors, choice);
        for (const alt of alternatives.get(interp)!) {
          if (alt === choice[interp] || !allowed(interp, alt)) continue;
          const s = score(vectors, { ...choice, [interp]: alt });
          if (s > bestScore) {
            best = alt;
            bestScore = s;
          }
        }
        if (best !== choice[interp]) {
          choice[interp] = best;
          changed = true;
        }
      }
    }
  }
  return choice;
}

/** `ID=alternative` of each alternative some vector's alternatives entry leaves devices unjudged under. */
function unjudgingAlternatives(suite: Suite): Set<string> {
  const out = new Set<string>();
  for (const v of suite.vectors) {
    for (const alt of v.alternatives ?? []) for (const id of Object.keys(alt.unjudged ?? {})) out.add(`${id}=${alt.choices[id]}`);
  }
  return out;
}

/** The fewest interpretations (first in id order among as few) whose change to `choice` makes `j` pass. */
function smallestChange(j: Judged, followed: Readonly<Record<string, string>>, choice: Readonly<Record<string, string>>): [string, string][] {
  const flipped = j.touched.filter((i) => choice[i] !== followed[i]);
  for (let size = 1; size <= flipped.length; size++) {
    for (const subset of combinations(flipped, size)) {
      const trial = { ...followed };
      for (const i of subset) trial[i] = choice[i]!;
      if (j.passing.has(keyOf(j.touched, trial))) return subset.map((i) => [i, choice[i]!]);
    }
  }
  return flipped.map((i) => [i, choice[i]!]);
}

/** itertools.combinations: the subsets of `items` of `size`, in lexicographic order of positions. */
function* combinations<T>(items: readonly T[], size: number, start = 0): Generator<T[]> {
  if (size === 0) {
    yield [];
    return;
  }
  for (let i = start; i <= items.length - size; i++) for (const rest of combinations(items, size - 1, i + 1)) yield [items[i]!, ...rest];
}

/**
 * The inference over one run's verdicts. `alternatives`: each interpretation of the families run
 * with its alternatives in file order.
 */
export function inference(
  verdicts: readonly Verdict[],
  suite: Suite,
  alternatives: ReadonlyMap<string, readonly string[]>,
  followed: Readonly<Record<string, string>>,
  defaults: Readonly<Record<string, string>>,
  cpuWrites: ReadonlySet<string>,
): Inference {
  const judged = judgeAll(verdicts, suite, followed, defaults, cpuWrites);
  const choice = choose(judged, alternatives, followed, unjudgingAlternatives(suite));
  const byId = new Map(judged.map((j) => [j.id, j]));
  const explained = new Map<string, [string, string][]>();
  const unexplained: string[] = [];
  const knownExplained = new Map<string, [string, string][]>();
  const knownUnexplained: string[] = [];
  const statuses = new Map(verdicts.map((v) => [v.id, v.status]));
  for (const v of verdicts) {
    if (v.status !== FAIL && v.status !== ERROR && v.status !== XFAIL) continue;
    const known = v.status === XFAIL;
    const j = byId.get(v.id);
    if (j === undefined || !j.passing.has(keyOf(j.touched, choice))) (known ? knownUnexplained : unexplained).push(v.id);
    else (known ? knownExplained : explained).set(v.id, smallestChange(j, followed, choice));
  }
  const broken = judged.filter((j) => statuses.get(j.id) === PASS && !j.passing.has(keyOf(j.touched, choice))).map((j) => j.id);
  return { followed, choice, explained, unexplained, knownExplained, knownUnexplained, broken, judged: judged.length };
}
