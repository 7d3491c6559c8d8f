package org.usarsim.wss.hub.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.model.LinkQuality;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.shaping.RateTable;
import org.usarsim.wss.shaping.ShapingConfig;
import org.usarsim.wss.shaping.LossTable;
import org.usarsim.wss.shaping.JitterDistribution;
import org.usarsim.wss.shaping.JitterConfig;

/** The hub's rules without sockets, threads or waiting: each step's changes read as data, the time moved by hand. */
class HubCoreTest {

    private static final long SECOND = TimeUnit.SECONDS.toNanos(1);
    private static final InetAddress LOOPBACK = InetAddress.getLoopbackAddress();
    private static final RobotPair AB = RobotPair.of("A", "B");

    private final HubCore core = new HubCore("TestModel", true, 600, 1000, Integer.MAX_VALUE, ShapingConfig.OFF);
    private long now = 1_000 * SECOND;

    private final RobotSession sessionA = () -> { };
    private final RobotSession sessionB = () -> { };

    @Test
    void aDnsAllocatesAListeningPortWithTheNumberTheHubBound() {
        registerBoth();
        Changes out = new Changes();
        DnsResult asked = core.dns("A", "B", 0, true, -1, now, out);
        assertEquals(DnsOutcome.NEEDS_NUMBER, asked.outcome());
        assertEquals(new PortKey("A", "B", 6000), asked.key());
        assertTrue(out.events().isEmpty() && out.portActions().isEmpty(), "nothing happens before the number is bound");

        DnsResult allocated = core.dns("A", "B", 0, true, 40001, now, out);
        assertEquals(DnsOutcome.OK, allocated.outcome());
        assertEquals(40001, allocated.port());
        assertTrue(allocated.numberUsed());
        assertEquals(List.of(Changes.PortWork.LISTEN), works(out));
        assertTrue(out.events().contains(new HubEvent.PortAllocated(asked.key(), 40001, true)), out.events().toString());

        Changes again = new Changes();
        DnsResult second = core.dns("A", "B", 6000, true, 40002, now, again);
        assertEquals(40001, second.port(), "the same DNS, the same port");
        assertFalse(second.numberUsed(), "the hub gives the second number back");
        assertTrue(again.portActions().isEmpty());
    }

    @Test
    void aBreakStopsThePortAndClosesItsConnectionsAndAnOldListenerIsRefusedAfterTheResume() {
        WssPort port = registeredPort();
        int firstEpoch = port.epoch();
        FakeConnection link = new FakeConnection(50001);
        assertNull(core.commit(port, firstEpoch, LOOPBACK, true, link));

        Changes broke = new Changes();
        assertTrue(core.breakPair(AB, now, broke));
        assertEquals(List.of(Changes.PortWork.STOP), works(broke));
        assertEquals(List.of(new Changes.Close(link, CloseReason.OUT_OF_RANGE)), broke.closes());
        assertEquals("the port no longer listens", core.admit(port, firstEpoch, LOOPBACK, true, now, new Changes()).refusal());

        Changes resumed = new Changes();
        assertTrue(core.resumePair(AB, now, resumed));
        assertEquals(List.of(Changes.PortWork.LISTEN), works(resumed));
        assertEquals(firstEpoch + 1, resumed.portActions().get(0).epoch(), "a new listener, of a new epoch");
        assertEquals("the port no longer listens", core.admit(port, firstEpoch, LOOPBACK, true, now, new Changes()).refusal(),
                "a connection the stopped listener accepted late is refused");
        assertNull(core.admit(port, port.epoch(), LOOPBACK, true, now, new Changes()).refusal());
        assertEquals("TestModel does not allow A -> B now",
                core.admit(port, port.epoch(), LOOPBACK, false, now, new Changes()).refusal(), "the model's answer counts");
    }

    /**
     * Issue 36, item 10: a poll that finds the pair broken again while the connections the break
     * closed are still ending changes nothing, so the model tells no second break (the recording
     * had two {@code break} lines where the log said "broken" once).
     */
    @Test
    void aBreakAgainWhileTheBrokenLinksStillEndChangesNothing() {
        WssPort port = registeredPort();
        FakeConnection link = new FakeConnection(50001);
        assertNull(core.commit(port, port.epoch(), LOOPBACK, true, link));
        assertTrue(core.breakPair(AB, now, new Changes()));
        assertTrue(port.hasLinks(), "the link the break closed has not ended yet");

        Changes again = new Changes();
        assertFalse(core.breakPair(AB, now, again), "nothing changed: the pair was broken, its port stopped, its link told");
        assertTrue(again.events().isEmpty(), again.events().toString());
        assertTrue(again.portActions().isEmpty());
    }

