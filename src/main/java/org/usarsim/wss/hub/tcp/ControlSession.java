package org.usarsim.wss.hub.tcp;

import org.usarsim.wss.hub.core.DnsResult;
import java.io.IOException;
import java.net.InetAddress;
import java.net.StandardSocketOptions;
import java.nio.ByteBuffer;
import java.nio.channels.ClosedChannelException;
import java.nio.channels.SocketChannel;
import java.util.List;
import java.util.OptionalDouble;
import java.util.logging.Logger;
import org.usarsim.wss.routes.Route;
import org.usarsim.wss.routes.RouteTable;
import org.usarsim.wss.hub.core.RobotSession;
import org.usarsim.wss.protocol.Arguments;
import org.usarsim.wss.protocol.Command;
import org.usarsim.wss.protocol.CommandParser;
import org.usarsim.wss.protocol.LineSplitter;
import org.usarsim.wss.protocol.ProtocolException;
import org.usarsim.wss.protocol.Replies;

/**
 * One robot's control connection, on its own thread: reads lines, answers each with exactly one
 * reply written in one write, in order. Never sends anything unasked and never closes the
 * connection over a bad command. When the connection closes, the robot is deregistered.
 */
public final class ControlSession implements Runnable, LineSplitter.Sink, RobotSession {

    private static final Logger LOG = Logger.getLogger(ControlSession.class.getName());

    private final ControlHub hub;
    private final ControlListener listener;
    private final SocketChannel channel;
    private final InetAddress address;
    private final String peer;
    private final LineSplitter splitter = new LineSplitter();
    /** The name this connection registered, once INIT succeeded. Only the session's thread touches it. */
    private String robot;

    ControlSession(ControlHub hub, ControlListener listener, SocketChannel channel) {
        this.hub = hub;
        this.listener = listener;
        this.channel = channel;
        this.address = channel.socket().getInetAddress();
        this.peer = address.getHostAddress() + ":" + channel.socket().getPort();
    }

    void start() {
        Thread thread = new Thread(this, "control " + peer);
        thread.setDaemon(true);
        thread.start();
    }

    SocketChannel channel() {
        return channel;
    }

    @Override
    public void close() {
        Closing.quietly(channel);
    }

    @Override
    public void run() {
        LOG.fine(() -> "control connection from " + peer);
        try {
            channel.setOption(StandardSocketOptions.TCP_NODELAY, true);
            hub.keepAlive().apply(channel);
            ByteBuffer buffer = ByteBuffer.allocate(16 * 1024);
            int read;
            while ((read = channel.read(buffer)) >= 0) {
                splitter.feed(buffer.array(), 0, read, this);
                buffer.clear();
            }
        } catch (ClosedChannelException e) {
            LOG.fine(() -> "control connection from " + peer + " closed by the server");
        } catch (IOException e) {
            // A reset, or keepalive found the robot's machine gone (Connection timed out).
            if (robot == null) {
                LOG.fine(() -> "control connection from " + peer + " ended: " + e);
            } else {
                hub.say(LOG, "lost control connections", address, "lost the control connection of " + robot + " from "
                        + peer + " (" + e.getMessage() + "); deregistering it");
            }
        } finally {
            close();
            listener.ended(this);
            if (robot != null) {
                hub.deregister(robot, this);
            }
            LOG.fine(() -> "control connection from " + peer + " closed");
        }
    }

    @Override
    public void line(String line) {
        String reply;
        try {
            Command command = CommandParser.parse(line);
            if (command == null) {
                return;
            }
            reply = answer(command);
        } catch (ProtocolException e) {
            reply = e.reply();
        } catch (RuntimeException e) {
            hub.warn(LOG, "failed answers", address, peer + ": failed to answer '" + line + "': " + e, e);
            reply = Replies.error(Replies.INTERNAL_ERROR);
        }
        String answered = reply;
        LOG.fine(() -> peer + " " + line + " => " + answered);
        send(reply);
    }

    @Override
    public void lineTooLong() {
        hub.warn(LOG, "over-long lines", address,
                peer + ": a control line longer than " + LineSplitter.MAX_LINE_BYTES + " bytes; answered with an error", null);
        send(Replies.error(Replies.LINE_TOO_LONG));
    }

