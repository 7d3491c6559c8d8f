package org.usarsim.wss.hub.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.logging.Level;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * What a robot that left leaves behind, by the hub's rules with the clock moved by hand: its WSS
 * ports' numbers within wss.portMemory and given back after it; its pairs' time up. (Over real
 * sockets: PortMemoryTest, that the hub frees a forgotten port's number; LinkStatsTest.)
 */
class RobotGoneTest {

    private static final long SECOND = TimeUnit.SECONDS.toNanos(1);
    private static final long MILLISECOND = TimeUnit.MILLISECONDS.toNanos(1);

    private long now = 1_000 * SECOND;
    private int nextNumber = 40001;

    /** The core a hub with this wss.portMemory has (and the test configuration's other values). */
    private static HubCore core(int portMemorySeconds) {
        return new HubCore("TestModel", true, portMemorySeconds, 1000, Integer.MAX_VALUE, ShapingConfig.OFF);
    }

    @Test
    void aRobotBackWithinThePortMemoryGetsItsNumbersAndOneGoneLongerGivesThemBack() {
        HubCore core = core(1);
        register(core, "R2", 6000);
        RobotSession first = register(core, "R1", 5000);
        int toR1 = dns(core, "R2", "R1");
        int fromR1 = dns(core, "R1", "R2");
        Changes left = leave(core, "R1", first);
        assertEquals(List.of(new Changes.ForgetLater("R1", SECOND)), left.forgetLater());

        now += 500 * MILLISECOND;
        RobotSession back = register(core, "R1", 5000);
        assertEquals(toR1, dns(core, "R2", "R1"), "back within wss.portMemory: the same number");
        assertEquals(fromR1, dns(core, "R1", "R2"), "back within wss.portMemory: the same number");
        now += 500 * MILLISECOND;
        Changes firstTimer = new Changes();
        core.forgetIfGone("R1", now, firstTimer);
        assertTrue(firstTimer.portActions().isEmpty() && firstTimer.events().isEmpty(), "the first leave's timer: R1 is back");

        leave(core, "R1", back);
        Changes early = new Changes();
        core.forgetIfGone("R1", now + SECOND - MILLISECOND, early);
        assertTrue(early.portActions().isEmpty(), "not yet: " + early.portActions());
        Changes late = new Changes();
        core.forgetIfGone("R1", now + SECOND, late);
        assertEquals(List.of(Changes.PortWork.RELEASE, Changes.PortWork.RELEASE),
                late.portActions().stream().map(Changes.PortAction::work).toList(), "both numbers given back");
        assertEquals(List.of(toR1, fromR1).stream().sorted().toList(),
                late.portActions().stream().map(action -> action.port().number).sorted().toList());
        assertTrue(late.events().contains(new HubEvent.Said(Level.INFO, "forgotten WSS ports", "forgot 2 WSS ports of R1, gone for 1 s")),
                late.events().toString());
        assertTrue(core.ports().isEmpty(), "R2's port to R1 goes with R1's: " + core.ports());
        Changes r2 = new Changes();
        core.forgetIfGone("R2", now + 10 * SECOND, r2);
        assertTrue(r2.events().isEmpty(), "R2 is still here: only R1 was forgotten");
    }

    @Test
    void theTimeOneOfItsRobotsIsGoneIsNotTimeUpForAPair() {
        HubCore core = core(600);
        register(core, "A", 5000);
        RobotSession b = register(core, "B", 6000);
        dns(core, "A", "B");
        PairStats stats = stats(core, RobotPair.of("A", "B"));
        assertEquals(1.0, stats.upShare(now), 1e-9);

        now += 10 * SECOND;
        leave(core, "B", b);
        now += 30 * SECOND;
        assertEquals(0.25, stats.upShare(now), 1e-9, "up 10 s of 40");
        assertEquals(PairState.UP, stats.state(), "the state shown stays: the model did not break the pair");

        register(core, "B", 6000);
        now += 10 * SECOND;
        assertEquals(0.4, stats.upShare(now), 1e-9, "up again once B is back: 20 s of 50");
    }

    private RobotSession register(HubCore core, String name, int port) {
        RobotSession session = () -> { };
        assertEquals(NameCheck.REGISTERED, core.register(new RegisteredRobot(name, InetAddress.getLoopbackAddress(),
                List.of(port), session), now, new Changes()));
        return session;
    }

    /** A DNS from one robot to another's first port, with a number the hub bound for it: the port's number. */
    private int dns(HubCore core, String from, String to) {
        DnsResult result = core.dns(from, to, 0, true, nextNumber, now, new Changes());
        assertEquals(DnsOutcome.OK, result.outcome());
        if (result.numberUsed()) {
            nextNumber++;
        }
        return result.port();
    }

    private Changes leave(HubCore core, String name, RobotSession session) {
        assertFalse(core.beginLeaving(name, session) == null, name + "'s session");
        Changes left = new Changes();
        core.left(name, session, now, left);
        return left;
    }

    private static PairStats stats(HubCore core, RobotPair pair) {
        return core.pairStats(0).stream().filter(stats -> stats.pair.equals(pair)).findFirst().orElseThrow();
    }
}
