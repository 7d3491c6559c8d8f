package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.net.InetAddress;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.logging.Level;
import java.util.logging.Logger;
import java.util.stream.Collectors;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.LogCapture;
import org.usarsim.wss.hub.core.HubClock;
import org.usarsim.wss.net.LogLimiter;

/** The limit on warnings one client can cause, with a clock and a timer moved by hand. */
@Tag("slow")
class WarningLimiterTest {

    private static final String LOGGER = "org.usarsim.wss.hub.WarningLimiterTest";
    private static final long MINUTE = TimeUnit.SECONDS.toNanos(60);

    private final Logger log = Logger.getLogger(LOGGER);
    private final LogCapture capture = LogCapture.of(LOGGER, Level.ALL);
    private final ManualHubClock clock = new ManualHubClock(1_000_000_000L, 0);
    /** What the limiter asked the timer to run, and when (on the test's clock). */
    private final List<Long> dueAt = new ArrayList<>();
    private final List<Runnable> due = new ArrayList<>();
    private boolean timerStopped;
    private final WarningLimiter limiter = new WarningLimiter(5, LogLimiter.ALL_FIRST, MINUTE, clock, new LogLimiter.Timer() {
        @Override
        public void after(long delayNs, Runnable task) {
            dueAt.add(clock.nanoTime() + delayNs);
            due.add(task);
        }

        @Override
        public void stop() {
            timerStopped = true;
        }
    });

    @AfterEach
    void detach() {
        capture.close();
    }

    private static InetAddress address(String text) throws Exception {
        return InetAddress.getByName(text);
    }

    private void warn(String kind, String source, String message) throws Exception {
        limiter.warn(log, kind, address(source), message);
    }

    /** Moves the clock to the first task's time (unless it is past it: a late timer) and runs it. */
    private void runTimer() {
        long at = dueAt.remove(0);
        if (at - clock.nanoTime() > 0) {
            clock.advanceTo(at);
        }
        due.remove(0).run();
    }

    @Test
    void theFirstFiveAreWrittenTheRestCountedAndSaidInOneLineAtTheIntervalsEnd() throws Exception {
        for (int i = 0; i < 12; i++) {
            warn("refused connections", "127.0.0.2", "refused #" + i);
            clock.advance(Duration.ofNanos(TimeUnit.SECONDS.toNanos(1)));
        }
        assertEquals(List.of("refused #0", "refused #1", "refused #2", "refused #3", "refused #4"), capture.messages(Level.WARNING));
        assertEquals(List.of(1_000_000_000L + MINUTE), dueAt, "one summary, due when the interval that began with the first ends");

        runTimer();
        assertEquals("refused connections: 7 more like this from 127.0.0.2 in the last 60 s",
                capture.messages(Level.WARNING).get(5));
        assertEquals(6, capture.records.size());

        warn("refused connections", "127.0.0.2", "refused again");
        assertEquals("refused again", capture.messages(Level.WARNING).get(6), "a new interval writes again");
    }

    @Test
    void eachKindAndEachSourceHasItsOwnLimit() throws Exception {
        for (int i = 0; i < 8; i++) {
            warn("refused connections", "127.0.0.2", "A" + i);
            warn("refused connections", "127.0.0.3", "B" + i);
            warn("over-long lines", "127.0.0.2", "C" + i);
        }
        List<String> written = capture.messages(Level.WARNING);
        assertEquals(15, written.size(), written.toString());
        for (String prefix : List.of("A", "B", "C")) {
            assertEquals(5, written.stream().filter(m -> m.startsWith(prefix)).count(), written.toString());
        }
        clock.advance(Duration.ofNanos(MINUTE));
        for (int i = 0; i < 3; i++) {
            runTimer();
        }
        assertEquals(List.of("refused connections: 3 more like this from 127.0.0.2 in the last 60 s",
                "refused connections: 3 more like this from 127.0.0.3 in the last 60 s",
                "over-long lines: 3 more like this from 127.0.0.2 in the last 60 s"),
                capture.messages(Level.WARNING).subList(15, 18), "each summary once, though every timer task runs");
    }

