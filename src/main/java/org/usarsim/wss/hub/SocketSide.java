package org.usarsim.wss.hub;

import java.net.InetAddress;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.hub.tcp.Descriptors;
import org.usarsim.wss.hub.tcp.KeepAlive;
import org.usarsim.wss.hub.tcp.SocketRules;

/** What the control side and the link side answer alike ({@link SocketRules}). */
abstract class SocketSide implements SocketRules {

    /** Every WARNING a client can cause goes through it (docs/reliability.md). */
    final WarningLimiter warnings;
    private final KeepAlive keepAlive;
    private final Descriptors descriptors;

    SocketSide(WarningLimiter warnings, KeepAlive keepAlive, Descriptors descriptors) {
        this.warnings = warnings;
        this.keepAlive = keepAlive;
        this.descriptors = descriptors;
    }

    @Override
    public KeepAlive keepAlive() {
        return keepAlive;
    }

    @Override
    public Descriptors descriptors() {
        return descriptors;
    }

    @Override
    public void say(Logger log, String kind, InetAddress client, String message) {
        warnings.say(log, Level.INFO, kind, client, message);
    }

    @Override
    public void note(Logger log, String category, InetAddress client, String message) {
        warnings.info(log, category, client, message);
    }

    @Override
    public void warn(Logger log, String category, InetAddress client, String message, Throwable cause) {
        if (cause == null) {
            warnings.warn(log, category, client, message);
        } else {
            warnings.warn(log, category, client, message, cause);
        }
    }
}
