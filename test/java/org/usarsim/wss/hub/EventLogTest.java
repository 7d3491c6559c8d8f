package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStream;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.time.ZoneId;
import java.time.ZonedDateTime;
import java.time.format.DateTimeFormatter;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.usarsim.wss.StuckWriter;
import org.usarsim.wss.hub.core.HubClock;
import org.usarsim.wss.model.WssEventListener;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The CSV event log, fed by a real hub. */
class EventLogTest {

    @TempDir
    Path dir;

    /** The writer flushes whenever it has caught up, so the file can be read while the log is open. */
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

    /** The file's name and every line's time of day are the hub's clock's (moved by hand here), not the machine's. */
    @Test
    void theFilesNameAndEveryLinesTimeComeFromTheHubsClock() throws Exception {
        ManualHubClock clock = new ManualHubClock();
        ZonedDateTime start = Instant.ofEpochMilli(clock.wallMillis()).atZone(ZoneId.systemDefault());
        CsvEventLog log = CsvEventLog.create(dir, clock);
        assertEquals("log-" + DateTimeFormatter.ofPattern("yyyy.MM.dd-HH.mm.ss.SSS").format(start) + ".txt",
                log.file().getFileName().toString());
        log.robotRegistered("R1", "127.0.0.1", List.of(5000));
        clock.advance(Duration.ofMillis(1_500));
        log.dataSent("R1", "R2", 10);
        log.close();
        DateTimeFormatter time = DateTimeFormatter.ofPattern("HH:mm:ss.SSS");
        assertEquals(List.of("REGISTERED," + time.format(start) + ",R1,127.0.0.1,5000",
                "DATA_SENT," + time.format(start.plus(Duration.ofMillis(1_500))) + ",R1,R2,10"), Files.readAllLines(log.file()));
    }

    /** Counts the events the CSV log writes a line for. */
    private static final class EventCount implements WssEventListener {
        final AtomicLong count = new AtomicLong();
        final AtomicLong terminated = new AtomicLong();

        @Override
        public void robotRegistered(String robot, String address, List<Integer> ports) {
            count.incrementAndGet();
        }

        @Override
        public void robotDeregistered(String robot) {
            count.incrementAndGet();
        }

        @Override
        public void connectionEstablished(String from, String to, int targetPort) {
            count.incrementAndGet();
        }

        @Override
        public void connectionTerminated(String from, String to, int targetPort) {
            count.incrementAndGet();
            terminated.incrementAndGet();
        }

        @Override
        public void dataSent(String from, String to, int bytes) {
            count.incrementAndGet();
        }
    }

    @Test
    void aFixedUdpPortsCountsAreOneLineADirectionSayingItsPort() throws Exception {
        CsvEventLog log = CsvEventLog.create(dir);
        log.udpCounted("Scout", "Base", 17400, 1200, 1_680_000, 3, 2, 14);
        log.udpCounted("Scout", "Base", 17401, 5, 50, 0, 0, 0);
        log.close();
        List<String> lines = Files.readAllLines(log.file());
        assertEquals(2, lines.size(), lines.toString());
        assertTrue(lines.get(0).matches("UDP,\\d\\d:\\d\\d:\\d\\d\\.\\d{3},Scout,Base,17400,1200,1680000,3,2,14"), lines.get(0));
        assertTrue(lines.get(1).matches("UDP,\\d\\d:\\d\\d:\\d\\d\\.\\d{3},Scout,Base,17401,5,50,0,0,0"), lines.get(1));
    }

    @Test
    void aSettingOfTheRandomDrawsIsOneLine() throws Exception {
        CsvEventLog log = CsvEventLog.create(dir);
        log.setting("wss.seed", "42");
        log.close();
        List<String> lines = Files.readAllLines(log.file());
        assertEquals(1, lines.size(), lines.toString());
        assertTrue(lines.get(0).matches("SETTING,\\d\\d:\\d\\d:\\d\\d\\.\\d{3},wss.seed,42"), lines.get(0));
    }

