package org.plcvec.verify;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;

import org.junit.jupiter.api.Test;

import tools.jackson.databind.JsonNode;

class StdioServerTest {
    private record Served(int status, List<JsonNode> lines) {
    }

    private static Served serve(Implementation impl, String input) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        int status = StdioServer.serve(impl, new ByteArrayInputStream(input.getBytes(StandardCharsets.UTF_8)), out);
        List<JsonNode> lines = out.toString(StandardCharsets.UTF_8).lines().map(Suite.JSON::readTree).toList();
        return new Served(status, lines);
    }

    static final String HELLO = "{\"type\":\"hello\",\"protocol\":1,\"families\":{\"fx5-time-add\":{\"instructions\":[\"TADD\","
            + "\"TADDP\"],\"interpretations\":{\"TADD-EXACT-24\":{\"default\":\"carry-at-24\",\"alternatives\":[\"carry-at-24\","
            + "\"carry-above-24\"]}}}}}\n";

    static final Emulator ADD_ONE = (vector, memory) -> step -> {
        memory.setWord(vector.operand("d").device(), 1);
        return null;
    };

    @Test
    void helloRunBye() {
        String run = "{\"type\":\"run\",\"batch\":0,\"vectors\":[{\"id\":\"a\",\"family\":\"fx5-time-add\",\"instruction\":\"TADD\","
                + "\"assumes\":{\"device_sizes\":{\"D\":8000}},\"initial\":{\"devices\":{\"D0\":5,\"SM700\":false},"
                + "\"operands\":{\"d\":{\"device\":\"D0\"}}},\"steps\":[{\"en\":true}]}]}\n";
        Served s = serve(ADD_ONE, HELLO + run + "{\"type\":\"bye\"}\n");
        assertEquals(0, s.status());
        JsonNode hello = s.lines().get(0);
        assertEquals("hello", hello.get("type").stringValue());
        assertEquals(2, hello.get("instructions").size());
        assertEquals("carry-at-24", hello.get("interpretations").get("TADD-EXACT-24").stringValue());
        JsonNode result = s.lines().get(1);
        assertEquals("{\"type\":\"result\",\"id\":\"a\",\"steps\":[{\"devices\":{\"D0\":1,\"SM700\":false}}]}", result.toString());
    }

    @Test
    void aLineThatIsNotJsonIsFatal() {
        Served s = serve(ADD_ONE, HELLO + "{not json\n");
        assertEquals(2, s.status());
        JsonNode fatal = s.lines().get(1);
        assertEquals("fatal", fatal.get("type").stringValue());
        assertTrue(fatal.get("message").stringValue().startsWith("line 2 is not JSON"), fatal.toString());
    }

    @Test
    void anotherProtocolIsFatal() {
        Served s = serve(ADD_ONE, "{\"type\":\"hello\",\"protocol\":2,\"families\":{}}\n");
        assertEquals(1, s.status());
        assertEquals("this adapter speaks protocol 1, not 2", s.lines().get(0).get("message").stringValue());
    }

    @Test
    void aVectorItCannotReadIsAnErrorOfThatVector() {
        String run = "{\"type\":\"run\",\"batch\":0,\"vectors\":[{\"id\":\"broken\",\"family\":\"fx5-time-add\","
                + "\"instruction\":\"TADD\",\"initial\":{\"devices\":{\"D0\":\"x\"},\"operands\":{}},\"steps\":[]}]}\n";
        Served s = serve(ADD_ONE, run);
        assertEquals(0, s.status());
        JsonNode r = s.lines().get(0);
        assertEquals("broken", r.get("id").stringValue());
        assertTrue(r.get("error").stringValue().contains("initial.devices.D0"), r.toString());
    }

    @Test
    void anUnknownMessageIsFatalAndAnExceptionAnError() {
        assertEquals(2, serve(ADD_ONE, "{\"type\":\"sing\"}\n").status());
        Implementation boom = request -> {
            throw new IllegalStateException("nope");
        };
        String run = "{\"type\":\"run\",\"batch\":0,\"vectors\":[{\"id\":\"a\",\"family\":\"f\",\"instruction\":\"TADD\","
                + "\"initial\":{\"devices\":{},\"operands\":{}},\"steps\":[{\"en\":true}]}]}\n";
        JsonNode r = serve(boom, run).lines().get(0);
        assertTrue(r.get("error").stringValue().startsWith("IllegalStateException: nope"), r.toString());
        // A VectorError is the implementation's own report: its words alone, as the error answer.
        Implementation reports = request -> {
            throw new VectorError("comparator fault at s2");
        };
        assertEquals("comparator fault at s2", serve(reports, run).lines().get(0).get("error").stringValue());
    }
}
