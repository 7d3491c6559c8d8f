package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.LogCapture;
import org.usarsim.wss.net.LogLimiter;
import org.usarsim.wss.protocol.Arguments;

/**
 * Issue 27: robots from 100 addresses (127.0.0.2 to 127.0.0.101) register and leave in a loop
 * with the longest names allowed and a port list of 5,000 ports, each first trying a name of
 * 60,000 characters. The names over 256 characters are refused with their reason and log nothing;
 * the registered and deregistered lines are limited per kind, each cut at 1,000 characters, and
 * the server answers throughout. The log's bytes are counted (the messages, UTF-8).
 */
@Tag("slow")
class RegistrationFloodTest {

    private static final int ADDRESSES = 100;
    private static final int CYCLES = 6;

    @Test
    void registrationsWithLongNamesFrom100AddressesWriteABoundedLog() throws Exception {
        StringBuilder ports = new StringBuilder();
        for (int port = 10_000; port < 15_000; port++) {
            ports.append(ports.length() == 0 ? "" : ",").append(port);
        }
        long unlimited = 0;
        try (LogCapture log = LogCapture.of("org.usarsim.wss", Level.INFO)) {
            try (TestHub server = new TestHub()) {
                for (int cycle = 0; cycle < CYCLES; cycle++) {
                    for (int a = 0; a < ADDRESSES; a++) {
                        String address = "127.0.0." + (2 + a);
                        try (TestRobot robot = server.robotAt(address)) {
                            assertEquals("ERROR {Reason Robot.Name.Must.Be.At.Most.256.Characters}",
                                    robot.ask("INIT {Robot " + "N".repeat(60_000) + "} {Port 5000}"));
                            String suffix = "-" + a + "-" + cycle;
                            String name = "R".repeat(Arguments.MAX_NAME - suffix.length()) + suffix;
                            assertEquals("INITREPLY {Status OK}", robot.ask("INIT {Robot " + name + "} {Port " + ports + "}"));
                            // What the two lines would have been, whole and unlimited.
                            unlimited += ("registered " + name + " from " + address + " accepting on [" + ports.toString().replace(",", ", ")
                                    + "]").length() + ("deregistered " + name).length();
                        }
                    }
                }
                Wait.until("every robot deregistered", () -> server.hub.snapshot().robots().isEmpty());
                try (TestRobot last = server.robot()) {
                    last.init("Last");
                    assertEquals("SS {Robot Last} {Strength INF} {Error SS.To.Self}", last.ask("GETSS {Robot Last}"));
                }
                Wait.until("Last deregistered", () -> server.hub.snapshot().robots().isEmpty());
            }
            long registered = log.count(Level.INFO, "registered R");
            long deregistered = log.count(Level.INFO, "deregistered R");
            assertEquals(WarningLimiter.SAID_ALL_FIRST, registered - deregistered, "registered lines: the kind's limit from all addresses");
            assertEquals(WarningLimiter.SAID_ALL_FIRST, deregistered, "deregistered lines: the kind's limit");
            long bytes = 0;
            int longest = 0;
            for (LogRecord record : log.records) {
                String message = record.getMessage();
                bytes += message.getBytes(StandardCharsets.UTF_8).length;
                longest = Math.max(longest, message.length());
            }
            assertTrue(longest <= LogLimiter.MAX_MESSAGE + 40, "every line cut: the longest has " + longest + " characters");
            List<String> summaries = log.messages(Level.INFO).stream().filter(m -> m.contains(" more like this from ")).toList();
            int more = ADDRESSES * CYCLES + 1 - WarningLimiter.SAID_ALL_FIRST; // and Last
            assertTrue(summaries.stream().anyMatch(m -> m.startsWith("registered robots: " + more + " more like this from any address")),
                    summaries.toString());
            assertTrue(summaries.stream().anyMatch(m -> m.startsWith("deregistered robots: " + more + " more like this from any address")),
                    summaries.toString());
            long bound = 4L * (WarningLimiter.SAID_ALL_FIRST + 1) * (LogLimiter.MAX_MESSAGE + 40);
            assertTrue(bytes <= bound, bytes + " bytes of log for " + ADDRESSES * CYCLES + " registrations, more than " + bound);
            System.out.printf("registration flood: %d registrations from %d addresses, %d log records, %d bytes of messages"
                    + " (unlimited and uncut: %d), longest line %d characters%n", ADDRESSES * CYCLES, ADDRESSES, log.records.size(), bytes,
                    unlimited, longest);
        }
    }
}