    /**
     * Issue 36, item 13: the stop says every connection terminated and every robot deregistered,
     * itself, so that they come before the hub's "WSS stopped"; a link that ends later says nothing.
     */
    @Test
    void theStopTerminatesTheConnectionsAndDeregistersEveryRobot() {
        WssPort port = registeredPort();
        FakeConnection link = new FakeConnection(50001);
        assertNull(core.commit(port, port.epoch(), LOOPBACK, true, link));
        Changes stopped = new Changes();
        core.close(stopped);
        assertEquals(List.of(new HubEvent.Terminated(port.key), new HubEvent.Deregistered("A"), new HubEvent.Deregistered("B")),
                stopped.events().stream().filter(e -> e instanceof HubEvent.Terminated || e instanceof HubEvent.Deregistered).toList());
        assertEquals(List.of(new Changes.Close(link, CloseReason.SERVER_STOPPED)), stopped.closes());
        Changes ended = new Changes();
        core.linkEnded(port, link, true, now, ended);
        assertTrue(ended.events().stream().noneMatch(e -> e instanceof HubEvent.Terminated), "said once, at the stop");
    }

    /**
     * Issue 36: a FORCE down answered while a link was connecting to its target. The link was
     * committed before the force, so the force's step closes it; once that step has run, the link
     * is not announced established (no CON_ESTABLISHED after FORCED ... DOWN), whatever comes after
     * (an UP of the storm: the port listens again, with a new epoch). A connection the old listener
     * accepted before the force, handed over after it, is refused at admission, and stays refused
     * after the UP. A link committed with no force in between is established.
     */
    @Test
    void aLinkAForceDownClosedBeforeItReachedItsTargetIsNeverEstablishedNorIsAConnectionAcceptedBeforeIt() {
        WssPort port = registeredPort();
        int before = port.epoch();
        FakeConnection connecting = new FakeConnection(50001);
        assertNull(core.commit(port, before, LOOPBACK, true, connecting));
        assertTrue(core.established(port, connecting), "not forced: it is established once it reaches its target");

        Changes down = new Changes();
        core.force(AB, Force.DOWN, now, down);
        assertEquals(List.of(new Changes.Close(connecting, CloseReason.FORCED)), down.closes());
        assertFalse(core.established(port, connecting), "closed by the force's step, before its socket is");
        assertNotNull(core.admit(port, before, LOOPBACK, true, now, new Changes()).refusal(), "accepted before the force, refused after it");

        core.force(AB, Force.UP, now, new Changes());
        assertFalse(core.established(port, connecting), "the UP that follows does not revive it");
        assertNotNull(core.admit(port, before, LOOPBACK, true, now, new Changes()).refusal(), "nor the old listener's connection");
        FakeConnection after = new FakeConnection(50002);
        assertNull(core.commit(port, port.epoch(), LOOPBACK, true, after));
        assertTrue(core.established(port, after));
        core.linkEnded(port, connecting, false, now, new Changes());
        assertFalse(core.established(port, connecting), "ended: no longer the port's");
    }

    @Test
    void aForceWinsOverTheModelAndItsReleaseGivesThePairBack() {
        WssPort port = registeredPort();
        Changes broke = new Changes();
        core.breakPair(AB, now, broke);

        Changes up = new Changes();
        core.force(AB, Force.UP, now, up);
        assertEquals(new HubEvent.PairForced("A", "B", true), up.events().get(0), "the force comes before what it does");
        assertEquals(List.of(Changes.PortWork.LISTEN), works(up));
        assertNull(core.admit(port, port.epoch(), LOOPBACK, false, now, new Changes()).refusal(), "forced up: whatever the model says");

        Changes released = new Changes();
        core.release(AB, true, true, now, released);
        assertEquals(new HubEvent.PairReleased("A", "B"), released.events().get(0));
        assertEquals(List.of(Changes.PortWork.STOP), works(released), "the model's last break counts again");
        assertNull(core.forced(AB));
    }

