package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.ConnectException;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.hub.TestRobot;

/**
 * Forcing from the properties file (wss.force.down, wss.force.up) and the operator command, in a
 * real headless server process run by Main, with real robots.
 */
@Tag("slow")
class HeadlessForceTest {

    @TempDir
    Path dir;

    @Test
    void pairsForcedInThePropertiesFileAreForcedFromTheStartAndAnOperatorReleasesThem() throws Exception {
        Path logs = dir.resolve("logs");
        ServerProcess server = ServerProcess.start("--headless", "--config", ServerProcess.config(dir, Map.of(
                "wss.force.down", "R2:R1", "wss.force.up", "R1:R3", "wss.eventLog", "true",
                "wss.eventLogDir", logs.toString())).toString());
        try {
            int port = Integer.parseInt(server.awaitListening().group(1));
            List<String> start = server.stdoutSoFar();
            assertTrue(start.stream().anyMatch(line -> line.endsWith("INFO forced R1 - R2 down")), start.toString());
            assertTrue(start.stream().anyMatch(line -> line.endsWith("INFO forced R1 - R3 up")), start.toString());
            try (TestRobot r1 = new TestRobot(port, "127.0.0.1"); TestRobot r2 = new TestRobot(port, "127.0.0.2");
                    TestRobot operator = new TestRobot(port, "127.0.0.1"); TestRobot foreign = new TestRobot(port, "127.0.0.3")) {
                r1.init("R1");
                ServerSocket r2Accepts = r2.initAccepting("R2");
                int toR2 = r1.dns("R2", 0);
                assertThrows(ConnectException.class, () -> r1.connect(toR2).close(), "R1 - R2 forced down by the file");

                assertEquals("ERROR {Reason Not.An.Operator.Address}", foreign.ask("FORCE {Robot R1} {Peer R2} {State Model}"));
                assertThrows(ConnectException.class, () -> r1.connect(toR2).close(), "still forced down");

                assertEquals("FORCEREPLY {Status OK}", operator.ask("FORCE {Robot R1} {Peer R2} {State Model}"));
                try (Socket out = r1.connect(toR2); Socket in = r2Accepts.accept()) {
                    out.getOutputStream().write('!');
                    assertEquals('!', in.getInputStream().read(), "released: NoopPropagationModel allows every pair");
                }
                server.awaitLine(line -> line.endsWith("INFO released R1 - R2 to the model"));
            }
            server.sigterm();
            assertEquals(Main.OK, server.awaitExit(), server.stderr());
        } finally {
            server.kill();
        }
        List<String> events = eventLines(logs);
        assertEquals(List.of("FORCED,R1,R2,DOWN", "FORCED,R1,R3,UP", "RELEASED,R1,R2"), events.stream()
                .filter(line -> line.startsWith("FORCED") || line.startsWith("RELEASED")).toList(), events.toString());
    }

    /** The lines of the one event log file in the folder, without their time. */
    private static List<String> eventLines(Path logs) throws IOException {
        try (Stream<Path> files = Files.list(logs)) {
            List<Path> all = files.toList();
            assertEquals(1, all.size(), all.toString());
            return Files.readAllLines(all.get(0)).stream().map(line -> line.replaceFirst(",[0-9:.]+", "")).toList();
        }
    }
}
