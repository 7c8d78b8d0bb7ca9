package org.plcvec.faults;

import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.io.IOException;
import java.lang.reflect.Field;
import java.util.List;

import org.plcvec.verify.StepState;
import org.plcvec.verify.VectorRequest;

/** What the hostile implementations do to the process they run in, beside a wrong answer. */
final class Misbehaviour {
    /** The file descriptors a process may have inherited or opened beside 0, 1 and 2. */
    private static final int FIRST = 3;
    private static final int LAST = 1023;
    /** How long the child holds the inherited standard output: far longer than a run may take. */
    private static final String CHILD_SECONDS = "300";

    private Misbehaviour() {
    }

    /** Never returns, deaf to interrupts. */
    static List<StepState> loopForever() {
        long spins = 0;
        while (spins >= 0) {
            spins++;
            Thread.onSpinWait();
        }
        return List.of();
    }

    /** Clear what of the request can be cleared; the API hands out read-only views, which is the point. */
    static void clear(VectorRequest vector) {
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

    /**
     * Close every descriptor from 3 to 1023, whatever the runner and the test runner opened there
     * (Java has no call for a descriptor by number: a FileDescriptor is given the number, which
     * needs {@code --add-opens java.base/java.io=ALL-UNNAMED}, as faults-entry runs it).
     */
    static void closeInheritedDescriptors() throws ReflectiveOperationException {
        Field number = FileDescriptor.class.getDeclaredField("fd");
        number.setAccessible(true);
        for (int fd = FIRST; fd <= LAST; fd++) {
            FileDescriptor d = new FileDescriptor();
            number.setInt(d, fd);
            try (FileOutputStream out = new FileOutputStream(d)) {
                out.getFD();   // closed by the try: close(2) on the number, open or not
            } catch (IOException notOpen) {
                // EBADF: nothing was open there
            }
        }
    }

    /** Start a process that inherits standard output and error and sleeps, and leave it running. */
    static void childHoldingStdout() throws IOException {
        new ProcessBuilder("sleep", CHILD_SECONDS).inheritIO().redirectInput(ProcessBuilder.Redirect.PIPE).start();
    }
}