    @Test
    void thePortsOfARobotThatLeftAreForgottenOnlyOnceThePortMemoryHasPassed() {
        WssPort port = registeredPort();
        List<WssPort> draining = core.beginLeaving("A", sessionA);
        assertEquals(List.of(port), draining, "its listening ports drain first");
        Changes left = new Changes();
        core.left("A", sessionA, now, left);
        assertTrue(left.events().contains(new HubEvent.Deregistered("A")));
        assertEquals(List.of(Changes.PortWork.STOP), works(left), "the port stops listening, its number kept");
        assertEquals(List.of(new Changes.ForgetLater("A", 600 * SECOND)), left.forgetLater());

        Changes early = new Changes();
        core.forgetIfGone("A", now + 599 * SECOND, early);
        assertTrue(early.portActions().isEmpty(), "not yet");

        Changes late = new Changes();
        core.forgetIfGone("A", now + 600 * SECOND, late);
        assertEquals(List.of(Changes.PortWork.RELEASE), works(late));
        assertTrue(late.events().contains(new HubEvent.PortForgotten(port.key, port.number)));
        assertTrue(late.events().contains(new HubEvent.Said(java.util.logging.Level.INFO, "forgotten WSS ports", "forgot 1 WSS port of A, gone for 600 s")),
                late.events().toString());
        assertNull(core.port(port.key));
    }

    @Test
    void aRobotBackBeforeThePortMemoryPassedKeepsItsPortAndListensAgain() {
        WssPort port = registeredPort();
        core.beginLeaving("A", sessionA);
        core.left("A", sessionA, now, new Changes());
        Changes back = new Changes();
        assertEquals(NameCheck.REGISTERED, core.register(robot("A", sessionA, 5000), now + 10 * SECOND, back));
        assertEquals(List.of(Changes.PortWork.LISTEN), works(back));
        Changes later = new Changes();
        core.forgetIfGone("A", now + 600 * SECOND, later);
        assertTrue(later.portActions().isEmpty(), "back: nothing is forgotten");
        assertEquals(port, core.port(port.key));
    }

    @Test
    void aTakenNameSaysWhetherItsHolderIsLeaving() {
        registerBoth();
        RobotSession other = () -> { };
        assertEquals(NameCheck.TAKEN, core.register(robot("A", other, 5000), now, new Changes()));
        core.beginLeaving("A", sessionA);
        assertEquals(NameCheck.TAKEN_BY_LEAVING, core.register(robot("A", other, 5000), now, new Changes()));
    }

    @Test
    void theTimeUpOfAPairFollowsTheMovedClock() {
        registeredPort();
        core.breakPair(AB, now + 30 * SECOND, new Changes());
        PairStats stats = core.pairStats(0).get(0);
        assertEquals(PairState.BROKEN, stats.state());
        assertEquals(0.5, stats.upShare(now + 60 * SECOND), 1e-9, "up 30 s of the 60 s since first seen");
    }

    @Test
    void aKickGivesThePortsBackClosesTheLinksAndTheControlConnection() {
        WssPort port = registeredPort();
        FakeConnection link = new FakeConnection(50002);
        core.commit(port, port.epoch(), LOOPBACK, true, link);
        Changes kicked = new Changes();
        core.kick("B", now, kicked);
        assertEquals(List.of(Changes.PortWork.RELEASE), works(kicked));
        assertEquals(List.of(new Changes.Close(link, CloseReason.KICKED)), kicked.closes());
        assertEquals(List.of(sessionB), kicked.sessionsToClose());
        assertFalse(core.isRegistered("B"));
    }

    @Test
    void reverseDnsFindsTheSourceByTheOutgoingPort() {
        WssPort port = registeredPort();
        core.commit(port, port.epoch(), LOOPBACK, true, new FakeConnection(50003));
        assertEquals("A", core.reverseDns("B", 50003));
        assertNull(core.reverseDns("B", 50004));
    }

