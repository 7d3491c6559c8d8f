package org.usarsim.wss.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.lang.reflect.Proxy;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.hub.HubSnapshot;
import org.usarsim.wss.hub.core.PairState;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.noop.NoopPropagationModel;

/** What the view gathers for the map from a snapshot and a model's query methods. */
class MapDataTest {

    private static HubSnapshot robots(List<HubSnapshot.PairEntry> pairs, String... names) {
        return new HubSnapshot(java.util.Arrays.stream(names).map(name -> new HubSnapshot.RobotEntry(name, "127.0.0.2", List.of())).toList(),
                List.of(), List.of(), pairs);
    }

    @Test
    void aModelWithoutPositionsListsEveryRobotWithoutOneAndEveryPairUp() {
        MapData map = MapData.gather(robots(List.of(), "A", "B", "C"), new NoopPropagationModel());
        assertEquals(List.of("A", "B", "C"), map.robots().stream().map(MapData.Robot::name).toList());
        map.robots().forEach(robot -> assertNull(robot.position(), robot.name()));
        assertEquals(List.of("A-B", "A-C", "B-C"), map.lines().stream().map(line -> line.first() + "-" + line.second()).toList());
        map.lines().forEach(line -> assertEquals(PairState.UP, line.state()));
        assertEquals(List.of(), map.walls());
        assertEquals(Double.NaN, map.cutoff());
    }

    @Test
    void thePairsOfTheSnapshotGiveTheLinesAndTheirStatesWhenItHasThem() {
        // Noop placing A and B: every other answer is Noop's.
        NoopPropagationModel noop = new NoopPropagationModel();
        Map<String, Position> at = Map.of("A", new Position(1, 2, 0), "B", new Position(4, 6, 0));
        PropagationModel placed = (PropagationModel) Proxy.newProxyInstance(getClass().getClassLoader(),
                new Class<?>[] {PropagationModel.class}, (proxy, method, args) -> switch (method.getName()) {
                    case "positionOf" -> Optional.ofNullable(at.get((String) args[0]));
                    case "rangeFor" -> 42.0;
                    default -> method.invoke(noop, args);
                });
        HubSnapshot.PairEntry forced = new HubSnapshot.PairEntry("A", "B", PairState.FORCED_DOWN, -60, 5, 0, 0, 0, 0, 0, 0, 0, 0, null);
        HubSnapshot.PairEntry gone = new HubSnapshot.PairEntry("A", "Gone", PairState.UP, -60, 5, 0, 0, 0, 0, 0, 0, 0, 0, null);
        MapData map = MapData.gather(robots(List.of(forced, gone), "A", "B", "C"), placed);
        assertEquals(new MapData.Robot("A", new Position(1, 2, 0), 42), map.robot("A"));
        assertNull(map.robot("C").position(), "C is listed beside the map");
        assertEquals(List.of("A-B FORCED_DOWN", "A-C UP", "B-C UP"),
                map.lines().stream().map(line -> line.first() + "-" + line.second() + " " + line.state()).toList(),
                "every pair of registered robots, in the hub's state where it has one; none with a robot that left");
    }
}
