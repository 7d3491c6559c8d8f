package org.usarsim.wss.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.OptionalDouble;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Motion and battery: the world as a pure function of elapsed seconds. */
class WorldTest {

    private static final double EXACT = 1e-9;

    /** From (0,0,0) at 2 m/s: 10 m east, then 5 m north; 7.5 s in all. */
    private static Route lShape(boolean loop) {
        return new Route(new Point(0, 0, 0), List.of(new Point(10, 0, 0), new Point(10, 5, 0)), 2, loop);
    }

    @ParameterizedTest(name = "once at t={0}")
    @CsvSource({
        "0,     0,  0",
        "1,     2,  0",
        "2.5,   5,  0",
        "5,     10, 0",
        "6,     10, 2",
        "7.5,   10, 5",
        "8,     10, 5",
        "1000,  10, 5",
    })
    void onceStopsAtTheLastWaypoint(double t, double x, double y) {
        assertAt(x, y, 0, lShape(false).at(t));
    }

    /** Looping adds the way back from (10,5) to the start: 5*sqrt(5) m, about 11.18 m, 5.59 s. */
    @ParameterizedTest(name = "loop at t={0}")
    @CsvSource({
        "0,      0,  0",
        "6,      10, 2",
        "7.5,    10, 5",
        "10.295084971874736, 5, 2.5",
        "13.090169943749473, 0, 0",
        "14.090169943749473, 2, 0",
        "19.090169943749473, 10, 2",
    })
    void loopGoesBackToTheStartAndRepeats(double t, double x, double y) {
        assertAt(x, y, 0, lShape(true).at(t));
    }

    @Test
    void manyLapsLater() {
        double lap = (15 + 5 * Math.sqrt(5)) / 2;
        assertAt(2, 0, 0, lShape(true).at(1000 * lap + 1), 1e-6);
    }

    @Test
    void heightChangesAlongTheWay() {
        Route ramp = new Route(new Point(0, 0, 0), List.of(new Point(3, 0, 4)), 1, false);
        assertAt(1.8, 0, 2.4, ramp.at(3));
        assertAt(3, 0, 4, ramp.at(5));
    }

    @Test
    void aWaypointRepeatedOrEqualToTheStartIsHarmless() {
        Route route = new Route(new Point(0, 0, 0), List.of(new Point(0, 0, 0), new Point(4, 0, 0), new Point(4, 0, 0)), 1, true);
        assertAt(0, 0, 0, route.at(0));
        assertAt(4, 0, 0, route.at(4));
        assertAt(2, 0, 0, route.at(6));
        assertAt(1, 0, 0, route.at(9));
        Route nowhere = new Route(new Point(1, 2, 3), List.of(new Point(1, 2, 3)), 1, true);
        assertAt(1, 2, 3, nowhere.at(12.5));
    }

    @Test
    void routesNeedAPositiveSpeed() {
        assertThrows(IllegalArgumentException.class, () -> new Route(new Point(0, 0, 0), List.of(new Point(1, 0, 0)), 0, false));
        assertThrows(IllegalArgumentException.class, () -> new Route(new Point(0, 0, 0), List.of(new Point(1, 0, 0)), Double.NaN, false));
    }

    @Test
    void batteryIsEmptyFromItsLifeOn() {
        WorldRobot robot = new WorldRobot("R", new Point(0, 0, 0), null, OptionalDouble.of(30));
        assertFalse(robot.at(0).batteryEmpty(), "at the start");
        assertFalse(robot.at(29.999).batteryEmpty(), "just before");
        assertTrue(robot.at(30).batteryEmpty(), "once 30 s have passed");
        assertTrue(robot.at(3000).batteryEmpty(), "and for ever after");
        assertTrue(new WorldRobot("R", new Point(0, 0, 0), null, OptionalDouble.of(0)).at(0).batteryEmpty(), "a life of 0: empty from the start");
        assertFalse(new WorldRobot("R", new Point(0, 0, 0), null, OptionalDouble.empty()).at(1e9).batteryEmpty(), "no battery life: never empty");
    }

    @Test
    void aRobotWithoutARouteStandsStill() {
        WorldRobot robot = new WorldRobot("R", new Point(1, 2, 3), null, OptionalDouble.empty());
        assertEquals(new Point(1, 2, 3), robot.at(0).position());
        assertEquals(new Point(1, 2, 3), robot.at(99).position());
    }

    @Test
    void snapshotsKeepFileOrderAndAreImmutable() {
        World world = new World(List.of(
                new WorldRobot("Zed", new Point(0, 0, 0), null, OptionalDouble.empty()),
                new WorldRobot("Alf", new Point(0, 0, 0), lShape(false), OptionalDouble.of(5))), List.of(new Wall(0, 1, 1, 1)));
        Snapshot at6 = world.at(6);
        assertEquals(List.of("Zed", "Alf"), at6.robots().stream().map(RobotAt::name).toList());
        assertAt(10, 2, 0, at6.robot("Alf").orElseThrow().position());
        assertTrue(at6.robot("Alf").orElseThrow().batteryEmpty());
        assertThrows(UnsupportedOperationException.class, () -> at6.robots().clear());
        assertThrows(UnsupportedOperationException.class, () -> at6.walls().clear());
        Snapshot at0 = world.at(0);
        assertAt(0, 0, 0, at0.robot("Alf").orElseThrow().position());
        assertFalse(at0.robot("Alf").orElseThrow().batteryEmpty());
        assertEquals(new Point(10, 2, 0), at6.robot("Alf").orElseThrow().position(), "an earlier snapshot does not change");
        assertEquals(2, world.robotCount());
        assertEquals(1, world.wallCount());
    }

    @Test
    void timeStartsAtZero() {
        World world = new World(List.of(), List.of());
        assertThrows(IllegalArgumentException.class, () -> world.at(-1));
        assertThrows(IllegalArgumentException.class, () -> world.at(Double.NaN));
        assertEquals(0, world.at(0).robots().size());
    }

    private static void assertAt(double x, double y, double z, Point actual) {
        assertAt(x, y, z, actual, EXACT);
    }

    private static void assertAt(double x, double y, double z, Point actual, double tolerance) {
        String where = "expected " + x + "," + y + "," + z + " but was " + actual;
        assertEquals(x, actual.x(), tolerance, where);
        assertEquals(y, actual.y(), tolerance, where);
        assertEquals(z, actual.z(), tolerance, where);
    }
}
