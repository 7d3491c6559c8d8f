package org.usarsim.wss.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class WorldFileTest {

    @TempDir
    Path dir;

    @Test
    void theExamplesParse() throws Exception {
        World corridor = WorldFile.read(Path.of("docs/examples/corridor.world"));
        assertEquals(2, corridor.robotCount());
        assertEquals(4, corridor.wallCount());
        assertEquals(List.of("Base", "Scout"), names(corridor.at(0)));

        World building = WorldFile.read(Path.of("docs/examples/building.world"));
        assertEquals(4, building.robotCount());
        assertEquals(10, building.wallCount());
        assertEquals(List.of("Operator", "Explorer", "Mapper", "Scout"), names(building.at(0)));
    }

    @Test
    void everyStatementWithCommentsBlankLinesAndTabs() throws Exception {
        World world = WorldFile.parse("test.world", List.of(
                "# a world",
                "",
                "   ",
                "robot Base 1.25,-3,0.45   # stands still",
                "robot\tScout\t0,0,0\tbattery\t90",
                "robot Drone -1e1,+2.,.5 battery 0",
                "path Scout speed 2 once 10,0 10,10,4",
                "path Drone speed 0.5 loop -10,10",
                "wall 0,-1 0,1",
                "wall -5.5,2 5.5,2 # another",
                "#wall 100,100 200,200"));
        assertEquals(3, world.robotCount());
        assertEquals(2, world.wallCount());
        Snapshot start = world.at(0);
        assertEquals(new Point(1.25, -3, 0.45), start.robot("Base").orElseThrow().position());
        assertEquals(new Point(0, 0, 0), start.robot("Scout").orElseThrow().position());
        assertEquals(new Point(-10, 2, 0.5), start.robot("Drone").orElseThrow().position());
        assertTrue(start.robot("Drone").orElseThrow().batteryEmpty(), "battery 0: empty at once");
        assertFalse(start.robot("Scout").orElseThrow().batteryEmpty());
        assertEquals(List.of(new Wall(0, -1, 0, 1), new Wall(-5.5, 2, 5.5, 2)), start.walls());

        // Scout: 10 m, then sqrt(10^2 + 4^2) m, at 2 m/s: at its last waypoint after 10.4 s.
        Snapshot later = world.at(11);
        assertEquals(new Point(10, 10, 4), later.robot("Scout").orElseThrow().position(), "once: the last waypoint, with its own z");
        assertFalse(later.robot("Scout").orElseThrow().batteryEmpty(), "battery 90: not yet");
        assertTrue(world.at(90).robot("Scout").orElseThrow().batteryEmpty(), "battery 90: empty after 90 s");
        // Drone: 8 m to (-10,10) and 8 m back at 0.5 m/s, a lap of 32 s.
        assertEquals(new Point(-10, 7.5, 0.5), later.robot("Drone").orElseThrow().position(), "an x,y waypoint keeps the start's z");
        assertEquals(new Point(-10, 2, 0.5), world.at(32).robot("Drone").orElseThrow().position(), "loop: back at the start");
        assertEquals(new Point(-10, 8, 0.5), world.at(44).robot("Drone").orElseThrow().position(), "and off again");
    }

    @Test
    void anEmptyFileIsAnEmptyWorld() throws Exception {
        World world = WorldFile.parse("empty.world", List.of());
        assertEquals(0, world.robotCount());
        assertEquals(0, world.wallCount());
    }

    /** Each mistake: the message names the source, the line number, what is wrong, and quotes the line. */
    @ParameterizedTest(name = "[{index}] {0}")
    @CsvSource(delimiter = '|', value = {
        "robt A 1,2,3                       | unknown statement 'robt'",
        "Robot A 1,2,3                      | unknown statement 'Robot'",
        "robot R                            | a robot is 'robot NAME X,Y,Z'",
        "robot R 1,2,3 battery              | a robot is 'robot NAME X,Y,Z'",
        "robot R 1,2                        | expected the start position X,Y,Z",
        "robot R 1,2,3,4                    | expected the start position X,Y,Z",
        "robot R 1, 2, 3                    | (numbers separated by commas, no spaces), found '1,'",
        "robot R 1,two,3                    | 'two' is not a number, in the start position X,Y,Z",
        "robot R 1,,3                       | '' is not a number",
        "robot R NaN,0,0                    | 'NaN' is not a number",
        "robot R Infinity,0,0               | 'Infinity' is not a number",
        "robot R 1e999,0,0                  | '1e999' is not a number",
        "robot R 1d,0,0                     | '1d' is not a number",
        "robot R 0x10,0,0                   | '0x10' is not a number",
        "robot {R} 1,2,3                    | a robot name cannot contain { or }: {R}",
        "robot R 1,2,3 batery 5             | expected 'battery', found 'batery'",
        "robot R 1,2,3 battery -1           | the battery life must be 0 seconds or more: -1",
        "robot R 1,2,3 battery soon         | 'soon' is not a number, in the battery life in seconds",
        "path B speed 1 loop 1,1            | a path for B, which is no robot declared above",
        "path A speed 1 loop                | with at least one waypoint",
        "path A sped 1 loop 1,1             | expected 'speed', found 'sped'",
        "path A speed 0 loop 1,1            | the speed must be above 0 metres per second: 0",
        "path A speed -2 loop 1,1           | the speed must be above 0 metres per second: -2",
        "path A speed fast loop 1,1         | 'fast' is not a number, in the speed in metres per second",
        "path A speed 1 forever 1,1         | expected loop or once, found 'forever'",
        "path A speed 1 once 1              | expected a waypoint X,Y or X,Y,Z",
        "path A speed 1 once 1,1 2,2,2,2    | expected a waypoint X,Y or X,Y,Z",
        "at B 1 1,1                         | a timed point for B, which is no robot declared above",
        "at A 1                             | a timed point is 'at NAME SECONDS X,Y[,Z]'",
        "at A 1 1,1 2,2                     | a timed point is 'at NAME SECONDS X,Y[,Z]'",
        "at A -1 1,1                        | the time must be 0 seconds or more: -1",
        "at A soon 1,1                      | 'soon' is not a number, in the time in seconds",
        "at A 1 1                           | expected the point X,Y or X,Y,Z",
        "at A 1 1,1,1,1                     | expected the point X,Y or X,Y,Z",
        "wall 0,0                           | a wall is 'wall X1,Y1 X2,Y2'",
        "wall 0,0 1,1 2,2                   | a wall is 'wall X1,Y1 X2,Y2'",
        "wall 0,0,0 1,1                     | expected the wall's first end X1,Y1",
        "wall 0,0 1,x                       | 'x' is not a number, in the wall's second end X2,Y2",
        "wall 3,4 3,4                       | a wall of length 0",
    })
    void mistakes(String badLine, String what) {
        WorldFileException e = assertThrows(WorldFileException.class,
                () -> WorldFile.parse("my.world", List.of("# line 1", "robot A 0,0,0", "", badLine, "robot Z 0,0,0")));
        String message = e.getMessage();
        assertTrue(message.startsWith("my.world:4: "), "file and line first: " + message);
        assertTrue(message.contains(what), "says '" + what + "': " + message);
        assertTrue(message.endsWith(" (" + badLine.strip() + ")"), "quotes the line: " + message);
        assertFalse(message.contains("\n"), "one line: " + message);
    }

    @Test
    void aSecondRobotOfTheSameName() {
        WorldFileException e = assertThrows(WorldFileException.class,
                () -> WorldFile.parse("w", List.of("robot A 0,0,0", "robot B 0,0,0", "robot A 1,1,1")));
        assertEquals("w:3: a second robot named A (robot A 1,1,1)", e.getMessage());
    }

    @Test
    void aSecondPathForOneRobot() {
        WorldFileException e = assertThrows(WorldFileException.class,
                () -> WorldFile.parse("w", List.of("robot A 0,0,0", "path A speed 1 loop 1,1", "path A speed 2 once 2,2")));
        assertEquals("w:3: A already has a path, on line 2 (path A speed 2 once 2,2)", e.getMessage());
    }

    @Test
    void aPathBeforeItsRobot() {
        WorldFileException e = assertThrows(WorldFileException.class,
                () -> WorldFile.parse("w", List.of("path A speed 1 loop 1,1", "robot A 0,0,0")));
        assertEquals("w:1: a path for A, which is no robot declared above (path A speed 1 loop 1,1)", e.getMessage());
    }

    @Test
    void timedPointsMoveARobotLinearlyInTimeFromItsStartToItsLastPoint() throws Exception {
        World world = WorldFile.parse("w", List.of(
                "robot A 0,0,1",
                "robot B 5,5,0",
                "at A 2 0,0",         // an X,Y point keeps the start's z
                "at B 0 5,5,0",
                "at A 4 10,0,3",
                "at B 10 5,5,0",      // B stands still: two points
                "at A 4.5 10,5"));
        assertEquals(new Point(0, 0, 1), position(world, 0, "A"), "before the first point: the start");
        assertEquals(new Point(0, 0, 1), position(world, 2, "A"), "at a point's time: the point");
        assertEquals(new Point(5, 0, 2), position(world, 3, "A"), "half way in time, half way in space");
        assertEquals(new Point(10, 0, 3), position(world, 4, "A"));
        assertEquals(new Point(10, 2.5, 2), position(world, 4.25, "A"), "faster on a shorter leg: the times count");
        assertEquals(new Point(10, 5, 1), position(world, 4.5, "A"));
        assertEquals(new Point(10, 5, 1), position(world, 1000, "A"), "after the last point it stays");
        assertEquals(new Point(5, 5, 0), position(world, 7, "B"));
    }

    @Test
    void timedPointsStartFromTheRobotsStartBeforeTheFirstTime() throws Exception {
        World world = WorldFile.parse("w", List.of("robot A 0,0,0", "at A 10 10,0"));
        assertEquals(new Point(0, 0, 0), position(world, 9.999, "A"), "no move before the first point: it jumps there at its time");
        assertEquals(new Point(10, 0, 0), position(world, 10, "A"));
    }

    @Test
    void theTimesOfARobotsPointsMustGrow() {
        WorldFileException e = assertThrows(WorldFileException.class,
                () -> WorldFile.parse("w", List.of("robot A 0,0,0", "robot B 0,0,0", "at A 1 1,1", "at B 0.5 1,1", "at A 1 2,2")));
        assertEquals("w:5: the times of A's points must grow: 1 s is not after 1 s (at A 1 2,2)", e.getMessage());
        e = assertThrows(WorldFileException.class,
                () -> WorldFile.parse("w", List.of("robot A 0,0,0", "at A 2.5 1,1", "at A 0.5 2,2")));
        assertEquals("w:3: the times of A's points must grow: 0.5 s is not after 2.5 s (at A 0.5 2,2)", e.getMessage());
    }

    @Test
    void aRobotFollowsAPathOrTimedPointsNotBoth() {
        WorldFileException e = assertThrows(WorldFileException.class,
                () -> WorldFile.parse("w", List.of("robot A 0,0,0", "path A speed 1 loop 1,1", "at A 1 1,1")));
        assertEquals("w:3: A already has a path, on line 2: a robot follows a path or timed points, not both (at A 1 1,1)", e.getMessage());
        e = assertThrows(WorldFileException.class,
                () -> WorldFile.parse("w", List.of("robot A 0,0,0", "at A 1 1,1", "path A speed 1 loop 1,1")));
        assertEquals("w:3: A already has timed points ('at', from line 2): a robot follows a path or timed points, not both"
                + " (path A speed 1 loop 1,1)", e.getMessage());
    }

    private static Point position(World world, double seconds, String robot) {
        return world.at(seconds).robot(robot).orElseThrow().position();
    }

    @Test
    void theFirstMistakeIsTheOneReported() {
        WorldFileException e = assertThrows(WorldFileException.class,
                () -> WorldFile.parse("w", List.of("wall 0,0 0,0", "robot A")));
        assertTrue(e.getMessage().startsWith("w:1: "), e.getMessage());
    }

    @Test
    void fileErrorsNameTheFile() throws Exception {
        Path bad = dir.resolve("bad.world");
        Files.writeString(bad, "robot A 0,0,0\nrobot A 0,0,0\n", StandardCharsets.UTF_8);
        assertEquals(bad + ":2: a second robot named A (robot A 0,0,0)",
                assertThrows(WorldFileException.class, () -> WorldFile.read(bad)).getMessage());

        Path absent = dir.resolve("absent.world");
        assertEquals(absent + ": no such file", assertThrows(WorldFileException.class, () -> WorldFile.read(absent)).getMessage());

        Path binary = dir.resolve("binary.world");
        Files.write(binary, new byte[] {'r', (byte) 0xff, (byte) 0xfe, '\n'});
        assertEquals(binary + ": not UTF-8 text", assertThrows(WorldFileException.class, () -> WorldFile.read(binary)).getMessage());
    }

    @Test
    void windowsLineEndsAreFine() throws Exception {
        Path file = dir.resolve("crlf.world");
        Files.writeString(file, "robot A 0,0,0\r\nwall 0,0 1,1\r\n", StandardCharsets.UTF_8);
        assertEquals(1, WorldFile.read(file).robotCount());
    }

    private static List<String> names(Snapshot snapshot) {
        return snapshot.robots().stream().map(RobotAt::name).toList();
    }
}
