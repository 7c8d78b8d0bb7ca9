package org.plcvec.faults;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
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
            "mutates-request", "supports-nothing", "skips-everything", "bad-choice", "cpu-writes");

    private final Reference reference = new Reference();
    private final String kind;
    private final String on;

    private Hostile(String kind, String on) {
        this.kind = kind;
        this.on = on;
    }

    /** {@code PLCVEC_HOSTILE} (absent: the plain reference) acting on {@code PLCVEC_HOSTILE_ON}. */
    static Implementation fromEnvironment() {
        String kind = System.getenv().getOrDefault("PLCVEC_HOSTILE", "reference");
        if (!KINDS.contains(kind)) {
            throw new IllegalArgumentException("PLCVEC_HOSTILE=" + kind + ": known: " + String.join(", ", KINDS));
        }
        // The plain reference is the documented Emulator, exactly as an implementer plugs one in.
        return kind.equals("reference") ? new Reference() : new Hostile(kind, System.getenv("PLCVEC_HOSTILE_ON"));
    }

    @Override
    public String name() {
        return "hostile-" + kind;
    }

    @Override
    public Choices choices() {
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
        if (kind.equals("skips-everything")) {
            throw new SkipVector("this implementation skips every vector");
        }
        boolean target = vector.id().equals(on);
        if (kind.equals("cpu-writes")) {
            return edit(reference.run(vector), d -> {
                d.put("SM56", true);
                d.put("SD1", 1);
                if (target) {
                    d.put("SD0", 1);
                }
            });
        }
        if (!target) {
            return reference.run(vector);
        }
        switch (kind) {
            case "panic":
                throw new IllegalStateException("hostile: a panic on " + vector.id());
            case "loop-forever":
                long spins = 0;
                while (spins >= 0) {     // never returns, deaf to interrupts
                    spins++;
                    Thread.onSpinWait();
                }
                return List.of();
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
                clear(vector);
                return answer;
            }
            default:
                break;
        }
        List<StepState> states = reference.run(vector);
        switch (kind) {
            case "wrong-result":
                if (states.get(0).result() != null) {
                    List<StepState> out = new ArrayList<>(states);
                    out.set(0, new StepState(!states.get(0).result(), states.get(0).devices()));
                    return out;
                }
                return edit(states, d -> firstOf(d, Integer.class).ifPresent(k -> d.put(k, ((Integer) d.get(k) + 1) & 0xFFFF)));
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
            default:
                throw new IllegalStateException("PLCVEC_HOSTILE=" + kind + " is not handled");
        }
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

    private static java.util.Optional<String> firstOf(Map<String, Object> devices, Class<?> type) {
        return devices.entrySet().stream().filter(e -> type.isInstance(e.getValue())).map(Map.Entry::getKey)
                .filter(k -> k.matches("[A-Z]+\\d+")).findFirst();
    }

    /** Clear what of the request can be cleared; the API hands out read-only views, which is the point. */
    private static void clear(VectorRequest vector) {
        try {
            vector.steps().clear();
        } catch (UnsupportedOperationException readOnly) {
            // the request's steps cannot be changed from outside
        }
        try {
            vector.steps().forEach(s -> s.set().clear());
        } catch (UnsupportedOperationException readOnly) {
            // nor a step's inputs
        }
        try {
            vector.operands().clear();
            vector.initialDevices().clear();
        } catch (UnsupportedOperationException readOnly) {
            // nor the operands
        }
    }
}
