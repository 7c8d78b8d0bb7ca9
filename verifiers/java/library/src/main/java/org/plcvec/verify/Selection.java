package org.plcvec.verify;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Pattern;
import java.util.zip.CRC32;

import org.plcvec.spec.Family;
import org.plcvec.spec.Instruction;
import org.plcvec.spec.Interpretation;
import org.plcvec.spec.Tag;

/**
 * Which vectors to run. Each filter is OR within itself; the filters are AND together; an empty
 * filter lets everything through. Immutable: every method returns a new selection.
 *
 * <pre>{@code
 * Selection.all().families(Family.FX5_TIME_ADD).tags(Tag.BOUNDARY).shard(2, 4)
 * }</pre>
 *
 * <p>{@link PlcvecTests} narrows it further by {@code PLCVEC_FAMILY}, {@code PLCVEC_INSTRUCTION},
 * {@code PLCVEC_TAG}, {@code PLCVEC_ID} (globs), {@code PLCVEC_INTERPRETATION} (each a
 * comma-separated list) and {@code PLCVEC_SHARD=K/N} ({@link Environment#narrow}), so one CI
 * variable narrows any factory: {@code PLCVEC_ID='fx5-time-add/TADDP/*' mvn test}.
 */
public final class Selection {
    private static final Selection ALL = new Selection(Set.of(), Set.of(), Set.of(), List.of(), Set.of(), 0, 0);

    private final Set<String> families;
    private final Set<String> instructions;
    private final Set<String> tags;
    private final List<String> ids;
    private final List<Pattern> idPatterns;
    private final Set<String> interpretations;
    private final int shardK;
    private final int shardN;

    private Selection(Set<String> families, Set<String> instructions, Set<String> tags, List<String> ids,
                      Set<String> interpretations, int shardK, int shardN) {
        this.families = Collections.unmodifiableSet(new LinkedHashSet<>(families));
        this.instructions = Collections.unmodifiableSet(new LinkedHashSet<>(instructions));
        this.tags = Collections.unmodifiableSet(new LinkedHashSet<>(tags));
        this.ids = List.copyOf(ids);
        this.idPatterns = ids.stream().map(Selection::glob).toList();
        this.interpretations = Collections.unmodifiableSet(new LinkedHashSet<>(interpretations));
        this.shardK = shardK;
        this.shardN = shardN;
        this.and = null;
    }

    /**
     * Every vector.
     *
     * @return the selection of everything
     */
    public static Selection all() {
        return ALL;
    }

    /**
     * Also these families.
     *
     * @param names the families
     * @return the new selection
     */
    public Selection families(Family... names) {
        return families(Arrays.stream(names).map(Family::id).toArray(String[]::new));
    }

    /**
     * Also these families, as the vectors spell them ({@code fx5-time-add}).
     *
     * @param names the families
     * @return the new selection
     */
    public Selection families(String... names) {
        return new Selection(union(families, names), instructions, tags, ids, interpretations, shardK, shardN);
    }

    /**
     * Also these instructions.
     *
     * @param names the instructions
     * @return the new selection
     */
    public Selection instructions(Instruction... names) {
        return instructions(Arrays.stream(names).map(Instruction::mnemonic).toArray(String[]::new));
    }

    /**
     * Also these instructions, as the vectors spell them ({@code LDTM<=}, {@code LD <=DT}).
     *
     * @param names the instructions
     * @return the new selection
     */
    public Selection instructions(String... names) {
        return new Selection(families, union(instructions, names), tags, ids, interpretations, shardK, shardN);
    }

    /**
     * Also the vectors with one of these tags.
     *
     * @param names the tags
     * @return the new selection
     */
    public Selection tags(Tag... names) {
        return tags(Arrays.stream(names).map(Tag::id).toArray(String[]::new));
    }

    /**
     * Also the vectors with one of these tags, as the vectors spell them ({@code boundary}).
     *
     * @param names the tags
     * @return the new selection
     */
    public Selection tags(String... names) {
        return new Selection(families, instructions, union(tags, names), ids, interpretations, shardK, shardN);
    }

    /**
     * Also the vectors whose id a glob matches: {@code *} any run of characters (slashes too),
     * {@code ?} one, {@code [abc]}, {@code [!abc]}; a glob matches the whole id.
     *
     * @param globs exact ids or globs
     * @return the new selection
     */
    public Selection ids(String... globs) {
        List<String> all = new ArrayList<>(ids);
        all.addAll(Arrays.asList(globs));
        return new Selection(families, instructions, tags, all, interpretations, shardK, shardN);
    }

