package org.usarsim.wss.world;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.ros.JsonException;
import org.usarsim.wss.ros.JsonLimits;
import org.usarsim.wss.ros.JsonNode;

/** A connection's fragment_size as rosbridge_library 0.11.17's protocol.py and fragmentation.py apply it. */
class FragmentsTest {

    /** 60 chars, as in rosbridge's own example. */
    private static final String FRAME = "{\"op\": \"publish\", \"topic\": \"/tf\", \"msg\": {\"transforms\": []}}";

    private final Fragments fragments = new Fragments();

    @Test
    void aFrameLongerThanTheSizeGoesInFragmentOpsOfItsTextWithAFloatTotal() throws JsonException {
        assertEquals(60, FRAME.length());
        assertEquals(List.of(FRAME), fragments.of(FRAME, null), "no fragment_size: whole");
        fragments.set(20.0, true);
        assertEquals(List.of(
                "{\"op\":\"fragment\",\"id\":0,\"data\":\"{\\\"op\\\": \\\"publish\\\", \\\"t\",\"num\":0,\"total\":3.95}",
                "{\"op\":\"fragment\",\"id\":0,\"data\":\"opic\\\": \\\"/tf\\\", \\\"msg\\\":\",\"num\":1,\"total\":3.95}",
                "{\"op\":\"fragment\",\"id\":0,\"data\":\" {\\\"transforms\\\": []}}\",\"num\":2,\"total\":3.95}"),
                fragments.of(FRAME, null));
        StringBuilder joined = new StringBuilder();
        for (String fragment : fragments.of(FRAME, null)) {
            joined.append(JsonNode.parse(fragment, JsonLimits.DEFAULT).get("data").string());
        }
        assertEquals(FRAME, joined.toString(), "reassembled");
        assertEquals("x", JsonNode.parse(fragments.of(FRAME, "x").get(0), JsonLimits.DEFAULT).get("id").string(), "a frame's own id");
    }

    @Test
    void aFrameUpToTheSizeGoesWhole() throws JsonException {
        fragments.set(60.0, true);
        assertEquals(List.of(FRAME), fragments.of(FRAME, null));
        fragments.set(59.0, true);
        assertEquals(2, fragments.of(FRAME, null).size());
        assertEquals("2.0", JsonNode.parse(fragments.of(FRAME, null).get(1), JsonLimits.DEFAULT).get("total").value().toString());
        fragments.set(20.0, true);
        List<String> four = fragments.of(FRAME + " ", null);
        assertEquals(4, four.size(), "61 chars: total 4.0, as many as the total truncated (3.95: 3)");
        assertEquals(4.0, JsonNode.parse(four.get(3), JsonLimits.DEFAULT).get("total").number());
        fragments.set(null, false);
        assertEquals(List.of(FRAME), fragments.of(FRAME, null), "null: no fragments again");
    }

    @Test
    void aSizeRosbridgeCannotSplitWithSendsNothingLonger() {
        fragments.set(100.0, false); // written 100.0: a float
        assertEquals(List.of(FRAME), fragments.of(FRAME, null), "a float compares");
        fragments.set(20.0, false);
        assertEquals(List.of(), fragments.of(FRAME, null), "but range() refuses it");
        fragments.set(0.0, true);
        assertEquals(List.of(), fragments.of(FRAME, null));
        fragments.set(-5.0, true);
        assertEquals(List.of(), fragments.of(FRAME, null));
        fragments.set("20", false);
        assertEquals(List.of(), fragments.of(FRAME, null), "a string does not even compare");
        fragments.set(true, false);
        assertEquals(60, fragments.of(FRAME, null).size(), "True is 1");
    }

    @Test
    void theLengthIsOfTheTextWithNonAsciiEscapedAsPythonsJsonWritesIt() {
        fragments.set(10.0, true);
        assertEquals("\"\\u00e9\\u00e9\"", Fragments.ascii("\"éé\""));
        assertEquals(2, fragments.of("{\"a\":\"é\"}", null).size(), "7 chars, 12 once escaped");
    }

    @Test
    void floatsAsPythonsReprWritesThem() {
        assertEquals("3.95", Fragments.pythonFloat(59.0 / 20 + 1));
        assertEquals("4.0", Fragments.pythonFloat(60.0 / 20 + 1));
        assertEquals("1.3333333333333333", Fragments.pythonFloat(1.0 / 3 + 1));
        assertEquals("1.1", Fragments.pythonFloat(1.1));
        assertEquals("12345678.5", Fragments.pythonFloat(12345678.5));
    }
}
