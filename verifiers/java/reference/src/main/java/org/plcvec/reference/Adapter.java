package org.plcvec.reference;

import java.util.ArrayList;
import java.util.List;

import org.plcvec.verify.Choices;
import org.plcvec.verify.StdioServer;
import org.plcvec.verify.VerifyException;

/**
 * Serves the reference over the stdio protocol:
 * {@code plcvec verify --adapter verifiers/java/reference-adapter [--choose ID=ALT ...]}.
 */
public final class Adapter {
    private Adapter() {
    }

    /**
     * Serve the reference over standard input and output, following {@code --choose ID=ALT}.
     *
     * @param args {@code --choose ID=ALT}, repeatable
     */
    public static void main(String[] args) {
        System.exit(run(args, null));
    }

    /**
     * Parse {@code --choose ID=ALT} (repeatable) and serve; {@code variants} builds another
     * implementation from the choices (the mutants' adapter passes its own).
     *
     * @param args the command line
     * @param variants the implementation to serve for the choices, or null for the reference
     * @return the exit status
     */
    public static int run(String[] args, java.util.function.Function<Choices, ? extends org.plcvec.verify.Implementation> variants) {
        List<String> choose = new ArrayList<>();
        for (int i = 0; i < args.length; i++) {
            if (args[i].equals("--choose") && i + 1 < args.length) {
                choose.add(args[++i]);
            } else if (args[i].startsWith("--choose=")) {
                choose.add(args[i].substring("--choose=".length()));
            } else if (args[i].equals("-h") || args[i].equals("--help")) {
                System.err.println("usage: reference-adapter [--choose ID=ALTERNATIVE]...\n"
                        + "Serves the Java reference implementation over the plcvec stdio protocol (PROTOCOL.md).");
                return 0;
            } else {
                System.err.println("reference-adapter: unknown argument '" + args[i] + "' (see --help)");
                return 2;
            }
        }
        try {
            Choices choices = Choices.parse(choose).checked();
            return StdioServer.serve(variants == null ? new Reference(choices) : variants.apply(choices));
        } catch (VerifyException e) {
            System.err.println("reference-adapter: " + e.getMessage());
            return 2;
        }
    }
}