    /**
     * Also the vectors whose outcome depends on one of these interpretations.
     *
     * @param names the interpretations
     * @return the new selection
     */
    public Selection interpretations(Interpretation... names) {
        return interpretations(Arrays.stream(names).map(Interpretation::id).toArray(String[]::new));
    }

    /**
     * Also the vectors whose outcome depends on one of these interpretations, by id.
     *
     * @param names the interpretation ids
     * @return the new selection
     */
    public Selection interpretations(String... names) {
        return new Selection(families, instructions, tags, ids, union(interpretations, names), shardK, shardN);
    }

    /**
     * Shard {@code k} of {@code n}, chosen as the Python runner does: crc32(id) % n + 1 == k.
     *
     * @param k the shard, 1 to n
     * @param n the number of shards
     * @return the new selection
     * @throws VerifyException when k is not between 1 and n
     */
    public Selection shard(int k, int n) {
        if (n < 1 || k < 1 || k > n) {
            throw new VerifyException("shard " + k + "/" + n + ": K must be between 1 and N");
        }
        return new Selection(families, instructions, tags, ids, interpretations, k, n);
    }

    /**
     * Shard {@code K/N}.
     *
     * @param text {@code K/N}, e.g. {@code 2/4}
     * @return the new selection
     * @throws VerifyException for anything else
     */
    public Selection shard(String text) {
        String[] parts = text.trim().split("/");
        try {
            if (parts.length == 2) {
                return shard(Integer.parseInt(parts[0].trim()), Integer.parseInt(parts[1].trim()));
            }
        } catch (NumberFormatException e) {
            // fall through to the message below
        }
        throw new VerifyException("shard takes K/N (e.g. 2/4), got '" + text + "'");
    }

    /**
     * The shard a vector belongs to: a hash of the id, so adding vectors moves no other vector.
     *
     * @param id the vector's id
     * @param n the number of shards
     * @return the shard, 1 to n
     */
    public static int shardOf(String id, int n) {
        CRC32 crc = new CRC32();
        crc.update(id.getBytes(java.nio.charset.StandardCharsets.UTF_8));
        return (int) (crc.getValue() % n) + 1;
    }

    /**
     * Vectors both this selection and {@code other} select.
     *
     * @param other another selection
     * @return their intersection
     */
    public Selection and(Selection other) {
        return other == ALL ? this : this == ALL ? other : new Selection(this, other);
    }

    /**
     * This selection narrowed by the {@code plcvec.*} system properties alone, unchecked (0.1.0).
     *
     * @return the selection narrowed
     * @deprecated the factory reads every setting, {@code PLCVEC_*} variables and {@code plcvec.*}
     *             properties alike, and refuses a name the suite does not have
     *             ({@link Environment#narrow(Selection, Suite)}); removed in 0.3.0
     */
    @Deprecated(since = "0.2.0", forRemoval = true)
    public Selection withSystemProperties() {
        Selection p = all();
        String[] names = {"family", "instruction", "tag", "id", "interpretation"};
        for (String name : names) {
            String v = System.getProperty("plcvec." + name);
            if (v != null && !v.isBlank()) {
                String[] items = Arrays.stream(v.split(",")).map(String::trim).filter(x -> !x.isEmpty()).toArray(String[]::new);
                p = name.equals("family") ? p.families(items) : name.equals("instruction") ? p.instructions(items)
                        : name.equals("tag") ? p.tags(items) : name.equals("id") ? p.ids(items) : p.interpretations(items);
            }
        }
        String shard = System.getProperty("plcvec.shard");
        if (shard != null && !shard.isBlank()) {
            p = p.shard(shard);
        }
        return and(p);
    }

    /**
     * Every vector, narrowed by the {@code plcvec.*} system properties alone (0.1.0).
     *
     * @return the selection
     * @deprecated as {@link #withSystemProperties()}; removed in 0.3.0
     */
    @Deprecated(since = "0.2.0", forRemoval = true)
    public static Selection fromSystemProperties() {
        return all().withSystemProperties();
    }

    // Another selection this one is ANDed with ("family A" AND "family B" is not "A or B").
    private final Selection and;

    private Selection(Selection base, Selection and) {
        this.families = base.families;
        this.instructions = base.instructions;
        this.tags = base.tags;
        this.ids = base.ids;
        this.idPatterns = base.idPatterns;
        this.interpretations = base.interpretations;
        this.shardK = base.shardK;
        this.shardN = base.shardN;
        this.and = base.and == null ? and : new Selection(base.and, and);
    }

