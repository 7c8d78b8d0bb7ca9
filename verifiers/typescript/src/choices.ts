/**
 * The interpretation choices: the alternatives an implementation declares, checked against the
 * suite, and the alternative followed for every interpretation (declared or default).
 */
import { VerifyError } from "./errors.js";
import { interpretationsOf, type Suite } from "./suite.js";

/** Interpretation id -> alternative, as an implementation declares it (checked here; the generated `Choices` type-checks one). */
type Choices = Readonly<Record<string, string>>;

/** Every interpretation's alternative, declared or default, and the defaults. */
export interface Followed {
  readonly choices: Readonly<Record<string, string>>;
  readonly defaults: Readonly<Record<string, string>>;
}

/** The declared alternatives checked against the suite, with every interpretation's default. */
export function resolveChoices(suite: Suite, declared: Choices = {}): Followed {
  const interps = interpretationsOf(suite);
  const defaults: Record<string, string> = {};
  for (const [id, i] of interps) defaults[id] = i.default;
  for (const [id, alt] of Object.entries(declared)) {
    const interp = interps.get(id);
    if (interp === undefined) {
      throw new VerifyError(`declared interpretation ${JSON.stringify(id)} is not in the suite (known: ${[...interps.keys()].sort().join(", ")})`);
    }
    if (!interp.alternatives.includes(alt)) {
      throw new VerifyError(`${id}=${alt}: no such alternative (known: ${interp.alternatives.join(", ")})`);
    }
  }
  return { choices: { ...defaults, ...declared }, defaults };
}
