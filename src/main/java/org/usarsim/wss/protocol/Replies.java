package org.usarsim.wss.protocol;

import java.nio.charset.StandardCharsets;
import org.usarsim.wss.Decimals;

/**
 * Every reply the server sends on a control connection, spelled exactly as the original
 * (typos included: clients compare these strings). Nothing else in the server builds a reply.
 */
public final class Replies {

    /** Every reply ends with CR LF. */
    static final String LINE_END = "\r\n";

    // Reasons of the original, kept letter for letter.
    public static final String MUST_INIT_FIRST = "Must.Use.INIT.Method.First";
    public static final String PORTS_MUST_BE_INTEGER = "Ports.List.Must.Be.Integer";
    public static final String NAME_MUST_NOT_BE_EMPTY = "Robot.Name.Must.Not.Be.Empty";
    public static final String ALREADY_EXISTS = "Robot.Alread.Exists";
    public static final String UNKNOWN_OR_SECOND_INIT = "Method.Unknown.Or.Can.INIT.only.once";
    public static final String PORT_MUST_BE_INTEGER = "Port.Must.Be.Integer";
    public static final String COULD_NOT_ALLOCATE_PORT = "Could.Not.Allocate.Port";

    // Reasons of ours, for input the original mishandled (see docs/protocol.md).
    public static final String LINE_TOO_LONG = "Line.Too.Long";
    public static final String MALFORMED_NO_COMMAND = "Malformed.Line.No.Command";
    public static final String MALFORMED_TEXT_OUTSIDE_BRACES = "Malformed.Line.Text.Outside.Braces";
    public static final String MALFORMED_UNCLOSED_BRACE = "Malformed.Line.Unclosed.Brace";
    public static final String MALFORMED_NESTED_BRACE = "Malformed.Line.Nested.Brace";
    public static final String MALFORMED_EMPTY_SEGMENT = "Malformed.Line.Empty.Segment";
    public static final String NAME_MUST_NOT_CONTAIN_WHITESPACE = "Robot.Name.Must.Not.Contain.Whitespace";
    /** A name longer than {@link Arguments#MAX_NAME} characters (issue 27: names reach every log line). */
    public static final String NAME_TOO_LONG = "Robot.Name.Must.Be.At.Most.256.Characters";
    /** A fault of the server's own (logged as a WARNING); the connection stays usable. */
    public static final String INTERNAL_ERROR = "Server.Internal.Error";

    // Reasons of the operator command FORCE, an extension of ours (docs/protocol.md section 7).
    public static final String NOT_AN_OPERATOR = "Not.An.Operator.Address";
    public static final String PEER_NAME_MUST_NOT_BE_EMPTY = "Peer.Name.Must.Not.Be.Empty";
    public static final String PEER_NAME_MUST_NOT_CONTAIN_WHITESPACE = "Peer.Name.Must.Not.Contain.Whitespace";
    public static final String PEER_NAME_TOO_LONG = "Peer.Name.Must.Be.At.Most.256.Characters";
    public static final String PEER_MUST_NOT_BE_THE_ROBOT = "Peer.Must.Not.Be.The.Robot";
    public static final String STATE_MUST_BE_DOWN_UP_OR_MODEL = "State.Must.Be.Down.Up.Or.Model";
    /** FORCE's {@code Rate}, with links shaped (docs/shaping.md): a bit rate such as 512k, 1M or 54M, more than 0. */
    public static final String RATE_MUST_BE_A_BIT_RATE = "Rate.Must.Be.A.Bit.Rate";
    public static final String DELAY_MUST_BE_0_TO_10000_MS = "Delay.Must.Be.0.To.10000.Ms";
    public static final String RATE_AND_DELAY_NEED_STATE_UP = "Rate.And.Delay.Need.State.Up";
    /** FORCE's {@code Jitter} (docs/shaping.md, "Jitter"): whole milliseconds from 0 to 10,000; it needs State Up too. */
    public static final String JITTER_MUST_BE_0_TO_10000_MS = "Jitter.Must.Be.0.To.10000.Ms";

    // Reasons of the operator command REPLAY, an extension of ours (docs/protocol.md section 8).
    public static final String NOT_A_REPLAY = "Not.A.Replay";
    public static final String TIME_MUST_BE_0_TO_DURATION = "Time.Must.Be.0.To.Duration.Seconds";
    public static final String SPEED_MUST_BE_0_25_TO_8 = "Speed.Must.Be.0.25.To.8";
    public static final String STATE_MUST_BE_PAUSE_OR_PLAY = "State.Must.Be.Pause.Or.Play";

    private Replies() {
    }

