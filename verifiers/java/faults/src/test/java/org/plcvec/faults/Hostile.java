package org.plcvec.faults;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

import org.plcvec.reference.Reference;
import org.plcvec.verify.Choices;
import org.plcvec.verify.Implementation;
import org.plcvec.verify.SkipVector;
import org.plcvec.verify.StepState;
import org.plcvec.verify.VectorRequest;

/**
 * The reference with one misbehaviour (verifiers/parity/README.md): on the vector
 * {@code PLCVEC_HOSTILE_ON} names, or on every vector for the whole-run ones. Everywhere else it
 * answers as the reference does, through the public API an outside implementation has.
 */
final class Hostile implements Implementation {
    static final List<String> KINDS = List.of("reference", "wrong-result", "panic", "loop-forever", "empty-answer",
            "stray-write", "duplicate-write", "wrong-type", "out-of-range", "exit-zero", "exit-nonzero", "crash",
            "mutates-request", "supports-nothing", "skips-everything", "bad-choice", "cpu-writes", "word-65536",
            "not-a-number", "closes-fds", "child-holds-stdout", "follows-alternative");
    /** The kinds that end or damage the process they run in: each needs a test process of its own. */
    static final Set<String> PROCESS_ENDING = Set.of("loop-forever", "exit-zero", "exit-nonzero", "crash", "closes-fds",
            "child-holds-stdout");

    private final Reference reference = new Reference();
    private final String kind;
    private final String on;
    /** What follows-alternative answers with: the reference following the undeclared choice. */
    private final Reference answering;

    private Hostile(String kind, String on, Reference answering) {
        this.kind = kind;
        this.on = on;
        this.answering = answering;
    }

    /**
     * {@code PLCVEC_HOSTILE} of {@code env} (absent: the plain reference) acting on
     * {@code PLCVEC_HOSTILE_ON}; {@code follows-alternative} follows {@code PLCVEC_HOSTILE_CHOICE}.
     */
    static Implementation from(Map<String, String> env) {
        String kind = env.getOrDefault("PLCVEC_HOSTILE", "reference");
        if (!KINDS.contains(kind)) {
            throw new IllegalArgumentException("PLCVEC_HOSTILE=" + kind + ": known: " + String.join(", ", KINDS));
        }
        if (kind.equals("reference")) {
            return new Reference();   // the documented Emulator, exactly as an implementer plugs one in
        }
        Reference answering = new Reference();
        if (kind.equals("follows-alternative")) {
            answering = new Reference(Choices.parse(List.of(env.getOrDefault("PLCVEC_HOSTILE_CHOICE", ""))).checked());
        }
        return new Hostile(kind, env.get("PLCVEC_HOSTILE_ON"), answering);
    }

    @Override
    public String name() {
        return "hostile-" + kind;
    }

    @Override
    public Choices choices() {
        // follows-alternative declares nothing: a reading followed but not declared.
        return kind.equals("bad-choice") ? Choices.of(Map.of("NO-SUCH-INTERPRETATION", "x")) : reference.choices();
    }

    @Override
    public Set<String> cpuWrites() {
        return kind.equals("cpu-writes") ? Set.of("SM56", "SD1", "SD0") : Set.of();
    }

    @Override
    public boolean supports(String instruction) {
        return !kind.equals("supports-nothing") && reference.supports(instruction);
    }

    @Override
    public List<StepState> run(VectorRequest vector) throws Exception {
        switch (kind) {
            case "skips-everything":
                throw new SkipVector("this implementation skips every vector");
            case "follows-alternative":
                return answering.run(vector);
            case "cpu-writes": {
                boolean target = vector.id().equals(on);
                return edit(reference.run(vector), d -> {
                    d.put("SM56", true);
                    d.put("SD1", 1);
                    if (target) {
                        d.put("SD0", 1);
                    }
                });
            }
            default:
                return vector.id().equals(on) ? misbehave(vector) : reference.run(vector);
        }
    }

    /** The misbehaviour on the target vector. */
    private List<StepState> misbehave(VectorRequest vector) throws Exception {
        switch (kind) {
            case "panic":
                throw new IllegalStateException("hostile: a panic on " + vector.id());
            case "loop-forever":
                return Misbehaviour.loopForever();
            case "empty-answer":
                return List.of();
            case "exit-zero":
                System.exit(0);
                return List.of();
            case "exit-nonzero":
                System.exit(3);
                return List.of();
            case "crash":
                Runtime.getRuntime().halt(134);
                return List.of();
            case "mutates-request": {
                List<StepState> answer = reference.run(vector);
                Misbehaviour.clear(vector);
                return answer;
            }
            case "closes-fds":
                Misbehaviour.closeInheritedDescriptors();
                return wrong(reference.run(vector));
            case "child-holds-stdout":
                Misbehaviour.childHoldingStdout();
                return reference.run(vector);
            default:
                return edited(reference.run(vector));
        }
    }

    /** The target vector's answer with a wrong value, a stray write or a wrong type. */
    private List<StepState> edited(List<StepState> states) {
        switch (kind) {
            case "wrong-result":
                return wrong(states);
            case "stray-write":
                return edit(states, d -> d.put("D7777", 1));
            case "duplicate-write":
                // One listed word twice: as itself and under a second spelling of the same
                // address (D40 and D040), with another value. A Map cannot hold one key twice.
                return edit(states, d -> firstOf(d, Integer.class).ifPresent(k -> {
                    String alias = k.replaceFirst("(\\d+)$", "0$1");
                    d.put(alias, ((Integer) d.get(k) + 1) & 0xFFFF);
                }));
            case "wrong-type":
                return edit(states, d -> firstOf(d, Boolean.class).ifPresent(k -> d.put(k, 1)));
            case "out-of-range":
                return edit(states, d -> firstOf(d, Integer.class).ifPresent(k -> d.put(k, 70000)));
            case "word-65536":
                return edit(states, d -> firstOf(d, Integer.class).ifPresent(k -> d.put(k, 65536)));
            case "not-a-number":
                return edit(states, d -> firstOf(d, Integer.class).ifPresent(k -> d.put(k, Double.NaN)));
            default:
                throw new IllegalStateException("PLCVEC_HOSTILE=" + kind + " is not handled");
        }
    }

    /** The contact result flipped, or 1 added to the first word of every step. */
    private static List<StepState> wrong(List<StepState> states) {
        if (states.get(0).result() != null) {
            List<StepState> out = new ArrayList<>(states);
            out.set(0, new StepState(!states.get(0).result(), states.get(0).devices()));
            return out;
        }
        return edit(states, d -> firstOf(d, Integer.class).ifPresent(k -> d.put(k, ((Integer) d.get(k) + 1) & 0xFFFF)));
    }

    private interface Edit {
        void apply(Map<String, Object> devices);
    }

    /** Every step's devices, edited. */
    private static List<StepState> edit(List<StepState> states, Edit edit) {
        List<StepState> out = new ArrayList<>(states.size());
        for (StepState s : states) {
            Map<String, Object> d = new LinkedHashMap<>(s.devices().toMap());
            edit.apply(d);
            out.add(StepState.of(s.result(), d));
        }
        return out;
    }

    private static Optional<String> firstOf(Map<String, Object> devices, Class<?> type) {
        return devices.entrySet().stream().filter(e -> type.isInstance(e.getValue())).map(Map.Entry::getKey)
                .filter(k -> k.matches("[A-Z]+\\d+")).findFirst();
    }
}