    @Test
    void anIntervalWithoutExtraWarningsWritesNoSummary() throws Exception {
        for (int i = 0; i < 5; i++) {
            warn("over-long lines", "127.0.0.2", "line " + i);
        }
        assertEquals(List.of(), dueAt);
        clock.advance(Duration.ofNanos(2 * MINUTE));
        limiter.flush();
        limiter.close();
        assertEquals(5, capture.records.size(), capture.toString());
    }

    @Test
    void aLateTimerStillWritesTheSummaryBeforeTheNextIntervalsFirstWarning() throws Exception {
        for (int i = 0; i < 6; i++) {
            warn("refused connections", "127.0.0.2", "first interval " + i);
        }
        clock.advance(Duration.ofNanos(MINUTE + 1));
        warn("refused connections", "127.0.0.2", "second interval");
        List<String> written = capture.messages(Level.WARNING);
        assertEquals(List.of("refused connections: 1 more like this from 127.0.0.2 in the last 60 s", "second interval"),
                written.subList(5, 7));
        runTimer();
        assertEquals(7, capture.records.size(), "the timer finds nothing more to say");
    }

    @Test
    void closingWritesWhatIsCountedWithTheTimeSoFarAndStopsTheTimer() throws Exception {
        for (int i = 0; i < 9; i++) {
            warn("over-long lines", "127.0.0.4", "line " + i);
        }
        clock.advance(Duration.ofNanos(TimeUnit.MILLISECONDS.toNanos(12_300)));
        limiter.close();
        assertEquals("over-long lines: 4 more like this from 127.0.0.4 in the last 13 s",
                capture.messages(Level.WARNING).get(5));
        assertEquals(true, timerStopped);
    }

    @Test
    void theServersTimerWritesTheSummaryOnItsOwnThenItsThreadEnds() throws Exception {
        // Another limiter's timer in this JVM (a hub an earlier test closed) may start or end its own
        // wss-warnings thread meanwhile: this one's thread is the one that was not there before.
        Set<Thread> before = warningsThreads();
        WarningLimiter real = new WarningLimiter(2, LogLimiter.ALL_FIRST, TimeUnit.MILLISECONDS.toNanos(200), HubClock.SYSTEM,
                WarningLimiter.timer(HubClock.SYSTEM));
        for (int i = 0; i < 5; i++) {
            real.warn(log, "refused connections", address("127.0.0.5"), "refused " + i);
        }
        Set<Thread> started = warningsThreads();
        started.removeAll(before);
        assertEquals(1, started.size(), "a thread while a summary is due");
        Thread timer = started.iterator().next();
        Wait.until("the summary", () -> capture.count(Level.WARNING, "3 more like this from 127.0.0.5") == 1);
        Wait.until("the timer's thread ended", () -> !timer.isAlive());
        real.close();
        for (int i = 0; i < 3; i++) {
            real.warn(log, "refused connections", address("127.0.0.5"), "after the close");
        }
        assertEquals(2, capture.count(Level.WARNING, "after the close"), "limited still, though no summary can be scheduled");
    }

    private static Set<Thread> warningsThreads() {
        return Thread.getAllStackTraces().keySet().stream().filter(t -> t.getName().equals("wss-warnings"))
                .collect(Collectors.toCollection(HashSet::new));
    }

    @Test
    void theWarningKeepsItsException() throws Exception {
        IllegalStateException bug = new IllegalStateException("a bug");
        limiter.warn(log, "failed answers", address("127.0.0.2"), "failed", bug);
        assertEquals(bug, capture.records.get(0).getThrown());
    }

