package org.plcvec.verify;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;

/** What the run is: the selected vectors, their expectations, the alternatives followed. */
final class Plan {
    final List<Vector> vectors;
    final Map<String, Expected> expected = new LinkedHashMap<>();
    final Map<String, Followed> followed;
    final Expected[] expectedInOrder;   // expected, in the order of `vectors`
    final boolean[] supported;          // implementation.supports(instruction), asked once
    final Memory[] memories;            // one per vector, reused by run()
    final Map<String, String> all;      // interpretation -> the alternative followed (declared or default)
    final Map<String, String> defaults;
    final Judge judge;

    Plan(Suite suite, Implementation impl, Selection selection) {
        this.vectors = selection.apply(suite);
        if (vectors.isEmpty()) {
            throw new VerifyException("the selection (" + selection + ") matches no vector of " + suite.source()
                    + "; a run of nothing proves nothing");
        }
        Choices choices = impl.choices();
        choices.validate(suite, impl.name());
        Map<String, String> defaults = new TreeMap<>();
        Map<String, String> all = new TreeMap<>();
        Map<String, Followed> followed = new TreeMap<>();
        Set<String> families = new TreeSet<>();
        vectors.forEach(v -> families.add(v.family()));
        for (Suite.InterpretationInfo i : suite.interpretations().values()) {
            defaults.put(i.id(), i.defaultAlternative());
            String declared = choices.get(i.id());
            all.put(i.id(), declared != null ? declared : i.defaultAlternative());
            if (i.families().stream().anyMatch(families::contains)) {
                followed.put(i.id(), new Followed(all.get(i.id()), declared != null, i.families()));
            }
        }
        this.followed = Collections.unmodifiableMap(followed);
        this.all = all;
        this.defaults = defaults;
        this.judge = new Judge(impl, all, defaults);
        long[] cpuWrites = impl.cpuWrites().stream().mapToLong(d -> Address.of(d).key()).toArray();
        for (Vector v : vectors) {
            expected.put(v.id(), Expected.of(v, all, defaults).cpuWrites(cpuWrites));
        }
        this.memories = new Memory[vectors.size()];
        this.expectedInOrder = vectors.stream().map(v -> expected.get(v.id())).toArray(Expected[]::new);
        this.supported = new boolean[vectors.size()];
        for (int i = 0; i < supported.length; i++) {
            supported[i] = impl.supports(vectors.get(i).instruction());
        }
    }
}
