package org.usarsim.wss.ros;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The JSON parser's strictness and limits, each refusal one clear line with its offset; and the writer. */
class JsonTest {

    private static Object parse(String text) throws JsonException {
        return Json.parse(text, JsonLimits.DEFAULT);
    }

    private static String refusal(String text) {
        return refusal(text, JsonLimits.DEFAULT);
    }

    private static String refusal(String text, JsonLimits limits) {
        return assertThrows(JsonException.class, () -> Json.parse(text, limits)).getMessage();
    }

    @Test
    void valuesOfEveryKind() throws JsonException {
        Map<String, Object> expected = new LinkedHashMap<>();
        expected.put("topic", "/gazebo/model_states");
        expected.put("list", Arrays.asList(1.0, -0.5, 1500.0, 0.01, true, false, null, "é😀\"\\\b\f\n\r\t"));
        expected.put("empty", Map.of());
        expected.put("none", List.of());
        assertEquals(expected, parse(" {\"topic\":\"\\/gazebo\\/model_states\",\r\n\t\"list\":[1,-0.5,1.5e3,1E-2,true,false,null,"
                + "\"\\u00e9\\ud83d\\ude00\\\"\\\\\\b\\f\\n\\r\\t\"],\"empty\":{},\"none\":[]} "));
        assertEquals(List.of("key", "order"), new ArrayList<>(((Map<?, ?>) parse("{\"key\":1,\"order\":2}")).keySet()));
        assertSame(parse("100"), parse("[100]") instanceof List<?> list ? list.get(0) : null, "small integers are shared");
        assertEquals(12345678901234567890.0, parse("12345678901234567890"));
        assertEquals(0.0, parse("1e-999"), "underflows to 0: finite");
        assertNull(parse("null"));
    }

    @Test
    void aTextOverTheSizeLimitIsRefusedBeforeItIsRead() {
        String text = "[" + "0,".repeat(600) + "0]";
        assertEquals("at offset 1000: the text is 1203 chars, over the limit of 1000", refusal(text, new JsonLimits(1000, 64)));
    }

    @Test
    void nestingOverTheDepthLimitIsRefused() throws JsonException {
        assertEquals(64, depth(parse("[".repeat(64) + "]".repeat(64))));
        assertEquals("at offset 64: nested deeper than the limit of 64", refusal("[".repeat(65) + "]".repeat(65)));
        assertEquals("at offset 64: nested deeper than the limit of 64", refusal("[".repeat(100_000)));
        assertEquals("at offset 11: nested deeper than the limit of 3", refusal("{\"a\":{\"b\":[{\"c\":1}]}}", new JsonLimits(100, 3)));
    }

    private static int depth(Object value) {
        return value instanceof List<?> list ? 1 + (list.isEmpty() ? 0 : depth(list.get(0))) : 0;
    }

    @Test
    void numbersThatAreNotFiniteOrNotJsonAreRefused() {
        assertEquals("at offset 5: the number 1e999 is not finite", refusal("{\"x\":1e999}"));
        assertEquals("at offset 1: the number -2E+400 is not finite", refusal("[-2E+400]"));
        assertEquals("at offset 0: expected a value, found 'N'", refusal("NaN"));
        assertEquals("at offset 1: expected a value, found 'I'", refusal("[Infinity]"));
        assertEquals("at offset 2: expected a digit, found 'I'", refusal("[-Infinity]"));
        assertEquals("at offset 1: unexpected '1' after the value", refusal("01"));
        assertEquals("at offset 3: expected a digit after '.', found ']'", refusal("[1.]"));
        assertEquals("at offset 1: expected a value, found '.'", refusal("[.5]"));
        assertEquals("at offset 1: expected a value, found '+'", refusal("[+1]"));
        assertEquals("at offset 3: expected a digit in the exponent, found ']'", refusal("[1e]"));
        assertEquals("at offset 1: expected a value, found 'x'", refusal("[x10]"));
    }

    @Test
    void badEscapesAndRawControlCharsAreRefused() {
        assertEquals("at offset 3: a bad escape \\x in a string", refusal("[\"a\\x\"]"));
        assertEquals("at offset 2: a bad escape: \\u needs four hex digits", refusal("[\"\\u12G4\"]"));
        assertEquals("at offset 2: a high surrogate escape without its low one", refusal("[\"\\ud800\"]"));
        assertEquals("at offset 2: a high surrogate escape without its low one", refusal("[\"\\ud800\\u0041\"]"));
        assertEquals("at offset 2: a low surrogate escape without its high one", refusal("[\"\\udc00\"]"));
        assertEquals("at offset 3: a raw control char '\\u000a' in a string", refusal("[\"a\nb\"]"));
        assertEquals("at offset 2: a bad escape \\' in a string", refusal("[\"\\'\"]"));
    }

    @Test
    void aTruncatedTextSaysSo() {
        String truncated = "the text ends where %s was expected (truncated)";
        assertEquals("at offset 32: " + truncated.formatted("a key in quotes"), refusal("{\"op\":\"subscribe\",\"topic\":\"/tf\","));
        assertEquals("at offset 4: " + truncated.formatted("the end of a string"), refusal("[\"ab"));
        assertEquals("at offset 3: " + truncated.formatted("'true'"), refusal("[tr"));
        assertEquals("at offset 5: " + truncated.formatted("four hex digits"), refusal("\"\\u00"));
        assertEquals("at offset 0: " + truncated.formatted("a value"), refusal(""));
        assertEquals("at offset 5: " + truncated.formatted("a value"), refusal("{\"a\":"));
        assertEquals("at offset 2: " + truncated.formatted("',' or ']'"), refusal("[1"));
    }

