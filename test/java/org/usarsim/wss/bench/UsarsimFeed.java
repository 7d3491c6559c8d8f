package org.usarsim.wss.bench;

import java.io.IOException;
import java.util.List;
import java.util.Random;
import org.usarsim.wss.model.simulator.FakeSimulator;

/** The peer: A and B in a USARSim position socket of this JVM ({@link FakeSimulator}); a move's publish is the moment B's place changes. */
final class UsarsimFeed implements PositionFeed {

    private final FakeSimulator simulator;
    private final int pollMs;
    private final Random random = new Random(23);

    UsarsimFeed(int pollMs) throws IOException {
        this.pollMs = pollMs;
        simulator = new FakeSimulator();
        simulator.place("A", 0, 0, 0);
        simulator.place("B", 10, 0, 0);
    }

    @Override
    public String label() {
        return "USARSim socket";
    }

    @Override
    public List<String> wssSettings() {
        return List.of("positions=usarsim", "usarsim.host=127.0.0.1", "usarsim.port=" + simulator.port());
    }

    @Override
    public long move(double x) throws InterruptedException {
        PositionFeed.pause(random, pollMs);
        long now = System.nanoTime();
        simulator.place("B", x, 0, 0);
        return now;
    }

    @Override
    public void close() throws IOException {
        simulator.close();
    }
}
