package org.plcvec.verify;

import org.junit.platform.engine.TestExecutionResult;
import org.junit.platform.launcher.TestExecutionListener;
import org.junit.platform.launcher.TestIdentifier;
import org.junit.platform.launcher.TestPlan;

/**
 * Speaks when a test run filtered by the test runner's own filter ({@code mvn test -Dtest=...})
 * ran no test at all, and so no plcvec vector: a filter matching nothing is not a pass, and the vectors are selected
 * with {@code PLCVEC_ID}. Registered with the JUnit Platform through
 * {@code META-INF/services}; it only prints (a listener cannot fail a run), so whether such a run
 * fails is the test runner's: Surefire fails a class pattern that matches nothing, but not a
 * method pattern ({@code -Dtest=MyTest#nothing}).
 */
public final class FilterWatch implements TestExecutionListener {
    private volatile int tests;

    @Override
    public void executionFinished(TestIdentifier identifier, TestExecutionResult result) {
        if (identifier.isTest()) {
            tests++;
        }
    }

    @Override
    public void testPlanExecutionFinished(TestPlan plan) {
        String filter = System.getProperty("test");
        // Only a run of nothing: a filter that picks some other test of the project is the user's intent.
        if (filter != null && !filter.isBlank() && !PlcvecTests.factoryRan && tests == 0) {
            System.err.println("plcvec: the test runner's own filter (-Dtest=" + filter + ") ran no plcvec vector; a "
                    + "filter that matches nothing tests nothing. Select vectors with " + Environment.ID
                    + " instead (e.g. " + Environment.ID + "='fx5-time-add/TADDP/*' mvn test).");
        }
    }
}
