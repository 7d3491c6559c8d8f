package org.usarsim.wss.model.simulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.model.RobotPair;

class SimulatorRepliesTest {

    @Test
    void readsTheOriginalsExample() throws Exception {
        Map<String, ReportedRobot> robots = SimulatorReplies.positions("POSITIONS {Robots 2} "
                + "{Name Robot1 Location 1.2500,-3.0000,0.4500 BatteryEmpty False} "
                + "{Name Robot2 Location 10.0000,2.5000,0.4500 BatteryEmpty True}");
        assertEquals(List.of("Robot1", "Robot2"), List.copyOf(robots.keySet()));
        assertEquals(new ReportedRobot("Robot1", 1.25, -3, 0.45, false), robots.get("Robot1"));
        assertEquals(new ReportedRobot("Robot2", 10, 2.5, 0.45, true), robots.get("Robot2"));
    }

    @Test
    void toleratesWhitespaceUnknownFieldsAndAMissingBatteryFlag() throws Exception {
        Map<String, ReportedRobot> robots = SimulatorReplies.positions(
                "  POSITIONS{Robots 1}   {  Name R  Speed 3  Location 1,2,3 }  ");
        assertEquals(new ReportedRobot("R", 1, 2, 3, false), robots.get("R"));
        assertEquals(Map.of(), SimulatorReplies.positions("POSITIONS {Robots 0}"));
    }

    @ParameterizedTest
    @ValueSource(strings = {
        "POSITIONS",
        "POSITIONS {Robots}",
        "POSITIONS {Robots x}",
        "POSITIONS {Robots 2} {Name A Location 1,2,3}",
        "POSITIONS {Robots 1} {Name A Location 1,2}",
        "POSITIONS {Robots 1} {Name A Location 1,2,x}",
        "POSITIONS {Robots 1} {Name A Location 1,2,NaN}",
        "POSITIONS {Robots 1} {Name A}",
        "POSITIONS {Robots 1} {Location 1,2,3}",
        "POSITIONS {Robots 1} {Name A Location 1,2,3 BatteryEmpty Maybe}",
        "POSITIONS {Robots 1} {Name A Location}",
        "POSITIONS {Robots 2} {Name A Location 1,2,3} {Name A Location 1,2,3}",
        "POSITIONS {Robots 1} {Name A Location 1,2,3",
        "POSITIONS {Robots 1} {Name {A} Location 1,2,3}",
        "POSITIONS {Robots 1} stray {Name A Location 1,2,3}",
        "POSITIONS {Robots 1} {Name A Location 1,2,3} {}",
        "POSITIONS {Robots 1} {Name A Location 1,2,3}}",
        "POSITIONS} {Robots 0}",
        "NUMOBS {From A} {To B} {ObstCount 1}",
    })
    void rejectsMalformedPositions(String line) {
        SimulatorReplyException e = assertThrows(SimulatorReplyException.class, () -> SimulatorReplies.positions(line));
        assertTrue(e.getMessage().startsWith("malformed reply ("), e.getMessage());
        assertTrue(e.getMessage().endsWith(line), e.getMessage());
    }

    @Test
    void readsObstacleCountsForTheUnorderedPair() throws Exception {
        assertEquals(new SimulatorReplies.ObstacleCount(RobotPair.of("A", "B"), 3),
                SimulatorReplies.obstacles("NUMOBS {From B} {To A} {ObstCount 3.0000}"));
        assertTrue(Double.isNaN(SimulatorReplies.obstacles("NUMOBS {From A} {To B} {ObstCount -1.0000}").count()));
        assertThrows(SimulatorReplyException.class, () -> SimulatorReplies.obstacles("NUMOBS {From A} {ObstCount 1}"));
        assertThrows(SimulatorReplyException.class, () -> SimulatorReplies.obstacles("NUMOBS {From A} {To B} {ObstCount many}"));
    }

    @Test
    void theTypeIsTheFirstWord() {
        assertEquals("POSITIONS", SimulatorReplies.type("POSITIONS{Robots 0}"));
        assertEquals("NUMOBS", SimulatorReplies.type(" NUMOBS {From A}"));
        assertEquals("garbage", SimulatorReplies.type("garbage"));
    }
}
