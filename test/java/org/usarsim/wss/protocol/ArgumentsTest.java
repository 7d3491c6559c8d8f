package org.usarsim.wss.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

class ArgumentsTest {

    private static Command parse(String line) throws ProtocolException {
        return CommandParser.parse(line);
    }

    private static Command withPort(String value) {
        return new Command("X", List.of(new Command.Field("Port", value)));
    }

    private static String reason(org.junit.jupiter.api.function.Executable call) {
        return assertThrows(ProtocolException.class, call).reason();
    }

    // --- robot() -------------------------------------------------------------------------------

    @Test
    void robotName() throws Exception {
        assertEquals("R1", Arguments.robot(parse("GETSS {Robot R1}")));
        assertEquals("Robot_1.x-y", Arguments.robot(parse("INIT {Robot  Robot_1.x-y } {Port 5000}")));
        assertEquals("Rödel", Arguments.robot(parse("DNS {Robot Rödel}")));
    }

    @Test
    void robotNameMissing() {
        assertEquals(Replies.NAME_MUST_NOT_BE_EMPTY, reason(() -> Arguments.robot(parse("GETSS"))));
        assertEquals(Replies.NAME_MUST_NOT_BE_EMPTY, reason(() -> Arguments.robot(parse("INIT {Port 5000}"))));
        // keys are case-sensitive: "robot" is not "Robot"
        assertEquals(Replies.NAME_MUST_NOT_BE_EMPTY, reason(() -> Arguments.robot(parse("GETSS {robot R1}"))));
    }

    @Test
    void robotNameEmpty() {
        assertEquals(Replies.NAME_MUST_NOT_BE_EMPTY, reason(() -> Arguments.robot(parse("GETSS {Robot}"))));
        assertEquals(Replies.NAME_MUST_NOT_BE_EMPTY, reason(() -> Arguments.robot(parse("GETSS {Robot    }"))));
        assertEquals(Replies.NAME_MUST_NOT_BE_EMPTY,
                reason(() -> Arguments.robot(new Command("GETSS", List.of(new Command.Field("Robot", ""))))));
    }

    @Test
    void robotNameWithWhitespaceInside() {
        assertEquals(Replies.NAME_MUST_NOT_CONTAIN_WHITESPACE, reason(() -> Arguments.robot(parse("GETSS {Robot R 1}"))));
        assertEquals(Replies.NAME_MUST_NOT_CONTAIN_WHITESPACE,
                reason(() -> Arguments.robot(parse("GETSS {Robot R\t1}"))));
    }

    @Test
    void robotNameOfAtMost256Characters() throws Exception {
        String longest = "R".repeat(Arguments.MAX_NAME);
        assertEquals(longest, Arguments.robot(parse("INIT {Robot " + longest + "} {Port 5000}")));
        assertEquals(Replies.NAME_TOO_LONG, reason(() -> Arguments.robot(parse("INIT {Robot " + longest + "x} {Port 5000}"))));
        assertEquals(Replies.NAME_TOO_LONG, reason(() -> Arguments.robot(parse("GETSS {Robot " + "N".repeat(60_000) + "}"))));
        assertEquals(Replies.PEER_NAME_TOO_LONG,
                reason(() -> Arguments.peer(parse("FORCE {Robot A} {Peer " + longest + "P} {State Up}"))));
        assertEquals(Replies.NAME_MUST_NOT_CONTAIN_WHITESPACE, reason(() -> Arguments.robot(parse("GETSS {Robot R " + longest + "}"))),
                "whitespace is checked first, as the reasons' order says");
    }

    @Test
    void robotNameLastOfDuplicates() throws Exception {
        assertEquals("B", Arguments.robot(parse("GETSS {Robot A} {Robot B}")));
        assertEquals("Q3", Arguments.robot(parse("INIT {Robot Q2} {Robot Q3} {Port 5000}")));
    }

    // --- portList() ----------------------------------------------------------------------------

