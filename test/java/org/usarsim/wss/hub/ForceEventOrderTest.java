package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.WssEventListener;

/**
 * Two operators force the same pair at once (the control port and the window's menu): the event
 * log's FORCED and RELEASED lines come in the order the pair was forced, so its last line for the
 * pair is the state the pair is in.
 */
class ForceEventOrderTest {

    private static final RobotPair PAIR = RobotPair.of("R1", "R2");

    @TempDir
    Path dir;

    @Test
    void theEventLogsLastLineForAPairForcedFromTwoPlacesAtOnceIsItsState() throws Exception {
        try (TestHub server = new TestHub(new ScriptedModel(), true, 65536); TestRobot operator = server.robot()) {
            Hub hub = server.hub;
            AtomicReference<Thread> window = new AtomicReference<>();
            // Between the control port's FORCE Up and its event, the window forces the pair down
            // (the listeners before the event log may take their time: a slow console, say).
            hub.addListener(new WssEventListener() {
                @Override
                public void pairForced(String first, String second, boolean up) {
                    if (!up || window.get() != null) {
                        return;
                    }
                    Thread other = new Thread(() -> hub.force("R2", "R1", Force.DOWN), "window's force menu");
                    window.set(other);
                    other.start();
                    Wait.settle("the window's force done, or waiting for this one", () -> other.getState() == Thread.State.TERMINATED
                            || other.getState() == Thread.State.BLOCKED ? 1 : 0, done -> done == 1);
                }
            });
            CsvEventLog log = CsvEventLog.create(dir);
            hub.addListener(log);

            assertEquals("FORCEREPLY {Status OK}", operator.ask("FORCE {Robot R1} {Peer R2} {State Up}"));
            Wait.until("the window forced the pair", () -> window.get() != null);
            window.get().join(5000);
            assertEquals(Force.DOWN, hub.forced(PAIR), "the window's force came last");
            log.close();

            List<String> lines = Files.readAllLines(log.file()).stream().filter(line -> line.startsWith("FORCED"))
                    .map(line -> line.replaceFirst(",\\d\\d:\\d\\d:\\d\\d\\.\\d{3}", "")).toList();
            assertEquals(List.of("FORCED,R1,R2,UP", "FORCED,R1,R2,DOWN"), lines, "in the order the pair was forced");
        }
    }

    @Test
    void aConnectionAForceClosesEndsInTheEventLogAfterTheForce() throws Exception {
        try (TestHub server = new TestHub(new ScriptedModel(), true, 65536); TestRobot a = server.robot();
                TestRobot b = server.robot()) {
            Hub hub = server.hub;
            // A listener before the event log takes its time over the force (a slow console, say),
            // long enough for the closed connection's thread to end.
            hub.addListener(new WssEventListener() {
                @Override
                public void pairForced(String first, String second, boolean up) {
                    Wait.settle("the forced connection's thread ended", ForceEventOrderTest::linkThreads, threads -> threads == 0);
                }
            });
            CsvEventLog log = CsvEventLog.create(dir);
            hub.addListener(log);
            a.init("Slow1");
            ServerSocket accepting = b.initAccepting("Slow2");
            try (Socket out = a.connect(a.dns("Slow2", 0)); Socket in = accepting.accept()) {
                Wait.until("the connection established", () -> hub.snapshot().links().size() == 1);
                hub.force("Slow1", "Slow2", Force.DOWN);
                Wait.until("the connection's end in the event log", () -> lines(log).stream().anyMatch(l -> l.startsWith("CON_TERMINATED")));
            }
            log.close();
            assertEquals(List.of("CON_ESTABLISHED", "FORCED", "CON_TERMINATED"),
                    lines(log).stream().map(line -> line.split(",")[0]).filter(type -> type.startsWith("CON") || type.startsWith("FORCED")).toList(),
                    "the force closed the connection: its end comes after it");
        }
    }

    @Test
    void aListenerThatChangesTheHubFromItsEventHearsTheChangeAfterTheEventsBeforeIt() throws Exception {
        try (TestHub server = new TestHub(new ScriptedModel(), true, 65536); TestRobot a = server.robot();
                TestRobot b = server.robot()) {
            Hub hub = server.hub;
            a.init("Near1");
            b.initAccepting("Near2");
            a.dns("Near2", 0); // a listening port: forcing the pair down stops it, a second event of the force
            List<String> heard = new CopyOnWriteArrayList<>();
            hub.addListener(new WssEventListener() {
                @Override
                public void pairForced(String first, String second, boolean up) {
                    heard.add("forced " + first + " - " + second);
                    if (first.equals("Near1")) {
                        hub.force("Far1", "Far2", Force.UP); // from the event's own thread
                    }
                }

                @Override
                public void portListening(String from, String to, int targetPort, int wssPort, boolean listening) {
                    heard.add("listening " + from + " -> " + to + " " + listening);
                }
            });
            hub.force("Near1", "Near2", Force.DOWN);
            assertEquals(List.of("forced Near1 - Near2", "listening Near1 -> Near2 false", "forced Far1 - Far2"), heard,
                    "the nested force's event after the rest of the first force's");
        }
    }

    /** The threads of this test's links but the caller (a link's thread may be the one delivering the force). */
    private static long linkThreads() {
        return Thread.getAllStackTraces().keySet().stream().filter(thread -> thread.getName().startsWith("link Slow1 -> Slow2:")
                && thread.isAlive() && thread != Thread.currentThread()).count();
    }

    private static List<String> lines(CsvEventLog log) {
        try {
            return Files.readAllLines(log.file());
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }
}