    /** The reason a control line that breaks the segment grammar gets (docs/protocol.md, 1.2). */
    static String malformed(SegmentException.Problem problem) {
        return switch (problem) {
            case NO_WORD -> MALFORMED_NO_COMMAND;
            case TEXT_OUTSIDE_BRACES -> MALFORMED_TEXT_OUTSIDE_BRACES;
            case UNCLOSED_BRACE -> MALFORMED_UNCLOSED_BRACE;
            case NESTED_BRACE -> MALFORMED_NESTED_BRACE;
            case EMPTY_SEGMENT -> MALFORMED_EMPTY_SEGMENT;
        };
    }

    /** The bytes to write for a reply: the line and CR LF, to be sent in one write. */
    public static byte[] wire(String reply) {
        return (reply + LINE_END).getBytes(StandardCharsets.UTF_8);
    }

    public static String error(String reason) {
        return "ERROR {Reason " + reason + "}";
    }

    public static String initOk() {
        return "INITREPLY {Status OK}";
    }

    public static String signalToSelf(String robot) {
        return "SS {Robot " + robot + "} {Strength INF} {Error SS.To.Self}";
    }

    public static String signalUnknownRobot(String robot) {
        return "SS {Robot " + robot + "} {Strength NaN} {Error Robot.Does.Not.Exist}";
    }

    /**
     * The reply to a GETSS the model answered: +infinity and NaN or a value above 0 dBm are
     * reported as the model's error; anything else is printed like C's {@code %g}.
     */
    public static String signal(String robot, double strength) {
        if (strength == Double.POSITIVE_INFINITY) {
            return "SS {Robot " + robot + "} {Strength INF} {Error Model.Returned.INF}";
        }
        if (Double.isNaN(strength) || strength > 0) {
            return "SS {Robot " + robot + "} {Strength NaN} {Error Model.Returned.NaN}";
        }
        return "SS {Robot " + robot + "} {Strength " + Strengths.format(strength) + "}";
    }

    public static String dns(String robot, int port) {
        return "DNSREPLY {Robot " + robot + "} {Port " + port + "}";
    }

    public static String dnsNoSuchRobot(String robot) {
        return "DNSREPLY {Robot " + robot + "} {Port -1} {Error NoSuchRobot}";
    }

    public static String dnsNotListening(String robot) {
        return "DNSREPLY {Robot " + robot + "} {Port -1} {Error RobotDoesNotListenOnThisPort}";
    }

    public static String reverseDns(String port, String sourceRobot) {
        return "REVERSEDNSREPLY {Port " + port + "} {Robot " + sourceRobot + "}";
    }

    public static String reverseDnsUnknown(String port) {
        return "REVERSEDNSREPLY {Port " + port + "} {Error UnknownOrIllegalPort}";
    }

    /** FORCE done: the pair is forced down or up, or given back to the model. */
    public static String forceOk() {
        return "FORCEREPLY {Status OK}";
    }

    /**
     * ROUTE's answer (docs/routes.md): the route from robot to peer, its hops, its path
     * ({@code A,R1,B}), its weakest hop ({@code R1,B}), and with links shaped ({@code rate} 0 or
     * more; -1 unshaped) the rate one stream could have over it.
     */
    public static String route(String robot, String peer, int hops, String path, String weakest, long rate) {
        return "ROUTEREPLY {Robot " + robot + "} {Peer " + peer + "} {Hops " + hops + "} {Path " + path + "} {Weakest " + weakest + "}"
                + (rate >= 0 ? " {Rate " + rate + "}" : "");
    }

    /** ROUTE's answer when there is no route: {@code {Hops -1}}, and {@code {Rate 0}} with links shaped ({@code rate} 0; -1 unshaped). */
    public static String noRoute(String robot, String peer, long rate) {
        return "ROUTEREPLY {Robot " + robot + "} {Peer " + peer + "} {Hops -1}" + (rate >= 0 ? " {Rate " + rate + "}" : "");
    }

    /**
     * REPLAY done (or only asked): where the replay is after the change, in seconds, its duration,
     * its speed, whether it plays, and the recorded time of the poll it applied last (what GETSS
     * answers from). Numbers to the millisecond, trailing zeros dropped.
     */
    public static String replayOk(double timeSeconds, double durationSeconds, double speed, boolean playing, double pollSeconds) {
        return "REPLAYREPLY {Status OK} {Time " + decimal(timeSeconds) + "} {Duration " + decimal(durationSeconds) + "} {Speed "
                + decimal(speed) + "} {State " + (playing ? "Play" : "Pause") + "} {Poll " + decimal(pollSeconds) + "}";
    }

    /** {@code 12.3}, {@code 60}, {@code 0.25}: to the thousandth, no trailing zeros, no exponent. */
    static String decimal(double value) {
        if (!Double.isFinite(value)) {
            return "NaN";
        }
        return Decimals.plain(java.math.BigDecimal.valueOf(Math.round(value * 1000), 3));
    }
}
