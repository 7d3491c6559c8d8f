package org.usarsim.wss.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.ConnectException;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.hub.TestHub;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.hub.Wait;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.simulator.DataConnection;
import org.usarsim.wss.protocol.Replies;

/**
 * The replay behind a real hub, robots on real sockets: GETSS answers the recorded strengths, a
 * DNS'd port refuses while the recording breaks the pair and listens again when it resumes, a
 * robot the recording never had is kicked. The replay's clock is the test's, so each poll comes
 * when the test says.
 */
class ReplayOverSocketsTest {

    private static final long MS = 1_000_000L;

    @TempDir
    Path dir;

    @Test
    void robotsLiveThroughTheRecordedNetwork() throws Exception {
        Path file = new Recordings()
                .robot("Alpha", 0, 0, false).robot("Bravo", 10, 0, false)
                .pair("Alpha", "Bravo", -60.25, true).poll(200)
                .robot("Alpha", 0, 0, false).robot("Bravo", 80, 0, false)
                .pair("Alpha", "Bravo", -95.5, false).poll(400)
                .robot("Alpha", 0, 0, false).robot("Bravo", 12, 0, false)
                .pair("Alpha", "Bravo", -61.125, true).poll(600)
                .write(dir.resolve("run.rec"), 700);
        AtomicLong now = new AtomicLong(0);
        ReplayPropagationModel model = new ReplayPropagationModel(now::get);
        model.configure(new ModelSettings(Map.of("replay.file", file.toString())));
        try (TestHub server = new TestHub(model, true, 65536);
                TestRobot alpha = server.robot();
                TestRobot bravo = server.robot();
                TestRobot stranger = server.robot()) {
            alpha.initAccepting("Alpha");
            ServerSocket bravoAccepts = bravo.initAccepting("Bravo");
            stranger.send("INIT {Robot Stranger}\r\n");
            assertThrows(IOException.class, () -> {
                while (true) {
                    stranger.readLine(); // its INITREPLY, then the end of the connection the kick closes
                }
            }, "a robot the recording never had is kicked");
            Wait.until("Stranger deregistered", () -> server.hub.getListOfRegisteredRobots().equals(List.of("Alpha", "Bravo")));

            assertEquals(Replies.signal("Bravo", -60.25), alpha.ask("GETSS {Robot Bravo}"));
            assertEquals(Replies.signal("Alpha", -60.25), bravo.ask("GETSS {Robot Alpha}"));
            int port = alpha.dns("Bravo", 0);
            DataConnection connection = DataConnection.open(alpha, port, bravoAccepts);
            connection.assertPasses("as recorded at 00:00.2");

            now.addAndGet(400 * MS);
            assertThrows(IOException.class, () -> connection.source().getInputStream().read(),
                    "the connection cut (reset, as a break resets: docs/protocol.md 4.3) by the recorded break");
            assertTrue(refuses(alpha, port), "the port refuses while the recording breaks the pair");
            assertEquals(Replies.signal("Bravo", -95.5), alpha.ask("GETSS {Robot Bravo}"));
            assertEquals(port, alpha.dns("Bravo", 0), "its number kept");

            now.addAndGet(200 * MS);
            DataConnection[] again = new DataConnection[1];
            Wait.until("the port listens again once the recording resumes the pair",
                    () -> (again[0] = openIfListening(alpha, port, bravoAccepts)) != null);
            assertEquals(Replies.signal("Bravo", -61.125), alpha.ask("GETSS {Robot Bravo}"));
            again[0].assertPasses("resumed");
            again[0].close();
            connection.close();
        }
    }

    /** A connection through the port, or null while it refuses. */
    private static DataConnection openIfListening(TestRobot robot, int port, ServerSocket targetAccepts) {
        try {
            return DataConnection.open(robot, port, targetAccepts);
        } catch (ConnectException e) {
            return null;
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    /** Whether a connect to the port is refused. */
    private static boolean refuses(TestRobot robot, int port) {
        try (Socket socket = robot.connect(port)) {
            return false;
        } catch (ConnectException e) {
            return true;
        } catch (IOException e) {
            return false;
        }
    }
}