    /**
     * Whether this selection selects a vector.
     *
     * @param v the vector
     * @return true when every filter lets it through
     */
    public boolean matches(Vector v) {
        if (!families.isEmpty() && !families.contains(v.family())) {
            return false;
        }
        if (!instructions.isEmpty() && !instructions.contains(v.instruction())) {
            return false;
        }
        if (!tags.isEmpty() && v.tags().stream().noneMatch(tags::contains)) {
            return false;
        }
        if (!idPatterns.isEmpty() && idPatterns.stream().noneMatch(p -> p.matcher(v.id()).matches())) {
            return false;
        }
        if (!interpretations.isEmpty() && v.interpretations().stream().noneMatch(interpretations::contains)) {
            return false;
        }
        if (shardN > 0 && shardOf(v.id(), shardN) != shardK) {
            return false;
        }
        return and == null || and.matches(v);
    }

    /**
     * The selected vectors of {@code suite}, in the suite's order.
     *
     * @param suite the vectors
     * @return those selected
     * @throws VerifyException for a name the suite does not have
     */
    public List<Vector> apply(Suite suite) {
        check(suite);
        List<Vector> out = new ArrayList<>();
        for (Vector v : suite.vectors()) {
            if (matches(v)) {
                out.add(v);
            }
        }
        return out;
    }

    /** A family, instruction, tag or interpretation the suite does not have is a mistake, not an empty run. */
    void check(Suite suite) {
        Set<String> knownFamilies = new LinkedHashSet<>(suite.families());
        Set<String> knownInstructions = new LinkedHashSet<>();
        Set<String> knownTags = new LinkedHashSet<>();
        for (Vector v : suite.vectors()) {
            knownInstructions.add(v.instruction());
            knownTags.addAll(v.tags());
        }
        for (String f : suite.families()) {
            knownInstructions.addAll(suite.instructions(f));
        }
        unknown("family", families, knownFamilies);
        unknown("instruction", instructions, knownInstructions);
        unknown("tag", tags, knownTags);
        unknown("interpretation", interpretations, suite.interpretations().keySet());
        for (int i = 0; i < ids.size(); i++) {
            Pattern p = idPatterns.get(i);
            if (suite.vectors().stream().noneMatch(v -> p.matcher(v.id()).matches())) {
                String example = suite.vectors().isEmpty() ? "" : " (ids look like " + suite.vectors().get(0).id()
                        + "; a glob matches the whole id)";
                throw new VerifyException("id '" + ids.get(i) + "' matches no vector id in " + suite.source() + example);
            }
        }
        if (and != null) {
            and.check(suite);
        }
    }

    private static void unknown(String what, Set<String> asked, Set<String> known) {
        for (String name : asked) {
            if (!known.contains(name)) {
                throw new VerifyException("no " + what + " '" + name + "' in the suite (known: " + String.join(", ", known) + ")");
            }
        }
    }

    private static Set<String> union(Set<String> a, String[] b) {
        Set<String> out = new LinkedHashSet<>(a);
        out.addAll(Arrays.asList(b));
        return out;
    }

    /** fnmatch, as the Python runner's {@code --id} reads it. */
    static Pattern glob(String glob) {
        StringBuilder re = new StringBuilder();
        for (int i = 0; i < glob.length(); i++) {
            char c = glob.charAt(i);
            if (c == '*') {
                re.append(".*");
            } else if (c == '?') {
                re.append('.');
            } else if (c == '[' && glob.indexOf(']', i + 2) > 0) {
                int end = glob.indexOf(']', i + 2);
                String body = glob.substring(i + 1, end);
                re.append('[');
                if (body.startsWith("!")) {
                    re.append('^');
                    body = body.substring(1);
                }
                re.append(body.replace("\\", "\\\\").replace("[", "\\[")).append(']');
                i = end;
            } else {
                re.append(Pattern.quote(String.valueOf(c)));
            }
        }
        return Pattern.compile(re.toString(), Pattern.DOTALL);
    }

    @Override
    public String toString() {
        List<String> parts = new ArrayList<>();
        if (!families.isEmpty()) {
            parts.add("family " + String.join("|", families));
        }
        if (!instructions.isEmpty()) {
            parts.add("instruction " + String.join("|", instructions));
        }
        if (!tags.isEmpty()) {
            parts.add("tag " + String.join("|", tags));
        }
        if (!ids.isEmpty()) {
            parts.add("id " + String.join("|", ids));
        }
        if (!interpretations.isEmpty()) {
            parts.add("interpretation " + String.join("|", interpretations));
        }
        if (shardN > 0) {
            parts.add("shard " + shardK + "/" + shardN);
        }
        if (and != null) {
            parts.add(and.toString());
        }
        return parts.isEmpty() ? "all vectors" : String.join(", ", parts);
    }
}
