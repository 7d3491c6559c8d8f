package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.net.InetAddress;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.hub.core.DeclaredRobot;
import org.usarsim.wss.hub.core.FixedPort;
import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.hub.core.PortKey;
import org.usarsim.wss.hub.core.RatePin;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.shaping.RateTable;
import org.usarsim.wss.shaping.ShapingConfig;

/** The one way to build a {@link HubConfig}: its canonical constructor, then {@code with...} each changing one thing. */
class HubConfigTest {

    private static final InetAddress LOCAL = InetAddress.getLoopbackAddress();

    private static HubConfig config(Map<RobotPair, Force> forced, Set<InetAddress> operators) {
        return new HubConfig(LOCAL, 50000, 2048, 0, true, 600, 1000, HubConfig.MAX_PORTS_PER_ADDRESS, 30, operators, forced,
                Map.of(), ShapingConfig.OFF, FixedSetup.NONE);
    }

    @Test
    void theConstructorCopiesItsCollectionsAndKeepsTheForcedPairsInOrder() {
        Map<RobotPair, Force> forced = new LinkedHashMap<>();
        forced.put(RobotPair.of("C", "D"), Force.UP);
        forced.put(RobotPair.of("A", "B"), Force.DOWN);
        Set<InetAddress> operators = new HashSet<>(Set.of(LOCAL));
        HubConfig config = config(forced, operators);
        forced.clear();
        operators.clear();
        assertEquals(List.of(RobotPair.of("C", "D"), RobotPair.of("A", "B")), List.copyOf(config.forced().keySet()));
        assertEquals(Set.of(LOCAL), config.operators());
        assertThrows(UnsupportedOperationException.class, () -> config.forced().clear());
        assertThrows(NullPointerException.class, () -> new HubConfig(LOCAL, 0, 1, 0, true, 0, 1, 1, 0, Set.of(), Map.of(), Map.of(),
                null, FixedSetup.NONE));
    }

    @Test
    void eachWithChangesOnlyItsComponents() {
        HubConfig base = config(Map.of(), Set.of(LOCAL));
        HubConfig moved = base.withControlPort(0);
        assertEquals(0, moved.controlPort());
        assertEquals(base, moved.withControlPort(50000));

        HubConfig capped = base.withMaxPortsPerAddress(5);
        assertEquals(5, capped.maxPortsPerAddress());
        assertEquals(base, capped.withMaxPortsPerAddress(HubConfig.MAX_PORTS_PER_ADDRESS));

        ShapingConfig shaped = new ShapingConfig(true, RateTable.DEFAULT, 2, true);
        Map<RobotPair, RatePin> pins = Map.of(RobotPair.of("A", "B"), new RatePin(1_000_000, 50));
        HubConfig withShaping = base.withShaping(shaped, pins);
        assertEquals(List.of(shaped, pins), List.of(withShaping.shaping(), withShaping.pins()));
        assertEquals(base, withShaping.withShaping(ShapingConfig.OFF, Map.of()));

        FixedSetup setup = new FixedSetup(List.of(new DeclaredRobot("A", LOCAL), new DeclaredRobot("B", LOCAL)),
                List.of(new FixedPort(FixedPort.Transport.TCP, new PortKey("A", "B", 80), 8080)), 60);
        HubConfig fixed = base.withFixed(setup);
        assertEquals(setup, fixed.fixed());
        assertEquals(base, fixed.withFixed(FixedSetup.NONE));
    }
}