    @Test
    void portListSingle() throws Exception {
        assertEquals(List.of(5000), Arguments.portList(parse("INIT {Robot R1} {Port 5000}")));
    }

    @Test
    void portListSeveralInOrder() throws Exception {
        assertEquals(List.of(5001, 5000, 7), Arguments.portList(parse("INIT {Robot R1} {Port 5001,5000,7}")));
    }

    @Test
    void portListWithSpaces() throws Exception {
        assertEquals(List.of(5000, 5001), Arguments.portList(parse("INIT {Robot R1} {Port 5000, 5001}")));
        assertEquals(List.of(5000, 5001, 5002),
                Arguments.portList(parse("INIT {Robot R1} { Port  5000 ,5001 ,  5002 }")));
    }

    @Test
    void portListDuplicatesDroppedOrderKept() throws Exception {
        assertEquals(List.of(5001, 5000), Arguments.portList(parse("INIT {Robot R1} {Port 5001,5000,5001,5000}")));
    }

    @Test
    void portListBounds() throws Exception {
        assertEquals(List.of(1, 65535), Arguments.portList(withPort("1,65535")));
    }

    @Test
    void portListLastOfDuplicates() throws Exception {
        assertEquals(List.of(5001), Arguments.portList(parse("INIT {Robot R1} {Port 5000} {Port 5001}")));
    }

    @Test
    void portListMissingOrEmptyIsEmpty() throws Exception {
        assertEquals(List.of(), Arguments.portList(parse("INIT {Robot R1}")));
        assertEquals(List.of(), Arguments.portList(parse("INIT {Robot R1} {Port}")));
        assertEquals(List.of(), Arguments.portList(parse("INIT {Robot R1} {port 5000}")));
    }

    @ParameterizedTest
    @ValueSource(strings = {"abc", "5000a", "50.00", "5000,abc", "5000,,5001", "5000,", ",5000", "5000 5001",
            "5000;5001", "0x10", "99999999999", "123456789012", "2147483648", "3000000000", "-2147483649"})
    void portListNotIntegers(String value) {
        assertEquals(Replies.PORTS_MUST_BE_INTEGER, reason(() -> Arguments.portList(withPort(value))));
    }

    @ParameterizedTest
    @CsvSource(delimiter = ';', value = {"0;0", "-1;-1", "65536;65536", "70000;70000", "2147483647;2147483647",
            "-2147483648;-2147483648", "0000000000005000;5000", "+5000;5000"})
    void portListAcceptsAnyIntegerAsTheOriginal(String value, int expected) throws Exception {
        assertEquals(List.of(expected), Arguments.portList(withPort(value)));
    }

    @Test
    void portListWithAnOutOfRangeItemKeepsEveryItem() throws Exception {
        assertEquals(List.of(5000, 0), Arguments.portList(withPort("5000,0")));
        assertEquals(List.of(5000, 65536, -1), Arguments.portList(withPort("5000, 65536,-1")));
    }

    // --- targetPort() --------------------------------------------------------------------------

    @Test
    void targetPortMissingIsZero() throws Exception {
        assertEquals(0, Arguments.targetPort(parse("DNS {Robot R2}")));
    }

    @Test
    void targetPortZeroIsZero() throws Exception {
        assertEquals(0, Arguments.targetPort(parse("DNS {Robot R2} {Port 0}")));
    }

    @Test
    void targetPortEmptyValueIsNotAnInteger() {
        // As the original: an empty value fails its integer conversion.
        assertEquals(Replies.PORT_MUST_BE_INTEGER, reason(() -> Arguments.targetPort(parse("DNS {Robot R2} {Port}"))));
        assertEquals(Replies.PORT_MUST_BE_INTEGER, reason(() -> Arguments.targetPort(parse("DNS {Robot R2} {Port   }"))));
    }

    @Test
    void targetPortLastOfDuplicates() throws Exception {
        assertEquals(5001, Arguments.targetPort(parse("DNS {Robot A} {Port 5000} {Port 5001}")));
    }