    @Test
    void aPairsConditionOneWayComesFromThePinThenTheModelsOwnRateThenTheRateTable() {
        HubCore shaped = new HubCore("TestModel", true, 600, 1000, Integer.MAX_VALUE,
                new ShapingConfig(true, RateTable.parse("-50:8M,-70:2M,-90:1M"), 5, true));
        OrderedPair ab = new OrderedPair("A", "B");
        OrderedPair ba = ab.reversed();
        shaped.register(robot("A", sessionA, 5000), now, new Changes());
        shaped.register(robot("B", sessionB, 6000), now, new Changes());
        Changes measuredFirst = new Changes();
        shaped.measured(Map.of(ab, new Measurement(-40, Optional.empty()), ba, new Measurement(-60, Optional.empty())), measuredFirst);
        assertTrue(measuredFirst.events().isEmpty(), "a pair not seen yet has no condition to say");

        Changes dns = new Changes();
        shaped.dns("A", "B", 0, true, 40001, now, dns);
        assertTrue(dns.events().containsAll(List.of(new HubEvent.RateChanged(ab, 8_000_000), new HubEvent.RateChanged(ba, 2_000_000))),
                "a new pair starts at its measured rates: " + dns.events());
        assertEquals(new PairCondition(PairState.UP, 8_000_000, 5), shaped.conditions().get(ab));

        Changes weaker = new Changes();
        shaped.measured(Map.of(ab, new Measurement(-80, Optional.empty())), weaker);
        assertEquals(List.of(new HubEvent.RateChanged(ab, 1_000_000)), weaker.events(), "said once, at the change");
        Changes same = new Changes();
        shaped.measured(Map.of(ab, new Measurement(-85, Optional.empty())), same);
        assertTrue(same.events().isEmpty(), "the same rate is not said again");

        Changes modelSays = new Changes();
        shaped.measured(Map.of(ab, new Measurement(-85, Optional.of(new LinkQuality(300_000, 40)))), modelSays);
        assertEquals(new PairCondition(PairState.UP, 300_000, 40, 1), shaped.conditions().get(ab),
                "the model's own rate and delay win; the loss is the default loss table's for -85 dBm");

        shaped.force(AB, Force.UP, new RatePin(1_000_000, 50), now, new Changes());
        assertEquals(new PairCondition(PairState.FORCED_UP, 1_000_000, 50, 1), shaped.conditions().get(ab),
                "the operator's pin wins (a pin pins rate and delay, the loss follows the strength)");
        assertEquals(new PairCondition(PairState.FORCED_UP, 1_000_000, 50), shaped.conditions().get(ba), "both ways");

        shaped.release(AB, true, true, now, new Changes());
        assertEquals(new PairCondition(PairState.UP, 300_000, 40, 1), shaped.conditions().get(ab), "released: the model's again");
        assertEquals(new PairCondition(PairState.UP, 2_000_000, 5), shaped.conditions().get(ba));

        org.usarsim.wss.model.DatagramLoss rule = (bytes, nowNs, random) -> bytes > 100;
        shaped.measured(Map.of(ab, new Measurement(-85, Optional.of(new LinkQuality(300_000, 40, rule)))), new Changes());
        assertSame(rule, shaped.conditions().get(ab).datagramLoss(), "the model's datagram loss rule reaches the pair's condition");
    }

    @Test
    void aPairsJitterIsTheSettingsUnlessAnOperatorPinsAnother() {
        ShapingConfig jittery = new ShapingConfig(true, RateTable.DEFAULT, 5, true, ShapingConfig.DEFAULT_QUEUE_MS, LossTable.DEFAULT,
                new JitterConfig(15, JitterDistribution.NORMAL, false, 0));
        HubCore shaped = new HubCore("TestModel", true, 600, 1000, Integer.MAX_VALUE, jittery);
        shaped.register(robot("A", () -> { }, 5000), now, new Changes());
        shaped.register(robot("B", () -> { }, 6000), now, new Changes());
        shaped.dns("A", "B", 0, true, 40001, now, new Changes());
        OrderedPair ab = new OrderedPair("A", "B");
        assertEquals(15, shaped.conditions().get(ab).jitterMs(), "wss.shaping.jitter");
        shaped.force(AB, Force.UP, new RatePin(1_000_000, 50, 20), now, new Changes());
        assertEquals(new PairCondition(PairState.FORCED_UP, 1_000_000, 50, 0, 20), shaped.conditions().get(ab), "the pin's");
        assertEquals(20, shaped.conditions().get(ab.reversed()).jitterMs(), "both ways");
        shaped.force(AB, Force.UP, new RatePin(1_000_000, 50), now, new Changes());
        assertEquals(15, shaped.conditions().get(ab).jitterMs(), "a pin without a jitter leaves the setting's");
        shaped.force(AB, Force.UP, new RatePin(0, -1, 0), now, new Changes());
        assertEquals(0, shaped.conditions().get(ab).jitterMs(), "a jitter pinned alone, to none");
        shaped.release(AB, true, true, now, new Changes());
        assertEquals(15, shaped.conditions().get(ab).jitterMs(), "released: the setting's again");
    }

