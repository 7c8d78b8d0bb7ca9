package org.plcvec.verify;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.BiConsumer;

/** Contract-level implementations for the tests, built around a vector's own expectations. */
final class Fakes {
    private Fakes() {
    }

    /**
     * Answers each step with the vector's expected state (worked out from the vector file, not from
     * any implementation), then lets {@code tamper} change the step's device map.
     */
    static Implementation echo(BiConsumer<Integer, Map<String, Object>> tamper) {
        return new Implementation() {
            @Override
            public String name() {
                return "echo";
            }

            @Override
            public List<StepState> run(VectorRequest request) {
                Vector v = Suite.golden().byId(request.id());
                Expected e = Expected.of(v, Map.of(), defaults());
                List<StepState> out = new ArrayList<>();
                for (int s = 0; s < v.steps().size(); s++) {
                    Map<String, Object> devices = new LinkedHashMap<>();
                    for (int j = 0; j < v.slots.length; j++) {
                        if (e.states[s][j] != Values.ABSENT) {
                            devices.put(v.slots[j].name(), Values.decode(e.states[s][j]));
                        }
                    }
                    tamper.accept(s, devices);
                    out.add(StepState.of(e.results[s], devices));
                }
                return out;
            }
        };
    }

    static Map<String, String> defaults() {
        Map<String, String> d = new LinkedHashMap<>();
        Suite.golden().interpretations().forEach((k, i) -> d.put(k, i.defaultAlternative()));
        return d;
    }
}