    @Test
    void portsAreAsciiDigitsOnly() {
        assertEquals(Replies.PORTS_MUST_BE_INTEGER, reason(() -> Arguments.portList(parse("INIT {Robot R} {Port \uFF15\uFF10\uFF10\uFF10}"))));
        assertEquals(Replies.PORT_MUST_BE_INTEGER, reason(() -> Arguments.targetPort(parse("DNS {Robot R} {Port \u0665\u0660\u0660\u0660}"))));
        assertEquals(Replies.PORT_MUST_BE_INTEGER, reason(() -> Arguments.askedPort(parse("REVERSEDNS {Port \uFF15}"))));
    }

    @ParameterizedTest
    @CsvSource({"1,1", "5000,5000", "65535,65535"})
    void targetPortValue(String value, int expected) throws Exception {
        assertEquals(expected, Arguments.targetPort(parse("DNS {Robot R2} {Port " + value + "}")));
    }

    @ParameterizedTest
    @ValueSource(strings = {"abc", "5000a", "5000,5001", "50.0", "99999999999", "2147483648"})
    void targetPortNotInteger(String value) {
        assertEquals(Replies.PORT_MUST_BE_INTEGER, reason(() -> Arguments.targetPort(withPort(value))));
    }

    @ParameterizedTest
    @CsvSource({"-1,-1", "65536,65536", "100000,100000"})
    void targetPortOutOfRangeIsAnIntegerForTheHubToRefuse(String value, int expected) throws Exception {
        assertEquals(expected, Arguments.targetPort(withPort(value)));
    }

    // --- askedPort() ---------------------------------------------------------------------------

    @Test
    void askedPortEchoesTheValue() throws Exception {
        assertEquals("40123", Arguments.askedPort(parse("REVERSEDNS {Port 40123}")));
        assertEquals("40123", Arguments.askedPort(parse("REVERSEDNS {  Port   40123 }")));
    }

    @Test
    void askedPortAnyIntegerIsEchoedForTheHubToAnswerUnknownOrIllegalPort() throws Exception {
        assertEquals("70000", Arguments.askedPort(withPort("70000")));
        assertEquals("-1", Arguments.askedPort(withPort("-1")));
        assertEquals("0", Arguments.askedPort(withPort("0")));
    }

    @Test
    void askedPortMissing() {
        assertEquals(Replies.PORT_MUST_BE_INTEGER, reason(() -> Arguments.askedPort(parse("REVERSEDNS"))));
        assertEquals(Replies.PORT_MUST_BE_INTEGER, reason(() -> Arguments.askedPort(parse("REVERSEDNS {Port}"))));
        assertEquals(Replies.PORT_MUST_BE_INTEGER, reason(() -> Arguments.askedPort(parse("REVERSEDNS {port 1}"))));
    }

    @ParameterizedTest
    @ValueSource(strings = {"abc", "40123x", "1,2", "4.5", "99999999999"})
    void askedPortNotInteger(String value) {
        assertEquals(Replies.PORT_MUST_BE_INTEGER, reason(() -> Arguments.askedPort(withPort(value))));
    }

    // --- integer() -----------------------------------------------------------------------------

    @Test
    void integerParsesDecimalOnly() {
        assertEquals(5000, Arguments.integer("5000"));
        assertEquals(-5, Arguments.integer("-5"));
        assertEquals(Integer.MAX_VALUE, Arguments.integer("2147483647"));
        assertEquals(Integer.MIN_VALUE, Arguments.integer("-2147483648"));
        assertEquals(null, Arguments.integer(""));
        assertEquals(null, Arguments.integer("2147483648"));
        assertEquals(null, Arguments.integer("9999999999"));
        assertEquals(7, Arguments.integer("000000000000007"), "leading zeros, any number of them");
        assertEquals(null, Arguments.integer("1e3"));
        assertEquals(null, Arguments.integer(" 5"));
    }
}
