package org.plcvec.verify;

import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

import org.plcvec.spec.Alternative;

/**
 * The interpretation alternatives an implementation declares (CONTRACT.md, "Declaring your
 * interpretation"): interpretation id → alternative id. Undeclared ones take the default.
 *
 * <pre>{@code
 * Choices.of(Alternatives.Fx5Sm709Scope.ALL_WORDS, Alternatives.TaddExact24.CARRY_ABOVE_24)
 * }</pre>
 */
public final class Choices {
    private static final Choices DEFAULTS = new Choices(Map.of());
    private final Map<String, String> chosen;

    private Choices(Map<String, String> chosen) {
        this.chosen = Collections.unmodifiableMap(new TreeMap<>(chosen));
    }

    /**
     * Nothing declared: every interpretation takes its default.
     *
     * @return the empty declaration
     */
    public static Choices defaults() {
        return DEFAULTS;
    }

    /**
     * The alternatives an implementation follows, by their generated names.
     *
     * @param alternatives one per interpretation ({@code Alternatives.TaddExact24.CARRY_ABOVE_24})
     * @return the declaration
     * @throws VerifyException when an interpretation is declared twice
     */
    public static Choices of(Alternative... alternatives) {
        Map<String, String> m = new TreeMap<>();
        for (Alternative a : alternatives) {
            if (m.put(a.interpretation().id(), a.id()) != null) {
                throw new VerifyException("interpretation " + a.interpretation().id() + " is declared twice");
            }
        }
        return new Choices(m);
    }

    /**
     * From interpretation id to alternative id, as the vectors spell them.
     *
     * @param chosen {@code FX5-SM709-SCOPE} to {@code all-words}, ...
     * @return the declaration
     */
    public static Choices of(Map<String, String> chosen) {
        return new Choices(chosen);
    }

    /**
     * From {@code ID=ALT} strings (a command line's {@code --choose}).
     *
     * @param items each {@code INTERPRETATION=ALTERNATIVE}
     * @return the declaration
     * @throws VerifyException for an item that is not of that form
     */
    public static Choices parse(List<String> items) {
        Map<String, String> m = new TreeMap<>();
        for (String item : items) {
            int eq = item.indexOf('=');
            if (eq <= 0 || eq == item.length() - 1) {
                throw new VerifyException("--choose takes ID=ALTERNATIVE, got '" + item + "'");
            }
            m.put(item.substring(0, eq), item.substring(eq + 1));
        }
        return new Choices(m);
    }

    /**
     * These choices with {@code alternative} declared too (replacing any for its interpretation).
     *
     * @param alternative the alternative to follow
     * @return the new declaration
     */
    public Choices with(Alternative alternative) {
        Map<String, String> m = new TreeMap<>(chosen);
        m.put(alternative.interpretation().id(), alternative.id());
        return new Choices(m);
    }

    /**
     * The declared alternative of an interpretation.
     *
     * @param interpretation its id
     * @return the alternative's id, or null when undeclared
     */
    public String get(String interpretation) {
        return chosen.get(interpretation);
    }

    /**
     * The declared alternative of an interpretation, or its default.
     *
     * @param interpretation the interpretation
     * @return the alternative's id
     */
    public String getOrDefault(org.plcvec.spec.Interpretation interpretation) {
        String alt = chosen.get(interpretation.id());
        return alt != null ? alt : interpretation.defaultAlternative().id();
    }

    /**
     * Whether {@code alternative} is what these choices follow (declared, or the default when undeclared).
     *
     * @param alternative an alternative
     * @return true when followed
     */
    public boolean follows(Alternative alternative) {
        return alternative.id().equals(getOrDefault(alternative.interpretation()));
    }

    /**
     * The declarations.
     *
     * @return interpretation id to alternative id, sorted
     */
    public Map<String, String> asMap() {
        return chosen;
    }

    /**
     * Checks every declaration against the spec's names this library was generated with (before
     * any suite is loaded, e.g. for a command line's {@code --choose}).
     *
     * @return these choices
     * @throws VerifyException naming an unknown interpretation or alternative
     */
    public Choices checked() {
        for (Map.Entry<String, String> e : chosen.entrySet()) {
            org.plcvec.spec.Interpretation i = org.plcvec.spec.Interpretation.byId(e.getKey());
            if (i == null) {
                StringBuilder known = new StringBuilder();
                for (org.plcvec.spec.Interpretation k : org.plcvec.spec.Interpretation.values()) {
                    known.append(known.length() == 0 ? "" : ", ").append(k.id());
                }
                throw new VerifyException("no interpretation " + e.getKey() + " (known: " + known + ")");
            }
            if (i.alternative(e.getValue()) == null) {
                StringBuilder known = new StringBuilder();
                i.alternatives().forEach(a -> known.append(known.length() == 0 ? "" : ", ").append(a.id()));
                throw new VerifyException(e.getKey() + " has no alternative " + e.getValue() + " (it has " + known + ")");
            }
        }
        return this;
    }

    /**
     * Checks every declaration against the suite; an unknown id is a usage error, never ignored.
     *
     * @param suite the vectors whose interpretations count
     * @param who the implementation, for the message
     * @throws VerifyException naming what is unknown and what is known
     */
    public void validate(Suite suite, String who) {
        Map<String, Suite.InterpretationInfo> known = suite.interpretations();
        for (Map.Entry<String, String> e : chosen.entrySet()) {
            Suite.InterpretationInfo info = known.get(e.getKey());
            if (info == null) {
                throw new VerifyException(who + " declares interpretation " + e.getKey()
                        + ", which no vector file defines (known: " + String.join(", ", known.keySet()) + ")");
            }
            if (!info.alternatives().contains(e.getValue())) {
                throw new VerifyException(who + " declares " + e.getKey() + "=" + e.getValue() + ", but " + e.getKey()
                        + " has the alternatives " + String.join(", ", info.alternatives()));
            }
        }
    }

    @Override
    public String toString() {
        StringBuilder sb = new StringBuilder();
        chosen.forEach((k, v) -> sb.append(sb.length() == 0 ? "" : ", ").append(k).append('=').append(v));
        return sb.length() == 0 ? "(defaults)" : sb.toString();
    }
}
