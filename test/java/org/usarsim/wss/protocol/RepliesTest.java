package org.usarsim.wss.protocol;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Every reply of the table in original-behaviour.md ("Exact replies"), letter for letter. */
class RepliesTest {

    // --- ERROR replies of the original -------------------------------------------------------

    @Test
    void mustInitFirst() {
        assertEquals("ERROR {Reason Must.Use.INIT.Method.First}", Replies.error(Replies.MUST_INIT_FIRST));
    }

    @Test
    void portsListMustBeInteger() {
        assertEquals("ERROR {Reason Ports.List.Must.Be.Integer}", Replies.error(Replies.PORTS_MUST_BE_INTEGER));
    }

    @Test
    void robotNameMustNotBeEmpty() {
        assertEquals("ERROR {Reason Robot.Name.Must.Not.Be.Empty}", Replies.error(Replies.NAME_MUST_NOT_BE_EMPTY));
    }

    @Test
    void robotAlreadExistsKeepsTheOriginalTypo() {
        assertEquals("ERROR {Reason Robot.Alread.Exists}", Replies.error(Replies.ALREADY_EXISTS));
    }

    @Test
    void unknownMethodOrSecondInit() {
        assertEquals("ERROR {Reason Method.Unknown.Or.Can.INIT.only.once}",
                Replies.error(Replies.UNKNOWN_OR_SECOND_INIT));
    }

    @Test
    void portMustBeInteger() {
        assertEquals("ERROR {Reason Port.Must.Be.Integer}", Replies.error(Replies.PORT_MUST_BE_INTEGER));
    }

    @Test
    void couldNotAllocatePort() {
        assertEquals("ERROR {Reason Could.Not.Allocate.Port}", Replies.error(Replies.COULD_NOT_ALLOCATE_PORT));
    }

    /** The manual: "The reason is always a string without whitespace." */
    @ParameterizedTest
    @ValueSource(strings = {
            Replies.MUST_INIT_FIRST, Replies.PORTS_MUST_BE_INTEGER, Replies.NAME_MUST_NOT_BE_EMPTY,
            Replies.ALREADY_EXISTS, Replies.UNKNOWN_OR_SECOND_INIT, Replies.PORT_MUST_BE_INTEGER,
            Replies.COULD_NOT_ALLOCATE_PORT, Replies.LINE_TOO_LONG, Replies.MALFORMED_NO_COMMAND,
            Replies.MALFORMED_TEXT_OUTSIDE_BRACES, Replies.MALFORMED_UNCLOSED_BRACE,
            Replies.MALFORMED_NESTED_BRACE, Replies.MALFORMED_EMPTY_SEGMENT,
            Replies.NAME_MUST_NOT_CONTAIN_WHITESPACE, Replies.NAME_TOO_LONG, Replies.PEER_NAME_TOO_LONG})
    void everyReasonIsOneTokenWithoutWhitespaceOrBraces(String reason) {
        assertEquals(reason.strip(), reason);
        assertEquals(-1, indexOfAny(reason, " \t\r\n{}"), reason);
        assertEquals("ERROR {Reason " + reason + "}", Replies.error(reason));
    }

    private static int indexOfAny(String text, String chars) {
        for (int i = 0; i < text.length(); i++) {
            if (chars.indexOf(text.charAt(i)) >= 0) {
                return i;
            }
        }
        return -1;
    }

    // --- INIT ----------------------------------------------------------------------------------

    @Test
    void initOk() {
        assertEquals("INITREPLY {Status OK}", Replies.initOk());
    }

    // --- GETSS ---------------------------------------------------------------------------------

    @Test
    void signalToSelf() {
        assertEquals("SS {Robot R1} {Strength INF} {Error SS.To.Self}", Replies.signalToSelf("R1"));
    }

    @Test
    void signalToUnknownRobot() {
        assertEquals("SS {Robot Ghost} {Strength NaN} {Error Robot.Does.Not.Exist}",
                Replies.signalUnknownRobot("Ghost"));
    }

    @Test
    void modelReturnedPositiveInfinity() {
        assertEquals("SS {Robot R2} {Strength INF} {Error Model.Returned.INF}",
                Replies.signal("R2", Double.POSITIVE_INFINITY));
    }

    @Test
    void modelReturnedNaN() {
        assertEquals("SS {Robot R2} {Strength NaN} {Error Model.Returned.NaN}", Replies.signal("R2", Double.NaN));
    }

    @ParameterizedTest
    @ValueSource(doubles = {Double.MIN_VALUE, 1e-300, 0.0001, 0.5, 1, 3.5, 1e6, Double.MAX_VALUE})
    void modelReturnedAValueAboveZeroIsReportedAsNaN(double strength) {
        assertEquals("SS {Robot R2} {Strength NaN} {Error Model.Returned.NaN}", Replies.signal("R2", strength));
    }

    @Test
    void noopModelGivesStrengthZero() {
        assertEquals("SS {Robot R2} {Strength 0}", Replies.signal("R2", 0.0));
    }

