package org.usarsim.wss.shaping;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;

/** The radios' ledger alone, its clock given by the test. */
class AirtimeTest {

    private static final long MS = 1_000_000;
    private static final long SECOND = 1_000_000_000;

    @Test
    void aGrantIsTheAirtimeAskedOfOneQuantumAtMost() {
        Airtime.Hop hop = Airtime.shared().open("A", "B", 0);
        assertEquals(new Airtime.Grant(0, 2 * MS), hop.grant(2 * MS, 0));
        assertEquals(new Airtime.Grant(2 * MS, 2 * MS + 15_000), hop.grant(15_000, 0), "after the first");
        assertThrows(IllegalArgumentException.class, () -> hop.grant(2 * MS + 1, 0), "more than a quantum");
        assertThrows(IllegalArgumentException.class, () -> hop.grant(0, 0));
    }

    @Test
    void anIdleRadioStartsAtOnceAndSavesNothingUp() {
        Airtime.Hop hop = Airtime.shared().open("A", "B", 0);
        hop.grant(2 * MS, 0);
        Airtime.Grant later = hop.grant(2 * MS, 10 * SECOND);
        assertEquals(new Airtime.Grant(10 * SECOND, 10 * SECOND + 2 * MS), later, "idle for 10 s: starts now, and lasts what it asked");
    }

    @Test
    void bothTheSenderAndTheReceiverAreBusy() {
        Airtime airtime = Airtime.shared();
        Airtime.Hop ab = airtime.open("A", "B", 0);
        Airtime.Hop cb = airtime.open("C", "B", 0);
        Airtime.Hop ca = airtime.open("C", "A", 0);
        Airtime.Hop cd = airtime.open("C", "D", 0);
        Airtime.Hop ef = airtime.open("E", "F", 0);
        assertEquals(0, ab.grant(2 * MS, 0).startNs());
        assertEquals(2 * MS, cb.grant(2 * MS, 0).startNs(), "B is receiving from A until 2 ms");
        assertEquals(4 * MS, ca.grant(2 * MS, 0).startNs(), "C is sending to B until 4 ms");
        assertEquals(0, cd.grant(2 * MS, 0).startNs(), "C and D are both idle until 2 ms: the gap is filled");
        assertEquals(6 * MS, cd.grant(2 * MS, 0).startNs(), "C is sending to A until 6 ms, and the direction's bytes keep their order");
        assertEquals(0, ef.grant(2 * MS, 0).startNs(), "E and F have nothing to do with them");
    }

    @Test
    void aGrantFillsAnIdleGapOfBothRadiosButNeverPrecedesItsDirectionsLastGrant() {
        Airtime airtime = Airtime.shared();
        Airtime.Hop xw = airtime.open("X", "W", 0);
        Airtime.Hop ax = airtime.open("A", "X", 0);
        Airtime.Hop ab = airtime.open("A", "B", 0);
        assertEquals(0, xw.grant(2 * MS, 0).startNs());
        assertEquals(2 * MS, ax.grant(2 * MS, 0).startNs(), "X is sending to W until 2 ms");
        assertEquals(0, ab.grant(MS, 0).startNs(), "A and B are both idle until 2 ms: the gap is filled");
        assertEquals(4 * MS, ab.grant(2 * MS, 0).startNs(), "from 1 ms to 2 ms is too short for 2 ms");
        assertEquals(6 * MS, ab.grant(MS, 0).startNs(), "1 ms to 2 ms would fit, but A to B's bytes keep their order");
    }

    @Test
    void anIdleGrantTakesTimeFreeNowOrAGapBetweenReservationsAndDelaysNoTurn() {
        Airtime airtime = Airtime.shared();
        Airtime.Hop next = airtime.open("R2", "R3", 0);
        Airtime.Hop middle = airtime.open("R1", "R2", 0);
        Airtime.Hop in = airtime.open("R0", "R1", 0);
        assertEquals(new Airtime.Grant(0, MS), in.idleGrant(MS, 0), "R0 and R1 free now, nothing reserved: at once");
        assertEquals(0, next.grant(2 * MS, 0).startNs());
        assertEquals(2 * MS, middle.grant(2 * MS, 0).startNs(), "R2 sends to R3 until 2 ms");
        assertEquals(4 * MS, next.grant(2 * MS, 0).startNs());
        assertEquals(6 * MS, middle.grant(2 * MS, 0).startNs(), "R1 idle from 4 to 6 ms: R2 is busy");
        assertEquals(new Airtime.Grant(4 * MS, 6 * MS), in.idleGrant(2 * MS, 3 * MS), "the gap R1 has while R1 to R2 waits for R2");
        assertEquals(8 * MS, middle.grant(2 * MS, 3 * MS).startNs(), "the turn it would have had without the idle grant");
        assertNull(in.idleGrant(2 * MS, 3 * MS), "after 10 ms nothing is reserved: that time is for the turns");
        assertEquals(10 * MS, in.idleFrom());
        assertEquals(new Airtime.Grant(10 * MS, 12 * MS), in.idleGrant(2 * MS, 10 * MS), "free now: at once");
        assertEquals(12 * MS, in.grant(2 * MS, 10 * MS).startNs(), "its own grants keep their order");
    }