    @Test
    void whatIsNotOneValueIsRefused() {
        assertEquals("at offset 3: unexpected 'x' after the value", refusal("{} x"));
        assertEquals("at offset 2: unexpected '{' after the value", refusal("{}{}"));
        assertEquals("at offset 3: expected a value, found ']'", refusal("[1,]"));
        assertEquals("at offset 7: expected a key in quotes, found '}'", refusal("{\"a\":1,}"));
        assertEquals("at offset 1: expected a key in quotes, found 'a'", refusal("{a:1}"));
        assertEquals("at offset 4: expected ':', found '1'", refusal("{\"a\"1}"));
        assertEquals("at offset 7: the key \"a\" twice in one object", refusal("{\"a\":1,\"a\":2}"));
        assertEquals("at offset 0: expected a value, found '\\u00a0'", refusal("\u00a0[]"));
    }

    @Test
    void unknownFieldsAreIgnoredAndNullWhereAnObjectIsExpectedIsNamedByItsPath() throws JsonException {
        PoseDecoder decoder = new PoseDecoder(MessageType.MODEL_STATES);
        String pose = "{\"position\":{\"x\":1,\"y\":2,\"z\":3,\"w\":\"extra\"},\"orientation\":{\"x\":0,\"y\":0,\"z\":0,\"w\":1}}";
        List<RobotPose> poses = decoder.decode("{\"op\":\"publish\",\"id\":\"x\",\"topic\":\"/gazebo/model_states\",\"msg\":"
                + "{\"name\":[\"A\"],\"pose\":[" + pose + "],\"extra\":{\"deep\":[null]}},\"more\":1}");
        assertEquals(List.of(new RobotPose("A", 1, 2, 3, RobotPose.NO_STAMP)), poses);
        assertEquals("msg.pose[1]: expected an object, found null", assertThrows(JsonException.class,
                () -> decoder.decode("{\"op\":\"publish\",\"msg\":{\"name\":[\"A\",\"B\"],\"pose\":[" + pose + ",null]}}"))
                .getMessage());
        assertEquals("msg.pose[0].position.x: expected a number, found null", assertThrows(JsonException.class,
                () -> decoder.decode("{\"op\":\"publish\",\"msg\":{\"name\":[\"A\"],\"pose\":[" + pose.replace("\"x\":1", "\"x\":null")
                        + "]}}")).getMessage());
        assertEquals("msg: expected an object, found null", assertThrows(JsonException.class,
                () -> decoder.decode("{\"op\":\"publish\",\"msg\":null}")).getMessage());
        assertEquals("msg.name: missing", assertThrows(JsonException.class,
                () -> decoder.decode("{\"op\":\"publish\",\"msg\":{\"pose\":[]}}")).getMessage());
        assertEquals("msg.pose: 0 poses for 1 names", assertThrows(JsonException.class,
                () -> decoder.decode("{\"op\":\"publish\",\"msg\":{\"name\":[\"A\"],\"pose\":[]}}")).getMessage());
        assertEquals("the frame: expected an object, found an array", assertThrows(JsonException.class,
                () -> decoder.decode("[]")).getMessage());
        assertEquals("op: expected a string, found a number", assertThrows(JsonException.class,
                () -> decoder.decode("{\"op\":3}")).getMessage());
    }

    @Test
    void framesThatAreNotPublishCarryNoPose() throws JsonException {
        PoseDecoder decoder = new PoseDecoder(MessageType.TF);
        assertEquals(List.of(), decoder.decode("{\"op\":\"status\",\"level\":\"error\",\"msg\":\"no such topic\"}"));
        assertEquals(List.of(), decoder.decode("{\"topic\":\"/tf\"}"));
        assertEquals("status", RosFrame.parse("{\"op\":\"status\"}", JsonLimits.DEFAULT).op());
    }

    @Test
    void theWriterWritesWhatTheParserReads() throws JsonException {
        Map<String, Object> value = new LinkedHashMap<>();
        value.put("op", "publish");
        value.put("topic", "/tf");
        value.put("text", "quote \" backslash \\ tab \t nul \u0000 é");
        value.put("numbers", List.of(1, -2L, 0.25, 1e-7, 43.200443269333334));
        value.put("nothing", null);
        value.put("yes", true);
        String text = Json.write(value);
        assertEquals("{\"op\":\"publish\",\"topic\":\"/tf\",\"text\":\"quote \\\" backslash \\\\ tab \\t nul \\u0000 é\","
                + "\"numbers\":[1,-2,0.25,1.0E-7,43.200443269333334],\"nothing\":null,\"yes\":true}", text);
        Map<?, ?> back = (Map<?, ?>) parse(text);
        assertEquals(value.get("text"), back.get("text"));
        assertEquals(List.of(1.0, -2.0, 0.25, 1e-7, 43.200443269333334), back.get("numbers"));
        assertThrows(IllegalArgumentException.class, () -> Json.write(List.of(Double.NaN)));
        assertThrows(IllegalArgumentException.class, () -> Json.write(new Object()));
        assertEquals("\"a\\\"b\"", Json.quote("a\"b"));
    }
}
