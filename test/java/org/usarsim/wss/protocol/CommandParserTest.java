package org.usarsim.wss.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class CommandParserTest {

    private static Command.Field field(String key, String value) {
        return new Command.Field(key, value);
    }

    private static String reasonFor(String line) {
        return assertThrows(ProtocolException.class, () -> CommandParser.parse(line), line).reason();
    }

    // --- well-formed lines -------------------------------------------------------------------

    @Test
    void initWithRobotAndPort() throws Exception {
        Command command = CommandParser.parse("INIT {Robot R1} {Port 5000}");
        assertEquals("INIT", command.type());
        assertEquals(List.of(field("Robot", "R1"), field("Port", "5000")), command.fields());
        assertEquals("R1", command.value("Robot"));
        assertEquals("5000", command.value("Port"));
    }

    @Test
    void commandWithoutFields() throws Exception {
        Command command = CommandParser.parse("GETSS");
        assertEquals("GETSS", command.type());
        assertEquals(List.of(), command.fields());
        assertNull(command.value("Robot"));
    }

    @Test
    void eachCommandOfTheManual() throws Exception {
        assertEquals(new Command("GETSS", List.of(field("Robot", "OtherRobotName"))),
                CommandParser.parse("GETSS {Robot OtherRobotName}"));
        assertEquals(new Command("DNS", List.of(field("Robot", "RobotName"))),
                CommandParser.parse("DNS {Robot RobotName}"));
        assertEquals(new Command("DNS", List.of(field("Robot", "RobotName"), field("Port", "7000"))),
                CommandParser.parse("DNS {Robot RobotName} {Port 7000}"));
        assertEquals(new Command("REVERSEDNS", List.of(field("Port", "40123"))),
                CommandParser.parse("REVERSEDNS {Port 40123}"));
        assertEquals(new Command("INIT", List.of(field("Robot", "R1"), field("Port", "5000,5001"))),
                CommandParser.parse("INIT {Robot R1} {Port 5000,5001}"));
    }

    @Test
    void fieldsKeepTheirOrder() throws Exception {
        Command command = CommandParser.parse("X {C 3} {A 1} {B 2}");
        assertEquals(List.of(field("C", "3"), field("A", "1"), field("B", "2")), command.fields());
    }

    @Test
    void extraWhitespaceBetweenSegments() throws Exception {
        Command expected = new Command("INIT", List.of(field("Robot", "R1"), field("Port", "5000")));
        assertEquals(expected, CommandParser.parse("INIT  {Robot R1}  {Port 5000}"));
        assertEquals(expected, CommandParser.parse("   INIT \t {Robot R1}\t\t{Port 5000}   "));
        assertEquals(expected, CommandParser.parse("INIT {Robot R1} {Port 5000}\r"));
    }

    @Test
    void extraWhitespaceInsideSegments() throws Exception {
        Command expected = new Command("INIT", List.of(field("Robot", "R1"), field("Port", "5000")));
        assertEquals(expected, CommandParser.parse("INIT { Robot R1 } {  Port   5000  }"));
        assertEquals(expected, CommandParser.parse("INIT {Robot\tR1} {\tPort\t5000\t}"));
    }

    @Test
    void segmentsMayTouch() throws Exception {
        Command expected = new Command("INIT", List.of(field("Robot", "R1"), field("Port", "5000")));
        assertEquals(expected, CommandParser.parse("INIT {Robot R1}{Port 5000}"));
        assertEquals(expected, CommandParser.parse("INIT{Robot R1}{Port 5000}"));
    }

    @Test
    void portListWithSpaceAfterComma() throws Exception {
        Command command = CommandParser.parse("INIT {Robot R1} {Port 5000, 5001}");
        assertEquals("5000, 5001", command.value("Port"));
    }

    @Test
    void keyWithoutValueHasEmptyValue() throws Exception {
        Command command = CommandParser.parse("INIT {Robot} {Port   }");
        assertEquals(List.of(field("Robot", ""), field("Port", "")), command.fields());
    }

    @Test
    void valueKeepsInnerWhitespaceButIsTrimmed() throws Exception {
        Command command = CommandParser.parse("GETSS {Robot  R 1  }");
        assertEquals("R 1", command.value("Robot"));
    }

    @Test
    void utf8Names() throws Exception {
        Command command = CommandParser.parse("GETSS {Robot Rödel_ß}");
        assertEquals("Rödel_ß", command.value("Robot"));
    }

    // --- case sensitivity and duplicates -------------------------------------------------------

    @Test
    void typeIsCaseSensitive() throws Exception {
        assertEquals("init", CommandParser.parse("init {Robot R1}").type());
        assertEquals("Init", CommandParser.parse("Init {Robot R1}").type());
        assertEquals("INIT", CommandParser.parse("INIT {Robot R1}").type());
    }

    @Test
    void keysAreCaseSensitive() throws Exception {
        Command command = CommandParser.parse("INIT {robot R1} {PORT 5000}");
        assertNull(command.value("Robot"));
        assertNull(command.value("Port"));
        assertEquals("R1", command.value("robot"));
        assertEquals("5000", command.value("PORT"));
    }

    @Test
    void lastValueCountsOnDuplicateKeys() throws Exception {
        Command command = CommandParser.parse("GETSS {Robot First} {Robot Second}");
        assertEquals("Second", command.value("Robot"), "as in the original");
        assertEquals(List.of(field("Robot", "First"), field("Robot", "Second")), command.fields());
    }

    @Test
    void valueIsCaseSensitiveAndUnchanged() throws Exception {
        assertEquals("rObOt1", CommandParser.parse("GETSS {Robot rObOt1}").value("Robot"));
    }

    // --- blank lines -----------------------------------------------------------------------------

    @ParameterizedTest
    @ValueSource(strings = {"", " ", "   "})
    void blankLinesAreIgnored(String line) throws Exception {
        assertNull(CommandParser.parse(line));
    }

    @ParameterizedTest
    @ValueSource(strings = {"\t", " \t \r", "\r", "\u000B\f", "\u001C", "\u001D", "\u001E", "\u001F", " \u000B "})
    void aLineOfOtherWhitespaceOnlyIsAnUnknownCommandWithNoSegment(String line) throws Exception {
        Command command = CommandParser.parse(line);
        assertEquals("", command.type());
        assertTrue(command.hasNoSegment());
    }

    @Test
    void aCommandWordAloneHasNoSegment() throws Exception {
        assertTrue(CommandParser.parse("INIT").hasNoSegment());
        assertTrue(CommandParser.parse("  GETSS  ").hasNoSegment());
        assertFalse(CommandParser.parse("GETSS {Robot}").hasNoSegment());
    }

    // --- malformed lines -------------------------------------------------------------------------

    @ParameterizedTest
    @ValueSource(strings = {"{Robot R1}", "  {Robot R1}", "{Robot R1} INIT", "{}"})
    void noCommandWord(String line) {
        assertEquals(Replies.MALFORMED_NO_COMMAND, reasonFor(line));
    }

    @ParameterizedTest
    @ValueSource(strings = {
            "INIT Robot R1",
            "INIT {Robot R1} junk",
            "INIT {Robot R1} Port 5000",
            "INIT {Robot R1}}",
            "INIT }",
            "INIT} {Robot R1}",
            "}",
            "GETSS {Robot R1} x {Port 1}",
            "INIT R1 {Robot R1}"})
    void textOutsideBraces(String line) {
        assertEquals(Replies.MALFORMED_TEXT_OUTSIDE_BRACES, reasonFor(line));
    }

    @ParameterizedTest
    @ValueSource(strings = {"INIT {Robot R1", "INIT {Robot R1} {Port 5000", "INIT {", "INIT{Robot"})
    void unclosedBrace(String line) {
        assertEquals(Replies.MALFORMED_UNCLOSED_BRACE, reasonFor(line));
    }

    @ParameterizedTest
    @ValueSource(strings = {"INIT {Robot {R1}}", "INIT {Robot R1 {Port 5000}", "INIT {{Robot R1}}", "INIT {Robot R1} {{}"})
    void nestedBrace(String line) {
        assertEquals(Replies.MALFORMED_NESTED_BRACE, reasonFor(line));
    }

    @ParameterizedTest
    @ValueSource(strings = {"INIT {}", "INIT {   }", "INIT {Robot R1} {}", "INIT {\t}{Robot R1}", "GETSS {}{}"})
    void emptySegment(String line) {
        assertEquals(Replies.MALFORMED_EMPTY_SEGMENT, reasonFor(line));
    }

    @Test
    void malformedLineGetsAnErrorReply() {
        ProtocolException e = assertThrows(ProtocolException.class, () -> CommandParser.parse("INIT {Robot R1"));
        assertEquals("ERROR {Reason Malformed.Line.Unclosed.Brace}", e.reply());
    }

    // --- Command record --------------------------------------------------------------------------

    @Test
    void commandFieldsAreAnUnmodifiableCopy() throws Exception {
        java.util.ArrayList<Command.Field> fields = new java.util.ArrayList<>(List.of(field("Robot", "R1")));
        Command command = new Command("GETSS", fields);
        fields.add(field("Robot", "R2"));
        assertEquals(1, command.fields().size());
        assertThrows(UnsupportedOperationException.class, () -> command.fields().add(field("A", "B")));
    }
}
