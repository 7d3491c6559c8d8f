package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The CSV event log, fed by a real hub. */
class EventLogTest {

    @TempDir
    Path dir;

    /** Every line but DATA_SENT is flushed at once, so the file can be read while the log is open. */
    private static boolean logged(CsvEventLog log, String text) {
        try {
            return Files.readString(log.file()).contains(text);
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    @Test
    void writesOneCsvLinePerEvent() throws Exception {
        CsvEventLog log = CsvEventLog.create(dir);
        assertTrue(log.file().getFileName().toString().matches("log-\\d{4}\\.\\d\\d\\.\\d\\d-\\d\\d\\.\\d\\d\\.\\d\\d\\.\\d{3}\\.txt"),
                log.file().toString());
        ScriptedModel model = new ScriptedModel();
        try (TestHub server = new TestHub(model, true, 65536)) {
            server.hub.addListener(log);
            try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot()) {
                ServerSocket r1Accepts = r1.listen();
                int r1Port = r1Accepts.getLocalPort();
                r1.init("R1", r1Port, 7777);
                r2.init("R2", 6000);
                try (Socket out = r2.connect(r2.dns("R1", 0)); Socket in = r1Accepts.accept()) {
                    out.getOutputStream().write("12345".getBytes(StandardCharsets.UTF_8));
                    assertEquals("12345", Sockets.readExactly(in.getInputStream(), 5));
                }
                Wait.until("the link is closed", () -> Sockets.linkThreads() == 0);
                r1.control.close();
                Wait.until("R1's deregistration is logged", () -> logged(log, "DEREGISTERED,"));
                // The events a model reports, through the listener the hub gave it.
                model.events().connectionOutOfRange("R1", "R2", -95.5, 120.25);
                model.events().connectionInRange("R1", "R2");
                model.events().robotOutOfBattery("R2");
                log.close();

                String time = "\\d\\d:\\d\\d:\\d\\d\\.\\d{3}";
                List<String> lines = Files.readAllLines(log.file());
                String[] expected = {
                    "REGISTERED," + time + ",R1,127\\.0\\.0\\.1," + r1Port + ":7777",
                    "REGISTERED," + time + ",R2,127\\.0\\.0\\.1,6000",
                    "CON_ESTABLISHED," + time + ",R2,R1," + r1Port,
                    "DATA_SENT," + time + ",R2,R1,5",
                    "CON_TERMINATED," + time + ",R2,R1," + r1Port,
                    "DEREGISTERED," + time + ",R1",
                    "OUT_OF_RANGE," + time + ",R1,R2,-95.5,120.25",
                    "IN_RANGE," + time + ",R1,R2",
                    "OUT_OF_BATTERY," + time + ",R2",
                };
                assertEquals(expected.length, lines.size(), String.join("\n", lines));
                for (int i = 0; i < expected.length; i++) {
                    assertTrue(lines.get(i).matches(expected[i]), lines.get(i) + " !~ " + expected[i]);
                }
            }
        }
    }
}