    @Test
    void ordinaryStrengthIsPrintedLikeC() {
        assertEquals("SS {Robot R2} {Strength -56.6597}", Replies.signal("R2", -56.6597));
        assertEquals("SS {Robot R2} {Strength -56.6597}", Replies.signal("R2", -56.659651));
        assertEquals("SS {Robot R2} {Strength -100}", Replies.signal("R2", -100.0));
        assertEquals("SS {Robot R2} {Strength -49.67}", Replies.signal("R2", -49.67));
        assertEquals("SS {Robot R2} {Strength -67.1235}", Replies.signal("R2", -67.1235));
        assertEquals("SS {Robot R2} {Strength -1.23457e+06}", Replies.signal("R2", -1234567.0));
        assertEquals("SS {Robot R2} {Strength -1e-05}", Replies.signal("R2", -0.00001));
    }

    @Test
    void negativeInfinityIsPrintedAsMinusInf() {
        assertEquals("SS {Robot R2} {Strength -INF}", Replies.signal("R2", Double.NEGATIVE_INFINITY));
    }

    @Test
    void negativeZeroIsPrintedAsC() {
        // printf("%g", -0.0) prints "-0"; not above 0, so no error.
        assertEquals("SS {Robot R2} {Strength -0}", Replies.signal("R2", -0.0));
    }

    // --- DNS / REVERSEDNS ------------------------------------------------------------------------

    @Test
    void dnsOk() {
        assertEquals("DNSREPLY {Robot R2} {Port 50012}", Replies.dns("R2", 50012));
    }

    @Test
    void dnsNoSuchRobot() {
        assertEquals("DNSREPLY {Robot Ghost} {Port -1} {Error NoSuchRobot}", Replies.dnsNoSuchRobot("Ghost"));
    }

    @Test
    void dnsRobotDoesNotListenOnThisPort() {
        assertEquals("DNSREPLY {Robot R2} {Port -1} {Error RobotDoesNotListenOnThisPort}",
                Replies.dnsNotListening("R2"));
    }

    @Test
    void reverseDnsOk() {
        assertEquals("REVERSEDNSREPLY {Port 40123} {Robot R1}", Replies.reverseDns("40123", "R1"));
    }

    @Test
    void reverseDnsUnknownOrIllegalPort() {
        assertEquals("REVERSEDNSREPLY {Port 40123} {Error UnknownOrIllegalPort}", Replies.reverseDnsUnknown("40123"));
    }

    @Test
    void nameAndPortAreEchoedAsAsked() {
        assertEquals("DNSREPLY {Robot Robot_1.a-b} {Port -1} {Error NoSuchRobot}",
                Replies.dnsNoSuchRobot("Robot_1.a-b"));
        assertEquals("REVERSEDNSREPLY {Port 0050} {Error UnknownOrIllegalPort}", Replies.reverseDnsUnknown("0050"));
        assertEquals("SS {Robot Rödel} {Strength NaN} {Error Robot.Does.Not.Exist}",
                Replies.signalUnknownRobot("Rödel"));
    }

    // --- ProtocolException -----------------------------------------------------------------------

    @Test
    void protocolExceptionCarriesReasonAndWholeReply() {
        ProtocolException e = new ProtocolException(Replies.PORT_MUST_BE_INTEGER);
        assertEquals("Port.Must.Be.Integer", e.reason());
        assertEquals("ERROR {Reason Port.Must.Be.Integer}", e.reply());
        assertEquals("Port.Must.Be.Integer", e.getMessage());
    }

    // --- wire format ---------------------------------------------------------------------------

    @Test
    void wireIsTheReplyFollowedByCrLf() {
        byte[] bytes = Replies.wire("INITREPLY {Status OK}");
        assertArrayEquals("INITREPLY {Status OK}\r\n".getBytes(StandardCharsets.US_ASCII), bytes);
        assertEquals('\r', bytes[bytes.length - 2]);
        assertEquals('\n', bytes[bytes.length - 1]);
    }

    @Test
    void wireOfAnErrorReply() {
        assertArrayEquals("ERROR {Reason Must.Use.INIT.Method.First}\r\n".getBytes(StandardCharsets.US_ASCII),
                Replies.wire(Replies.error(Replies.MUST_INIT_FIRST)));
    }

    @Test
    void wireContainsExactlyOneLineEnd() {
        byte[] bytes = Replies.wire(Replies.signal("R2", -56.6597));
        int crs = 0;
        int lfs = 0;
        for (byte b : bytes) {
            crs += b == '\r' ? 1 : 0;
            lfs += b == '\n' ? 1 : 0;
        }
        assertEquals(1, crs);
        assertEquals(1, lfs);
        assertEquals("SS {Robot R2} {Strength -56.6597}\r\n", new String(bytes, StandardCharsets.US_ASCII));
    }

    @Test
    void wireEncodesNamesAsUtf8() {
        byte[] bytes = Replies.wire(Replies.dns("Rö", 5));
        assertArrayEquals(new byte[] {'D', 'N', 'S', 'R', 'E', 'P', 'L', 'Y', ' ', '{', 'R', 'o', 'b', 'o', 't', ' ',
                'R', (byte) 0xC3, (byte) 0xB6, '}', ' ', '{', 'P', 'o', 'r', 't', ' ', '5', '}', '\r', '\n'}, bytes);
    }
}
