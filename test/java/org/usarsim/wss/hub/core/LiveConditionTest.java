package org.usarsim.wss.hub.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.net.InetAddress;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.shaping.RateTable;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * A pair's live condition wakes the threads that follow it when, and only when, it changes
 * (issue 27: a raised rate reached a link only at the end of the wait it was in), with the new
 * condition readable by then: the cells a link gets from the core, changed by an operator's pins.
 */
class LiveConditionTest {

    private static final long NOW = TimeUnit.SECONDS.toNanos(1000);
    private static final RobotPair AB = RobotPair.of("A", "B");

    @Test
    void aChangedPinWakesEveryWatcherOfBothWaysOnceWithTheNewConditionReadable() {
        HubCore core = new HubCore("TestModel", true, 600, 1000, Integer.MAX_VALUE,
                new ShapingConfig(true, RateTable.parse("-72:54M,-87:6M"), 2, true));
        core.register(new RegisteredRobot("A", InetAddress.getLoopbackAddress(), List.of(5000), () -> { }), NOW, new Changes());
        core.register(new RegisteredRobot("B", InetAddress.getLoopbackAddress(), List.of(6000), () -> { }), NOW, new Changes());
        core.dns("A", "B", 0, true, 40001, NOW, new Changes());
        Admission link = core.relay(new PortKey("A", "B", 6000), NOW, new Changes());
        List<String> woken = new ArrayList<>();
        Runnable up = () -> woken.add("up at " + link.up().get().bitsPerSecond());
        Runnable down = () -> woken.add("down at " + link.down().get().bitsPerSecond());
        link.up().watch(up);
        link.down().watch(down);

        core.force(AB, Force.UP, new RatePin(1, 0), NOW, new Changes());
        assertEquals(List.of("up at 1", "down at 1"), woken, "each way woken once, the pinned rate readable");

        woken.clear();
        core.force(AB, Force.UP, new RatePin(1, 0), NOW, new Changes());
        assertEquals(List.of(), woken, "the same pin changes nothing and wakes nobody");

        core.force(AB, Force.UP, new RatePin(54_000_000, 0), NOW, new Changes());
        assertEquals(List.of("up at 54000000", "down at 54000000"), woken, "raised: woken again");

        woken.clear();
        link.up().unwatch(up);
        core.force(AB, Force.UP, new RatePin(54_000_000, 10), NOW, new Changes());
        assertEquals(List.of("down at 54000000"), woken, "a watcher that stopped is not woken; a new delay wakes the other");
        assertSame(link.up(), core.relay(new PortKey("A", "B", 6000), NOW, new Changes()).up(), "one cell per way, shared by the links");
    }
}