    @Test
    void withShapingOffAConditionIsItsStateOnly() {
        registeredPort();
        core.breakPair(AB, now, new Changes());
        assertEquals(new PairCondition(PairState.BROKEN, 0, 0), core.conditions().get(new OrderedPair("A", "B")));
    }

    @Test
    void theRobotsOfOneAddressHoldAtMostMaxPortsPerAddressTogetherAndThoseThatLeftDoNotCount() throws Exception {
        HubCore capped = new HubCore("TestModel", true, 600, 1000, 3, ShapingConfig.OFF);
        InetAddress swarm = InetAddress.getByName("10.0.0.1");
        InetAddress other = InetAddress.getByName("10.0.0.2");
        RobotSession s1 = () -> { };
        RobotSession s2 = () -> { };
        capped.register(new RegisteredRobot("S1", swarm, List.of(5000), s1), now, new Changes());
        capped.register(new RegisteredRobot("S2", swarm, List.of(5000), s2), now, new Changes());
        capped.register(new RegisteredRobot("T1", other, List.of(5000, 5001, 5002), () -> { }), now, new Changes());
        capped.register(new RegisteredRobot("T2", other, List.of(5000), () -> { }), now, new Changes());
        int number = 40001;
        assertEquals(DnsOutcome.OK, capped.dns("S1", "T1", 5000, true, number++, now, new Changes()).outcome());
        assertEquals(DnsOutcome.OK, capped.dns("S1", "T1", 5001, true, number++, now, new Changes()).outcome());
        assertEquals(DnsOutcome.OK, capped.dns("S2", "T2", 0, true, number++, now, new Changes()).outcome());

        Changes refused = new Changes();
        assertEquals(DnsOutcome.NO_PORT, capped.dns("S2", "T1", 0, true, number++, now, refused).outcome(),
                "a fourth port from the swarm's address, by another name: answered as the robot cap is");
        assertEquals(List.of(new HubEvent.Warned("DNS beyond the address limit", swarm, "the robots registered from 10.0.0.1 hold 3"
                + " WSS ports as source, the most wss.maxPortsPerAddress allows; no new one for S2 -> T1:5000")), refused.events());
        assertTrue(refused.portActions().isEmpty());
        assertEquals(DnsOutcome.OK, capped.dns("S1", "T1", 5001, true, -1, now, new Changes()).outcome(),
                "a port it holds is answered still");
        assertEquals(DnsOutcome.OK, capped.dns("T1", "S1", 0, true, number++, now, new Changes()).outcome(),
                "another address is not affected");

        capped.beginLeaving("S1", s1);
        capped.left("S1", s1, now, new Changes());
        assertEquals(DnsOutcome.OK, capped.dns("S2", "T1", 0, true, number, now, new Changes()).outcome(),
                "the ports of a robot that left do not count against its address");
    }

    @Test
    void whenDescriptorsRunShortTheRememberedPortsOfTheRobotGoneLongestAreGivenBackFirstAndNeverAPresentRobots() {
        HubCore forever = new HubCore("TestModel", true, -1, 1000, Integer.MAX_VALUE, ShapingConfig.OFF); // -1: never forgotten by time, still given back
        RobotSession base = () -> { };
        forever.register(robot("Base", base, 5000), now, new Changes());
        List<String> gone = List.of("G1", "G2", "G3");
        int number = 40001;
        for (String name : gone) {
            RobotSession session = () -> { };
            forever.register(robot(name, session, 5000), now, new Changes());
            forever.dns(name, "Base", 0, true, number++, now, new Changes());
            forever.dns("Base", name, 0, true, number++, now, new Changes());
            forever.beginLeaving(name, session);
            Changes left = new Changes();
            forever.left(name, session, now, left);
            assertTrue(left.forgetLater().isEmpty(), "-1: no timer");
            now += SECOND;
        }
        RobotSession back = () -> { };
        forever.register(robot("G4", back, 5000), now, new Changes());
        forever.dns("G4", "Base", 0, true, number, now, new Changes());

        Changes first = new Changes();
        assertEquals(2, forever.giveBackRemembered(1, now, first), "a whole robot at a time: G1's two ports");
        assertEquals(List.of(Changes.PortWork.RELEASE, Changes.PortWork.RELEASE), works(first));
        assertTrue(first.portActions().stream().allMatch(action -> action.port().key.pair().contains("G1")), first.portActions().toString());
        assertTrue(first.events().contains(new HubEvent.Said(java.util.logging.Level.INFO, "ports given back",
                "descriptors ran short: gave back 2 remembered WSS ports of 1 robot that left, the longest gone first")), first.events().toString());

        Changes rest = new Changes();
        assertEquals(4, forever.giveBackRemembered(100, now, rest), "then G2's and G3's, and nothing of Base's or G4's");
        assertEquals(List.of(new PortKey("G4", "Base", 5000)), forever.ports().stream().map(port -> port.key).toList());
        assertEquals(0, forever.giveBackRemembered(100, now, new Changes()), "nothing left to give");
    }