    @Test
    void fiveThousandAddressesWriteTwentyLinesOfAKindThenOneSummaryForThemAll() throws Exception {
        WarningLimiter limited = new WarningLimiter(5, 20, MINUTE, clock, new LogLimiter.Timer() {
            @Override
            public void after(long delayNs, Runnable task) {
                dueAt.add(clock.nanoTime() + delayNs);
                due.add(task);
            }

            @Override
            public void stop() {
            }
        });
        for (int i = 0; i < 5000; i++) {
            // IPv6: as many addresses as an attacker likes.
            limited.warn(log, "refused connections", address("2001:db8::" + Integer.toHexString(i + 1)), "refused #" + i);
        }
        limited.warn(log, "over-long lines", address("2001:db8::1"), "another kind has its own total");
        List<String> written = capture.messages(Level.WARNING);
        assertEquals(21, written.size(), written.toString());
        assertEquals("refused #19", written.get(19));
        assertEquals(List.of(1_000_000_000L + MINUTE), dueAt, "one summary due");
        runTimer();
        assertEquals("refused connections: 4980 more like this from any address in the last 60 s",
                capture.messages(Level.WARNING).get(21));
        limited.close();
        assertEquals(22, capture.records.size(), "nothing else to say");
    }

    @Test
    void anAddressOverItsOwnLimitHasItsOwnSummaryBeforeTheTotal() throws Exception {
        WarningLimiter limited = new WarningLimiter(5, 8, MINUTE, clock, new LogLimiter.Timer() {
            @Override
            public void after(long delayNs, Runnable task) {
            }

            @Override
            public void stop() {
            }
        });
        for (int i = 0; i < 7; i++) {
            limited.warn(log, "refused connections", address("127.0.0.2"), "flood " + i);
        }
        for (int i = 0; i < 10; i++) {
            limited.warn(log, "refused connections", address("127.0.0." + (10 + i)), "crowd " + i);
        }
        assertEquals(8, capture.messages(Level.WARNING).size(), "5 of the flood, 3 of the crowd");
        clock.advance(Duration.ofNanos(MINUTE));
        limited.flush();
        assertEquals(List.of("refused connections: 2 more like this from 127.0.0.2 in the last 60 s",
                "refused connections: 7 more like this from any address in the last 60 s"),
                capture.messages(Level.WARNING).subList(8, 10));
    }

    @Test
    void theInfoPathLimitsAnOperatorsForcesAtInfoWithAnInfoSummary() throws Exception {
        for (int i = 0; i < 1000; i++) {
            limiter.info(log, "operator commands", address("127.0.0.1"), "operator 127.0.0.1:4000: FORCE A" + i + " - B down");
        }
        assertEquals(5, capture.messages(Level.INFO).size());
        assertEquals("operator 127.0.0.1:4000: FORCE A4 - B down", capture.messages(Level.INFO).get(4));
        runTimer();
        assertEquals("operator commands: 995 more like this from 127.0.0.1 in the last 60 s", capture.messages(Level.INFO).get(5));
        assertEquals(List.of(), capture.messages(Level.WARNING), "an operator's INFO is never a WARNING");
    }

    @Test
    void aMessageWithA32KilobyteNameIsCutToAThousandCharacters() throws Exception {
        String name = "N".repeat(32 * 1024);
        limiter.info(log, "operator commands", address("127.0.0.1"), "FORCE " + name + " - B down");
        String written = capture.messages(Level.INFO).get(0);
        assertEquals(1000 + "... (31783 more characters)".length(), written.length());
        assertEquals(true, written.startsWith("FORCE NNN") && written.endsWith("N... (31783 more characters)"),
                written.substring(written.length() - 40));
    }

    @Test
    void anInfoWithNoAddressIsLimitedByItsKindsTotalAlone() throws Exception {
        for (int i = 0; i < 1000; i++) {
            limiter.info(log, "forced pairs", "forced A" + i + " - B down");
        }
        assertEquals(20, capture.messages(Level.INFO).size(), "the kind's total, 20 a minute");
        runTimer();
        assertEquals("forced pairs: 980 more like this from any address in the last 60 s", capture.messages(Level.INFO).get(20));
    }
}