    @Test
    void aStuckWriterNeverHoldsUpTheLinksAndTheDroppedEventsAreCounted() throws Exception {
        StuckWriter writer = new StuckWriter();
        CsvEventLog log = new CsvEventLog(dir.resolve("stuck.txt"), writer, 8, HubClock.SYSTEM);
        EventCount events = new EventCount();
        try (TestHub server = new TestHub(new ScriptedModel(), true, 1024)) {
            server.hub.addListener(log);
            server.hub.addListener(events);
            try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot()) {
                ServerSocket r1Accepts = r1.listen();
                r1.init("R1", r1Accepts.getLocalPort());
                r2.init("R2", 6000);
                assertTrue(writer.stuck.await(5, TimeUnit.SECONDS), "the writer is writing its first batch");
                // 256 chunks of 1 KiB at least, each an event, go through while the writer cannot write one.
                byte[] data = Sockets.randomBytes(256 * 1024, 11);
                try (Socket out = r2.connect(r2.dns("R1", 0)); Socket in = r1Accepts.accept()) {
                    out.getOutputStream().write(data);
                    out.shutdownOutput();
                    InputStream received = in.getInputStream();
                    assertArrayEquals(data, received.readAllBytes());
                }
                Wait.until("the link's end is fired", () -> events.terminated.get() == 1);
                assertEquals("", writer.text.toString(), "the writer was stuck all along");
                long fired = events.count.get();
                assertTrue(fired > 256, "events fired: " + fired);

                writer.release.countDown();
                log.close();
                assertTrue(writer.closed, "close waits until the file is closed");
                List<String> lines = writer.lines();
                long written = lines.stream().filter(line -> !line.startsWith("DROPPED,")).count();
                long dropped = lines.stream().filter(line -> line.startsWith("DROPPED,"))
                        .peek(line -> assertTrue(line.matches("DROPPED,\\d\\d:\\d\\d:\\d\\d\\.\\d{3},[1-9]\\d*"), line))
                        .mapToLong(line -> Long.parseLong(line.substring(line.lastIndexOf(',') + 1))).sum();
                assertTrue(dropped > 0, String.join("\n", lines));
                assertEquals(fired, written + dropped, "every event is either written or counted as dropped:\n" + String.join("\n", lines));
                assertTrue(lines.get(0).startsWith("REGISTERED,"), lines.get(0));
            }
        }
    }

    @Test
    void closeWritesEverythingQueuedAndNothingAfter() throws Exception {
        StuckWriter writer = new StuckWriter();
        CsvEventLog log = new CsvEventLog(dir.resolve("queued.txt"), writer, 1000, HubClock.SYSTEM);
        log.robotRegistered("R1", "127.0.0.1", List.of(5000, 5001));
        assertTrue(writer.stuck.await(5, TimeUnit.SECONDS), "the writer is writing the first line");
        for (int i = 1; i <= 500; i++) {
            log.dataSent("R1", "R2", i);
        }
        writer.release.countDown();
        log.close();
        log.dataSent("R1", "R2", 501);
        log.close();

        List<String> lines = writer.lines();
        assertTrue(writer.closed);
        assertEquals(501, lines.size(), String.join("\n", lines));
        assertTrue(lines.get(0).matches("REGISTERED,\\d\\d:\\d\\d:\\d\\d\\.\\d{3},R1,127\\.0\\.0\\.1,5000:5001"), lines.get(0));
        for (int i = 1; i <= 500; i++) {
            assertTrue(lines.get(i).matches("DATA_SENT,\\d\\d:\\d\\d:\\d\\d\\.\\d{3},R1,R2," + i), lines.get(i));
        }
        assertFalse(lines.stream().anyMatch(line -> line.startsWith("DROPPED,")));
    }

    @Test
    void aFieldWithACommaAQuoteOrALineEndIsQuotedAsRfc4180Says() throws Exception {
        StuckWriter writer = new StuckWriter();
        writer.release.countDown();
        CsvEventLog log = new CsvEventLog(dir.resolve("quoted.txt"), writer, 100, HubClock.SYSTEM);
        log.robotRegistered("E,1", "127.0.0.1", List.of(5000));
        log.connectionEstablished("say \"hi\"", "line\rend", 5000);
        log.pairForced("A\nB", "plain", true);
        log.dataSent("a,b", "E\u001B", 65536);
        log.close();
        String text = writer.text.toString();
        List<String> lines = List.of(text.split(System.lineSeparator()));
        assertTrue(lines.get(0).matches("REGISTERED,[\\d:.]+,\"E,1\",127\\.0\\.0\\.1,5000"), lines.get(0));
        assertTrue(lines.get(1).matches("CON_ESTABLISHED,[\\d:.]+,\"say \"\"hi\"\"\",line\\\\u000Dend,5000"), lines.get(1));
        assertTrue(text.contains(",\"A\nB\",plain,UP" + System.lineSeparator()), text);
        assertTrue(text.matches("(?s).*" + System.lineSeparator() + "DATA_SENT,\\d\\d:\\d\\d:\\d\\d\\.\\d{3},\"a,b\",E\\\\u001B,65536"
                + System.lineSeparator()), "a DATA_SENT's names as every line's: " + text);
        StringBuilder plain = new StringBuilder();
        CsvEventLog.appendField(plain, "R1");
        assertEquals("R1", plain.toString(), "a name that needs nothing is written as it is");
        StringBuilder obeyed = new StringBuilder();
        CsvEventLog.appendField(obeyed, "E\u001B[2J\u202Eevil\u0085");
        assertEquals("E\\u001B[2J\\u202Eevil\\u0085", obeyed.toString(), "ESC, a bidi override and C1 escaped as in the log");
    }

    /** Issue 36: a backslash of a name is itself escaped, so that a name with ESC and one with the text of its escape differ. */
    @Test
    void aBackslashIsDoubledSoNoTwoNamesAreWrittenAlike() {
        StringBuilder escape = new StringBuilder();
        CsvEventLog.appendField(escape, "a\u001Bb");
        StringBuilder text = new StringBuilder();
        CsvEventLog.appendField(text, "a\\u001Bb");
        assertEquals("a\\u001Bb", escape.toString(), "ESC as the log writes it");
        assertEquals("a\\\\u001Bb", text.toString(), "a backslash, then text");
        StringBuilder both = new StringBuilder();
        CsvEventLog.appendField(both, "\\,\u001B");
        assertEquals("\"\\\\,\\u001B\"", both.toString(), "quoted as before, the backslash doubled inside");
    }
}