    @Test
    void anIdleGrantIsShortenedToItsGapAndSkipsGapsTooShort() {
        Airtime airtime = Airtime.shared();
        Airtime.Hop ac = airtime.open("A", "C", 0);
        Airtime.Hop xy = airtime.open("X", "Y", 0);
        Airtime.Hop xa = airtime.open("X", "A", 0);
        Airtime.Hop cz = airtime.open("C", "Z", 0);
        assertEquals(0, ac.grant(2 * MS, 0).startNs());
        xy.grant(2 * MS, 0);
        xy.grant(30_000, 0);
        assertEquals(2 * MS + 30_000, xa.grant(2 * MS, 0).startNs(), "A is free at 2 ms, X at 2.03 ms");
        assertEquals(2 * MS, cz.grant(2 * MS, 0).startNs());
        cz.grant(MS, 0);
        assertEquals(5 * MS, ac.grant(2 * MS, 0).startNs(), "C is free at 5 ms: A is left a gap of 30 us and one of 970 us");
        Airtime.Hop ab = airtime.open("A", "B", 0);
        assertEquals(new Airtime.Grant(4 * MS + 30_000, 5 * MS), ab.idleGrant(2 * MS, 0), "the gap of 970 us, not the one of 30 us");
        Airtime.Hop ad = airtime.open("A", "D", 0);
        assertEquals(new Airtime.Grant(2 * MS, 2 * MS + 20_000), ad.idleGrant(20_000, 0), "20 us fits the gap of 30 us");
    }

    @Test
    void withoutSharedAirtimeAnIdleGrantIsAnyGrant() {
        Airtime.Hop hop = Airtime.unshared().open("A", "B", 0);
        assertEquals(new Airtime.Grant(0, 2 * MS), hop.idleGrant(2 * MS, 0));
        assertEquals(new Airtime.Grant(2 * MS, 4 * MS), hop.idleGrant(2 * MS, 0));
    }

    @Test
    void aRelayPaysTwice() {
        Airtime airtime = Airtime.shared();
        Airtime.Hop in = airtime.open("A", "R", 0);
        Airtime.Hop out = airtime.open("R", "B", 0);
        Airtime.Grant received = in.grant(2 * MS, 0);
        Airtime.Grant sent = out.grant(2 * MS, 0);
        assertEquals(received.endNs(), sent.startNs(), "R cannot send while it receives");
    }

    @Test
    void withoutAirtimeEachDirectionHasOnlyItsOwnRate() {
        Airtime airtime = Airtime.unshared();
        Airtime.Hop ab = airtime.open("A", "B", 0);
        Airtime.Hop ac = airtime.open("A", "C", 0);
        Airtime.Hop ab2 = airtime.open("A", "B", 0);
        assertEquals(0, ab.grant(2 * MS, 0).startNs());
        assertEquals(0, ac.grant(2 * MS, 0).startNs());
        assertEquals(0, ab2.grant(2 * MS, 0).startNs(), "another link between the same robots: its own rate too");
        assertEquals(2 * MS, ab.grant(2 * MS, 0).startNs(), "but one direction's grants follow each other");
        assertTrue(Double.isNaN(airtime.inUse("A", 10 * MS)), "no shared radio to measure");
    }

