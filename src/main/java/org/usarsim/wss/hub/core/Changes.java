package org.usarsim.wss.hub.core;

import java.util.ArrayList;
import java.util.List;

/**
 * What a step of the core decided must happen, as data, in order: the events to deliver, the
 * ports to listen on, stop or give back, the connections to close and why, the control
 * connections to close (a kick), and the robots whose ports to forget later. The hub applies it
 * after its lock: first the socket work, in the order of the steps, then the events, in order.
 */
public final class Changes {

    /** What to do with a port's sockets. */
    public enum PortWork {
        /** Listen again on the port's number (a new listener, of the port's epoch now). */
        LISTEN,
        /** Stop listening at once; the number stays held. */
        STOP,
        /** Stop listening and give the number back to the OS. */
        RELEASE
    }

    /** One port's socket work. */
    public record PortAction(PortWork work, WssPort port, int epoch) {
    }

    /** A connection to close, and why. */
    public record Close(Connection link, CloseReason reason) {
    }

    /** A robot whose ports to forget once it has been gone {@code afterNs} (wss.portMemory), unless it is back. */
    public record ForgetLater(String robot, long afterNs) {
    }

    private final List<HubEvent> events = new ArrayList<>();
    private final List<PortAction> portActions = new ArrayList<>();
    private final List<Close> closes = new ArrayList<>();
    private final List<RobotSession> sessionsToClose = new ArrayList<>();
    private final List<ForgetLater> forgetLater = new ArrayList<>();

    void add(HubEvent event) {
        events.add(event);
    }

    void port(PortWork work, WssPort port) {
        portActions.add(new PortAction(work, port, port.epoch()));
    }

    void close(List<Connection> links, CloseReason reason) {
        links.forEach(link -> closes.add(new Close(link, reason)));
    }

    void closeSession(RobotSession session) {
        sessionsToClose.add(session);
    }

    void forgetLater(String robot, long afterNs) {
        forgetLater.add(new ForgetLater(robot, afterNs));
    }

    public List<HubEvent> events() {
        return events;
    }

    public List<PortAction> portActions() {
        return portActions;
    }

    public List<Close> closes() {
        return closes;
    }

    public List<RobotSession> sessionsToClose() {
        return sessionsToClose;
    }

    public List<ForgetLater> forgetLater() {
        return forgetLater;
    }

    /** Whether there is socket work to do (ports, connections, control connections). */
    public boolean hasSocketWork() {
        return !portActions.isEmpty() || !closes.isEmpty() || !sessionsToClose.isEmpty();
    }
}
