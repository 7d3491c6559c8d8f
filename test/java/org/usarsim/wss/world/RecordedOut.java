package org.usarsim.wss.world;

import java.util.ArrayList;
import java.util.List;
import java.util.logging.Level;

/** What a rosbridge session sent (its frames) and logged ("LEVEL message"), kept for a test. */
final class RecordedOut implements RosbridgeSession.Out {

    final List<String> sent = new ArrayList<>();
    final List<String> logged = new ArrayList<>();

    @Override
    public void send(String frame) {
        sent.add(frame);
    }

    @Override
    public void log(Level level, String kind, String message) {
        logged.add(level + " " + message);
    }
}
