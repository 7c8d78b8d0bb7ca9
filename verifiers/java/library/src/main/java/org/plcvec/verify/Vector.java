package org.plcvec.verify;

import java.util.List;
import java.util.Map;

/** A golden vector: the request, what it expects (under every alternative), and why it exists. */
public final class Vector extends VectorRequest {
    /** What one step must give: the contact result (or null) and the devices that change. */
    record StepExpect(Boolean result, Address[] devices, int[] values) {
    }

    /** The expectation under one combination of alternatives. */
    record Expectation(List<StepExpect> steps, Address[] finalDevices, int[] finalValues, String category) {
    }

    /**
     * An entry of {@code alternatives}: the choices it holds for, its expectation, and the devices
     * it leaves unjudged (interpretation to devices, both sorted; empty for most).
     */
    record Variant(Map<String, String> choices, Expectation expectation, Map<String, List<String>> unjudged) {
    }

    private final String description;
    private final List<String> tags;
    private final List<String> clauses;
    private final List<String> interpretations;
    private final Expectation expectation;
    private final List<Variant> variants;
    private java.net.URI source;     // where the vector is written, for an IDE to open (set by Suite)

    Vector(VectorRequest request, String description, List<String> tags, List<String> clauses,
           List<String> interpretations, Expectation expectation, List<Variant> variants) {
        super(request);
        this.description = description;
        this.tags = List.copyOf(tags);
        this.clauses = List.copyOf(clauses);
        this.interpretations = List.copyOf(interpretations);
        this.expectation = expectation;
        this.variants = List.copyOf(variants);
    }

    /**
     * Where the vector is written: the JUnit test source of its dynamic test.
     *
     * @return {@code classpath:/org/plcvec/vectors/fx5-time-add.jsonl?line=12} or a file URI, or null
     */
    public java.net.URI source() {
        return source;
    }

    void source(java.net.URI uri) {
        this.source = uri;
    }

    /**
     * What the vector tests, in words.
     *
     * @return the description, "" for none
     */
    public String description() {
        return description;
    }

    /**
     * Why the vector exists ({@code boundary}, {@code manual-example}, ...).
     *
     * @return its tags
     */
    public List<String> tags() {
        return tags;
    }

    /**
     * The spec clauses the vector exercises, for reports.
     *
     * @return clause ids ({@code fx5-time-add#carry})
     */
    public List<String> clauses() {
        return clauses;
    }

    /**
     * The interpretations the vector's outcome depends on.
     *
     * @return their ids (empty for most)
     */
    public List<String> interpretations() {
        return interpretations;
    }

    /**
     * The outcome category under the defaults.
     *
     * @return {@code value}, {@code error} or {@code implementation-defined}
     */
    public String category() {
        return interpretations.isEmpty() ? expectation.category() : "implementation-defined";
    }

    Expectation expectation() {
        return expectation;
    }

    List<Variant> variants() {
        return variants;
    }
}
