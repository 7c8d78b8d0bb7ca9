package org.plcvec.faults;

import java.util.stream.Stream;

import org.junit.jupiter.api.DynamicNode;
import org.junit.jupiter.api.TestFactory;
import org.plcvec.verify.PlcvecTests;

/**
 * The README's entry point, as an implementer's project has it: one factory over the
 * implementation {@code PLCVEC_HOSTILE} names, every other setting from the {@code PLCVEC_*}
 * variables. A row of the table of faults runs it alone (faults-entry), or {@link FaultsTable}
 * runs many rows through the same factory in one test process.
 */
class FaultsTest {
    @TestFactory
    Stream<DynamicNode> plcvec() {
        return PlcvecTests.of(Hostile.from(System.getenv())).stream();
    }
}