    @Test
    void airtimeInUseIsTheBusyPartOfTheLastSecond() {
        Airtime airtime = Airtime.shared();
        Airtime.Hop ab = airtime.open("A", "B", 0);
        long now = 0;
        while (now < 3 * SECOND) {
            now = ab.grant(2 * MS, now).endNs();
        }
        assertEquals(1, airtime.inUse("A", 3 * SECOND), 1e-9, "always on the air: 100 %");
        assertEquals(1, airtime.inUse("B", 3 * SECOND), 1e-9, "the receiver too");
        assertEquals(0, airtime.inUse("C", 3 * SECOND), "a robot it does not know");
        assertEquals(0.5, airtime.inUse("A", 3 * SECOND + 500 * MS), 0.011, "idle for the last half second");
        assertEquals(0, airtime.inUse("A", 4 * SECOND + MS), "idle for more than a second");

        now = 10 * SECOND;
        while (now < 12 * SECOND) {
            ab.grant(2 * MS, now);
            now += 4 * MS;
        }
        assertEquals(0.5, airtime.inUse("A", 12 * SECOND), 0.01, "2 ms on the air every 4 ms");
        assertEquals(0.5, airtime.inUse("B", 12 * SECOND), 0.01);
    }

    @Test
    void airtimeReservedAheadCountsOnlyOnceItIsPast() {
        Airtime airtime = Airtime.shared();
        Airtime.Hop ab = airtime.open("A", "B", 0);
        for (int i = 0; i < 250; i++) {
            ab.grant(2 * MS, 0);
        }
        assertEquals(0, airtime.inUse("A", 0), "reserved up to 500 ms, none of it past");
        assertEquals(100.0 / 990, airtime.inUse("A", 100 * MS), 1e-9,
                "100 ms past, in a window from -890 ms (the radio was idle before it was first used)");
        assertEquals(0.5, airtime.inUse("A", SECOND), 0.011);
    }

    @Test
    void timesMayBeNegativeAsNanoTimesAre() {
        Airtime airtime = Airtime.shared();
        long start = -7_000_000_000_000L;
        Airtime.Hop ab = airtime.open("A", "B", start);
        long now = start;
        while (now < start + 2 * SECOND) {
            now = ab.grant(2 * MS, now).endNs();
        }
        assertEquals(1, airtime.inUse("A", now), 1e-9);
        assertEquals(0, airtime.inUse("A", now + 2 * SECOND));
    }

    @Test
    void aClosedHopIsRefusedAndItsRobotsMayComeBack() {
        Airtime airtime = Airtime.shared();
        Airtime.Hop ab = airtime.open("A", "B", 0);
        ab.grant(2 * MS, 0);
        ab.close();
        ab.close();
        assertThrows(IllegalStateException.class, () -> ab.grant(1, 0));
        assertEquals(0.002, airtime.inUse("A", SECOND / 2), 1e-3, "still measured for a second");
        Airtime.Hop again = airtime.open("A", "C", 5 * SECOND);
        assertEquals(5 * SECOND, again.grant(1, 5 * SECOND).startNs());
    }

    @Test
    void grantsFromManyThreadsNeverOverlapOnARadio() throws InterruptedException {
        Airtime airtime = Airtime.shared();
        String[] robots = {"A", "B", "C", "D"};
        AtomicLong clock = new AtomicLong();
        Map<String, List<Airtime.Grant>> byRadio = new ConcurrentHashMap<>();
        for (String robot : robots) {
            byRadio.put(robot, Collections.synchronizedList(new ArrayList<>()));
        }
        List<Thread> threads = new ArrayList<>();
        CountDownLatch start = new CountDownLatch(1);
        for (int t = 0; t < 6; t++) {
            String from = robots[t % 4];
            String to = robots[(t + 1 + t / 4) % 4];
            Airtime.Hop hop = airtime.open(from, to, 0);
            Thread thread = new Thread(() -> {
                try {
                    start.await();
                } catch (InterruptedException e) {
                    return;
                }
                for (int i = 0; i < 2_000; i++) {
                    Airtime.Grant grant = hop.grant(1 + (i * 7919L) % Airtime.QUANTUM_NS, clock.addAndGet(1_000));
                    byRadio.get(from).add(grant);
                    byRadio.get(to).add(grant);
                }
            });
            threads.add(thread);
            thread.start();
        }
        start.countDown();
        for (Thread thread : threads) {
            thread.join();
        }
        for (String robot : robots) {
            List<Airtime.Grant> grants = new ArrayList<>(byRadio.get(robot));
            grants.sort(Comparator.comparingLong(Airtime.Grant::startNs));
            for (int i = 1; i < grants.size(); i++) {
                assertTrue(grants.get(i).startNs() >= grants.get(i - 1).endNs(),
                        robot + "'s radio has two grants at once: " + grants.get(i - 1) + " and " + grants.get(i));
            }
        }
    }
}
