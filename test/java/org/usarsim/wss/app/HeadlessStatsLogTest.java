package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.hub.TestRobot;

/**
 * wss.statsInterval in a real headless server process run by Main (runHeadless starting
 * StatsLog), with real robots exchanging data: the table in the log with the bytes sent, and no
 * table at all with the default 0.
 */
@Tag("slow")
class HeadlessStatsLogTest {

    private static final String TITLE = "INFO link statistics, 1 pair";

    @TempDir
    Path dir;

    @Test
    void everySecondTheLogShowsTheTableWithTheBytesSentAndNeverWithTheDefault() throws Exception {
        ServerProcess quiet = ServerProcess.start("--headless", "--config", ServerProcess.config(dir, Map.of()).toString());
        ServerProcess counting = null;
        try {
            int quietPort = Integer.parseInt(quiet.awaitListening().group(1));
            counting = ServerProcess.start("--headless", "--config",
                    ServerProcess.config(dir, Map.of("wss.statsInterval", "1")).toString());
            int countingPort = Integer.parseInt(counting.awaitListening().group(1));
            try (Exchange onQuiet = new Exchange(quietPort); Exchange onCounting = new Exchange(countingPort)) {
                // Robot A, B, state, dBm (Noop: 0), m (no positions), bytes R1>R2, R2>R1, B/s both ways,
                // connections, breaks, resumes, up %, last close (none: the connection is open).
                String expected = "R1 - R2 +up +0 +- +12345 +678 +\\d+ +\\d+ +1 +0 +0 +100\\.0 +-";
                String row = "";
                for (int table = 0; table < 10 && !row.matches(expected); table++) {
                    counting.awaitLine(line -> line.endsWith(TITLE));
                    assertEquals(StatsLog.HEADER, counting.awaitLine(line -> true));
                    row = counting.awaitLine(line -> true);
                }
                assertTrue(row.matches(expected), row);
                // The quiet server ran longer than the counting one took for its tables, its pair busy too.
                counting.awaitLine(line -> line.endsWith(TITLE));
            }
            quiet.sigterm();
            counting.sigterm();
            assertEquals(Main.OK, quiet.awaitExit(), quiet.stderr());
            assertEquals(Main.OK, counting.awaitExit(), counting.stderr());
            List<String> quietLog = quiet.stdoutSoFar();
            assertTrue(quietLog.stream().anyMatch(line -> line.contains("INFO connection established R1 -> R2:")),
                    quietLog.toString());
            assertTrue(quietLog.stream().noneMatch(line -> line.contains("link statistics")), quietLog.toString());
        } finally {
            quiet.kill();
            if (counting != null) {
                counting.kill();
            }
        }
    }

    /** R1 and R2 registered, R1 connected to R2 through the WSS: 12345 bytes to R2, 678 back. */
    private static final class Exchange implements AutoCloseable {

        private final TestRobot r1;
        private final TestRobot r2;
        private final Socket out;
        private final Socket in;

        Exchange(int port) throws Exception {
            r1 = new TestRobot(port, "127.0.0.1");
            r2 = new TestRobot(port, "127.0.0.1");
            r1.init("R1");
            ServerSocket r2Accepts = r2.initAccepting("R2");
            out = r1.connect(r1.dns("R2", 0));
            in = r2Accepts.accept();
            out.getOutputStream().write(new byte[12345]);
            assertEquals(12345, in.getInputStream().readNBytes(12345).length);
            in.getOutputStream().write(new byte[678]);
            assertEquals(678, out.getInputStream().readNBytes(678).length);
        }

        @Override
        public void close() throws Exception {
            out.close();
            in.close();
            r1.close();
            r2.close();
        }
    }
}
