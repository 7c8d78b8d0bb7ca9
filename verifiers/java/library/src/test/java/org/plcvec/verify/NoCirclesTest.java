package org.plcvec.verify;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.spi.ToolProvider;

import org.junit.jupiter.api.Test;

/**
 * No import circle among the library's classes (VOCABULARY.md, "Import circles"): the class
 * dependencies jdeps reads from the compiled classes of org.plcvec.verify (a nested class counted
 * as its outer one) form no cycle. The generated names (org.plcvec.spec) are left out: their links
 * both ways (a family's instructions, an instruction's family) are the spec's own model, public
 * since 0.1.0.
 */
class NoCirclesTest {
    private static final String PACKAGE = "org.plcvec.verify.";

    @Test
    void theLibrarysClassesDependOnEachOtherWithoutACircle() {
        Map<String, Set<String>> graph = dependencies();
        assertTrue(graph.size() > 20, "jdeps found the library's classes: " + graph.keySet());
        assertEquals(List.of(), circles(graph), "classes that depend on each other, each circle's members");
    }

    @Test
    void aCircleIsFound() {
        Map<String, Set<String>> graph = new TreeMap<>();
        graph.put("A", new TreeSet<>(Set.of("B")));
        graph.put("B", new TreeSet<>(Set.of("C")));
        graph.put("C", new TreeSet<>(Set.of("A")));
        graph.put("D", new TreeSet<>(Set.of("A")));
        assertEquals(List.of(List.of("A", "B", "C")), circles(graph));
    }

    /** class -> the classes of the package it refers to, from jdeps -verbose:class over target/classes. */
    private static Map<String, Set<String>> dependencies() {
        ToolProvider jdeps = ToolProvider.findFirst("jdeps").orElseThrow();
        StringWriter out = new StringWriter();
        int status = jdeps.run(new PrintWriter(out), new PrintWriter(out), "--multi-release", "17", "-verbose:class",
                "-filter:none", "target/classes");
        assertEquals(0, status, out.toString());
        Map<String, Set<String>> graph = new TreeMap<>();
        for (String line : out.toString().split("\n")) {
            String[] parts = line.trim().split("\\s+");
            if (parts.length >= 3 && parts[1].equals("->") && parts[0].startsWith(PACKAGE) && parts[2].startsWith(PACKAGE)) {
                String from = outer(parts[0]);
                String to = outer(parts[2]);
                graph.computeIfAbsent(from, k -> new TreeSet<>());
                if (!from.equals(to)) {
                    graph.get(from).add(to);
                }
            }
        }
        return graph;
    }

    private static String outer(String cls) {
        String simple = cls.substring(PACKAGE.length());
        int nested = simple.indexOf('$');
        return nested < 0 ? simple : simple.substring(0, nested);
    }

    /** The strongly connected components of more than one class (Tarjan), each sorted. */
    static List<List<String>> circles(Map<String, Set<String>> graph) {
        Map<String, Integer> index = new HashMap<>();
        Map<String, Integer> low = new HashMap<>();
        List<String> stack = new ArrayList<>();
        List<List<String>> out = new ArrayList<>();
        for (String v : graph.keySet()) {
            if (!index.containsKey(v)) {
                connect(v, graph, index, low, stack, out);
            }
        }
        return out;
    }

    private static void connect(String v, Map<String, Set<String>> graph, Map<String, Integer> index,
                                Map<String, Integer> low, List<String> stack, List<List<String>> out) {
        index.put(v, index.size());
        low.put(v, index.get(v));
        stack.add(v);
        for (String w : graph.getOrDefault(v, Set.of())) {
            if (!index.containsKey(w)) {
                connect(w, graph, index, low, stack, out);
                low.put(v, Math.min(low.get(v), low.get(w)));
            } else if (stack.contains(w)) {
                low.put(v, Math.min(low.get(v), index.get(w)));
            }
        }
        if (low.get(v).equals(index.get(v))) {
            List<String> component = new ArrayList<>();
            String w;
            do {
                w = stack.remove(stack.size() - 1);
                component.add(w);
            } while (!w.equals(v));
            if (component.size() > 1) {
                component.sort(null);
                out.add(component);
            }
        }
    }
}