    private String answer(Command command) throws ProtocolException {
        if (command.type().equals("FORCE") && !command.hasNoSegment()) {
            return force(command); // an operator's, not a robot's: no INIT needed
        }
        if (command.type().equals("ROUTE") && !command.hasNoSegment()) {
            return route(command); // an operator's too
        }
        if (command.type().equals("REPLAY")) {
            return replay(command); // an operator's too; alone, it asks where the replay is
        }
        if (robot == null) {
            boolean init = command.type().equals("INIT") && !command.hasNoSegment();
            return init ? init(command) : Replies.error(Replies.MUST_INIT_FIRST);
        }
        if (command.hasNoSegment()) {
            return Replies.error(Replies.UNKNOWN_OR_SECOND_INIT);
        }
        switch (command.type()) {
            case "GETSS":
                return signalStrength(command);
            case "DNS":
                return dns(command);
            case "REVERSEDNS":
                return reverseDns(command);
            default:
                return Replies.error(Replies.UNKNOWN_OR_SECOND_INIT);
        }
    }

    private String init(Command command) throws ProtocolException {
        String name = Arguments.robot(command);
        List<Integer> ports = Arguments.portList(command);
        if (!hub.register(name, address, ports, this)) {
            return Replies.error(Replies.ALREADY_EXISTS);
        }
        robot = name;
        return Replies.initOk();
    }

    private String signalStrength(Command command) throws ProtocolException {
        String other = Arguments.robot(command);
        if (other.equals(robot)) {
            return Replies.signalToSelf(other);
        }
        OptionalDouble strength = hub.signalStrength(robot, other);
        return strength.isPresent() ? Replies.signal(other, strength.getAsDouble()) : Replies.signalUnknownRobot(other);
    }

    private String dns(Command command) throws ProtocolException {
        String other = Arguments.robot(command);
        int targetPort = Arguments.targetPort(command);
        DnsResult result = hub.dns(robot, other, targetPort);
        switch (result.outcome()) {
            case OK:
                return Replies.dns(other, result.port());
            case NO_SUCH_ROBOT:
                return Replies.dnsNoSuchRobot(other);
            case NO_SUCH_TARGET_PORT:
                return Replies.dnsNotListening(other);
            default:
                return Replies.error(Replies.COULD_NOT_ALLOCATE_PORT);
        }
    }

    private String reverseDns(Command command) throws ProtocolException {
        String asked = Arguments.askedPort(command);
        String source = hub.reverseDns(robot, Integer.parseInt(asked));
        return source == null ? Replies.reverseDnsUnknown(asked) : Replies.reverseDns(asked, source);
    }

    /** FORCE (docs/protocol.md section 7), only from an address of wss.operators: {@link OperatorCommands#force}. */
    private String force(Command command) throws ProtocolException {
        if (!hub.isOperator(address)) {
            return refused("FORCE");
        }
        return OperatorCommands.force(hub, command, address, peer);
    }

    /** An operator command from an address not in wss.operators: said (limited), and its error. */
    private String refused(String what) {
        hub.warn(LOG, "operator commands refused", address,
                peer + ": " + what + " refused: " + address.getHostAddress() + " is not in wss.operators", null);
        return Replies.error(Replies.NOT_AN_OPERATOR);
    }

    /**
     * The operator command ROUTE (docs/routes.md, docs/protocol.md section 9): {@code ROUTE {Robot A} {Peer B}}, the
     * best route from A to B as last found. Only from an address of wss.operators, as FORCE: a
     * robot's own routing must find what the WSS knows; the names need not be registered.
     */
    private String route(Command command) throws ProtocolException {
        if (!hub.isOperator(address)) {
            return refused("ROUTE");
        }
        List<String> pair = Arguments.pair(command);
        RouteTable routes = hub.routes();
        Route route = routes.route(pair.get(0), pair.get(1));
        long rate = routes.rule().shaped() ? route.rateBound() : -1;
        return route.exists() ? Replies.route(route.from(), route.to(), route.hops(), route.pathText(), route.weakest().toString(), rate)
                : Replies.noRoute(route.from(), route.to(), rate);
    }

    /** REPLAY (docs/protocol.md section 8), only from an address of wss.operators: {@link OperatorCommands#replay}. */
    private String replay(Command command) throws ProtocolException {
        if (!hub.isOperator(address)) {
            return refused("REPLAY");
        }
        return OperatorCommands.replay(hub, command, address, peer);
    }

    private void send(String reply) {
        ByteBuffer bytes = ByteBuffer.wrap(Replies.wire(reply));
        try {
            while (bytes.hasRemaining()) {
                channel.write(bytes);
            }
        } catch (IOException e) {
            LOG.fine(() -> peer + ": could not send a reply: " + e);
            close();
        }
    }
}
