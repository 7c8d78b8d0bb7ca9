package org.plcvec.mutants;

import java.util.Arrays;
import java.util.stream.Collectors;

import org.plcvec.reference.Adapter;

/**
 * Serves one mutant over the stdio protocol:
 * {@code plcvec verify --adapter "verifiers/java/reference-adapter --mutant tadd-sm8022-not-written"}.
 */
public final class MutantAdapter {
    private MutantAdapter() {
    }

    public static void main(String[] args) {
        if (args.length < 2 || !args[0].equals("--mutant")) {
            System.err.println("usage: reference-adapter --mutant NAME [--choose ID=ALTERNATIVE]...");
            System.exit(2);
        }
        Mutant mutant = Mutants.byName(args[1]);
        if (mutant == null) {
            System.err.println("reference-adapter: no mutant '" + args[1] + "' (known: "
                    + Mutants.all().stream().map(Mutant::name).collect(Collectors.joining(", ")) + ")");
            System.exit(2);
        }
        System.exit(Adapter.run(Arrays.copyOfRange(args, 2, args.length), mutant.build()));
    }
}
