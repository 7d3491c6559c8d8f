package org.usarsim.wss.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.OptionalDouble;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class SegmentsTest {

    /** Robots' segment a-b against a wall c-d, both ways round and with each segment reversed: the answer must not change. */
    @ParameterizedTest(name = "[{index}] {8}")
    @CsvSource({
        // ax, ay, bx, by,   cx, cy, dx, dy, case,                                       meets
        "0, 0, 10, 0,   5, -1, 5, 1,       a proper crossing,                               true",
        "0, 0, 10, 10,  0, 10, 10, 0,      diagonals crossing,                              true",
        "0, 0, 10, 0,   5, 1, 5, 3,        the wall beside the line,                         false",
        "0, 0, 10, 0,   12, -1, 12, 1,     the wall beyond the end,                          false",
        "0, 0, 5, 0,    5, -1, 5, 1,       a robot standing on the wall,                     true",
        "0, 0, 10, 0,   5, 0, 5, 3,        the wall's end on the line (a T),                 true",
        "0, 0, 10, 0,   10, 0, 10, 3,      the wall's end on the robot (corner to corner),   true",
        "0, 0, 10, 0,   0, 1, 10, 1,       parallel 1 m apart,                              false",
        "0, 0, 10, 0,   0, 0.000001, 10, 0.000001, parallel within a micrometre,             true",
        "0, 0, 10, 0,   5, 0.00001, 5, 3,  the wall's end 10 micrometres off the line,       false",
        "0, 0, 10, 0,   2, 0, 8, 0,        collinear: the wall inside the segment,           true",
        "0, 0, 10, 0,   -5, 0, 20, 0,      collinear: the segment inside the wall,           true",
        "0, 0, 10, 0,   5, 0, 15, 0,       collinear: overlapping in part,                   true",
        "0, 0, 10, 0,   10, 0, 15, 0,      collinear: end to end,                            true",
        "0, 0, 10, 0,   11, 0, 15, 0,      collinear: apart,                                 false",
        "3, 0, 3, 0,    3, -1, 3, 1,       both robots at one point on the wall,             true",
        "3, 5, 3, 5,    3, -1, 3, 1,       both robots at one point off the wall,            false",
        "0.1, 0.2, 0.7, 0.4, 0.4, 0, 0.4, 1, a crossing at awkward decimals,                 true",
        "1e5, 1e5, 1e5, 1.0001e5, 0, 0, 2e5, 2e5, an end on a long diagonal far out,         true",
    })
    void meet(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy, String what, boolean meets) {
        assertEquals(meets, Segments.meet(ax, ay, bx, by, cx, cy, dx, dy), what);
        assertEquals(meets, Segments.meet(bx, by, ax, ay, dx, dy, cx, cy), what + ", both reversed");
        assertEquals(meets, Segments.meet(cx, cy, dx, dy, ax, ay, bx, by), what + ", swapped");
    }

    @Test
    void aRobotOnAWallAtAComputedPositionStillTouchesIt() {
        // 0.1 + 0.2 is not 0.3 in binary: the touch tolerance makes it count all the same.
        double x = 0.1 + 0.2;
        assertTrue(Segments.meet(x, 0, x, 5, 0.3, -1, 0.3, 1));
    }

    @Test
    void pointToSegmentDistance() {
        assertEquals(1, Segments.pointToSegment(5, 1, 0, 0, 10, 0), 1e-12, "above the middle");
        assertEquals(5, Segments.pointToSegment(13, 4, 0, 0, 10, 0), 1e-12, "beyond the end: to the end");
        assertEquals(5, Segments.pointToSegment(3, 4, 0, 0, 0, 0), 1e-12, "to a point");
    }

    @Test
    void countsEveryWallTheLineCrossesOrTouches() {
        List<Wall> walls = new ArrayList<>();
        for (int x = 1; x <= 9; x++) {
            walls.add(new Wall(x, -1, x, 1)); // nine walls across the line
        }
        walls.add(new Wall(2, 5, 10, 5)); // beside it
        walls.add(new Wall(10, 0, 12, 0)); // collinear: end to end with B
        walls.add(new Wall(-3, -3, -1, -1)); // behind A
        World world = new World(List.of(still("A", 0, 0), still("B", 10, 0), still("C", 0, 20)), walls);
        Snapshot now = world.at(0);
        assertEquals(10, now.obstacles("A", "B"));
        assertEquals(10, now.obstacles("B", "A"), "the same either way");
        assertEquals(0, now.obstacles("A", "C"));
        assertEquals(2, now.obstacles("B", "C"), "the wall at y = 5, crossed at x = 7.5, and the one B stands at the end of");
    }

    @Test
    void unknownRobotsHaveNoCount() {
        Snapshot now = new World(List.of(still("A", 0, 0)), List.of(new Wall(1, -1, 1, 1))).at(0);
        assertEquals(-1, now.obstacles("A", "Nobody"));
        assertEquals(-1, now.obstacles("Nobody", "A"));
        assertEquals(-1, now.obstacles("a", "A"), "names are case-sensitive");
        assertEquals(0, now.obstacles("A", "A"), "a robot and itself: a point, on no wall");
    }

    @Test
    void noWallsNoObstacles() {
        assertEquals(0, new World(List.of(still("A", 0, 0), still("B", 9, 9)), List.of()).at(0).obstacles("A", "B"));
    }

    private static WorldRobot still(String name, double x, double y) {
        return new WorldRobot(name, new Point(x, y, 0), null, OptionalDouble.empty());
    }

    @Test
    void wallBlocksUsesOnlyXAndY() {
        Wall wall = new Wall(5, -1, 5, 1);
        assertTrue(wall.blocks(new Point(0, 0, 0), new Point(10, 0, 100)), "heights do not matter");
        assertFalse(wall.blocks(new Point(0, 2, 0), new Point(10, 2, 0)));
    }
}