    @Test
    void aDeclaredRobotIsTakenForAnInitAndAKickClosesItsConnectionsButKeepsItAndItsFixedPorts() {
        assertEquals(NameCheck.REGISTERED, core.declare(robot("A", sessionA, 5000), now, new Changes()));
        assertEquals(NameCheck.REGISTERED, core.declare(robot("B", sessionB, 6000), now, new Changes()));
        assertEquals(NameCheck.TAKEN, core.register(robot("A", () -> { }, 7000), now, new Changes()));
        PortKey key = new PortKey("A", "B", 6000);
        DnsResult fixed = core.fix(key, true, 40007, now, new Changes());
        assertTrue(fixed.numberUsed());
        assertTrue(core.isFixed(key));
        WssPort port = core.port(key);
        FakeConnection link = new FakeConnection(50000);
        port.addLink(link);
        Changes kick = new Changes();
        core.kick("B", now, kick);
        assertEquals(1, kick.closes().size(), "its connections close");
        assertTrue(kick.sessionsToClose().isEmpty());
        assertTrue(core.isRegistered("B"), "a declared robot stays");
        assertSame(port, core.port(key), "its fixed port too, with its number");
        assertEquals(40007, port.number);
    }

    @Test
    void aFixedUdpPortsPairHasItsTargetItsCountersAndItsConditions() {
        registerBoth();
        Admission relay = core.relay(new PortKey("A", "B", 6000), now, new Changes());
        assertNull(relay.refusal());
        assertEquals(6000, relay.target().getPort());
        assertTrue(relay.up().get().passes());
        Changes broke = new Changes();
        core.breakPair(AB, now, broke);
        assertFalse(relay.up().get().passes(), "read live: broken");
        assertFalse(relay.down().get().passes());
        assertNotNull(core.relay(new PortKey("A", "Nobody", 1), now, new Changes()).refusal());
    }

    private void registerBoth() {
        assertEquals(NameCheck.REGISTERED, core.register(robot("A", sessionA, 5000), now, new Changes()));
        assertEquals(NameCheck.REGISTERED, core.register(robot("B", sessionB, 6000), now, new Changes()));
    }

    private WssPort registeredPort() {
        registerBoth();
        DnsResult result = core.dns("A", "B", 0, true, 40001, now, new Changes());
        WssPort port = core.port(result.key());
        assertNotNull(port);
        assertTrue(port.listening());
        return port;
    }

    private static RegisteredRobot robot(String name, RobotSession session, int port) {
        return new RegisteredRobot(name, LOOPBACK, List.of(port), session);
    }

    private static List<Changes.PortWork> works(Changes changes) {
        List<Changes.PortWork> works = new ArrayList<>();
        changes.portActions().forEach(action -> works.add(action.work()));
        return works;
    }

    private static final class FakeConnection implements Connection {
        private final int outgoingPort;
        private boolean closed;

        FakeConnection(int outgoingPort) {
            this.outgoingPort = outgoingPort;
        }

        @Override
        public int outgoingPort() {
            return outgoingPort;
        }

        @Override
        public boolean isEstablished() {
            return true;
        }

        @Override
        public boolean isClosed() {
            return closed;
        }

        @Override
        public void close(CloseReason reason) {
            closed = true;
        }
    }
}
