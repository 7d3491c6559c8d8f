package org.usarsim.wss.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.List;
import java.util.Locale;
import java.util.OptionalDouble;
import java.util.function.Supplier;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class PositionProtocolTest {

    /** The example of the spec: Robot1 and Robot2, the second with an empty battery. */
    private static final Snapshot SPEC = new World(List.of(
            new WorldRobot("Robot1", new Point(1.25, -3, 0.45), null, OptionalDouble.empty()),
            new WorldRobot("Robot2", new Point(10, 2.5, 0.45), null, OptionalDouble.of(0))),
            List.of(new Wall(5, -10, 5, 10), new Wall(7, -10, 7, 10))).at(0);

    private static String answer(String line) {
        return PositionProtocol.answer(line, () -> SPEC);
    }

    @Test
    void getpos() {
        assertEquals("POSITIONS {Robots 2} {Name Robot1 Location 1.2500,-3.0000,0.4500 BatteryEmpty False}"
                + " {Name Robot2 Location 10.0000,2.5000,0.4500 BatteryEmpty True}", answer("GETPOS"));
    }

    @Test
    void getposWithNoRobots() {
        assertEquals("POSITIONS {Robots 0}", PositionProtocol.answer("GETPOS", () -> new World(List.of(), List.of()).at(0)));
    }

    @Test
    void metresHaveFourDecimalsWhateverTheLocaleAndNeverMinusZero() {
        Locale before = Locale.getDefault();
        Locale.setDefault(Locale.GERMANY);
        try {
            Snapshot odd = new World(List.of(new WorldRobot("R", new Point(1234567.123456, -0.00004, -1e-9), null, OptionalDouble.empty())),
                    List.of()).at(0);
            assertEquals("POSITIONS {Robots 1} {Name R Location 1234567.1235,0.0000,0.0000 BatteryEmpty False}",
                    PositionProtocol.positions(odd));
        } finally {
            Locale.setDefault(before);
        }
    }

    @Test
    void getobs() {
        assertEquals("NUMOBS {From Robot1} {To Robot2} {ObstCount 2.0000}", answer("GETOBS {From Robot1} {To Robot2}"));
        assertEquals("NUMOBS {From Robot2} {To Robot1} {ObstCount 2.0000}", answer("GETOBS {From Robot2} {To Robot1}"));
        assertEquals("NUMOBS {From Robot1} {To Robot1} {ObstCount 0.0000}", answer("GETOBS {From Robot1} {To Robot1}"));
    }

    @Test
    void getobsForAnUnknownRobotIsMinusOne() {
        assertEquals("NUMOBS {From Robot1} {To Nobody} {ObstCount -1.0000}", answer("GETOBS {From Robot1} {To Nobody}"));
        assertEquals("NUMOBS {From robot1} {To Robot2} {ObstCount -1.0000}", answer("GETOBS {From robot1} {To Robot2}"),
                "names are case-sensitive, and echoed as asked");
    }

    @ParameterizedTest
    @ValueSource(strings = {
        "GETOBS   {From Robot1}     {To Robot2}",
        "GETOBS {From Robot1} {To Robot2}   ",
        "  GETOBS {From Robot1} {To Robot2}",
        "GETOBS\t{From Robot1}\t{To Robot2}",
        "GETOBS{From Robot1}{To Robot2}",
        "GETOBS { From  Robot1 } {To Robot2 }",
        "GETOBS {To Robot2} {From Robot1}",
        "GETOBS {From Robot1} {Extra thing} {To Robot2}",
    })
    void getobsToleratesWhitespaceOrderAndExtraSegments(String line) {
        assertEquals("NUMOBS {From Robot1} {To Robot2} {ObstCount 2.0000}", answer(line));
    }

    @ParameterizedTest
    @ValueSource(strings = {
        "",
        "   ",
        "GETPOSX",
        "GETPO",
        "FOO",
        "GETSS {Robot Robot1}",
        "INIT {Robot R1} {Port 5000}",
        "GETOBS",
        "GETOBS {From Robot1}",
        "GETOBS {To Robot2}",
        "GETOBS {From} {To Robot2}",
        "GETOBS From Robot1 To Robot2",
        "GETOBS {From Robot1} {To Robot2",
        "GETOBS {From Robot1} junk {To Robot2}",
        "{Robots 2}",
        "\u0000\u0001\u00ff",
    })
    void everythingElseHasNoAnswer(String line) {
        Supplier<Snapshot> unused = () -> {
            throw new AssertionError("the world is not looked at for '" + line + "'");
        };
        assertNull(PositionProtocol.answer(line, unused), line);
    }

    @ParameterizedTest
    @ValueSource(strings = {"getpos", "GetPos", "gEtPoS {Robot Robot1}"})
    void getposInAnyCase(String line) {
        assertEquals(answer("GETPOS"), answer(line), "USARSim matches commands case-insensitively");
    }

    @ParameterizedTest
    @ValueSource(strings = {"getobs {From Robot1} {To Robot2}", "GetObs {From Robot1} {To Robot2}",
            "GETOBS {from Robot1} {TO Robot2}", "gEtObS {FROM Robot1} {to Robot2}"})
    void getobsInAnyCase(String line) {
        assertEquals("NUMOBS {From Robot1} {To Robot2} {ObstCount 2.0000}", answer(line));
    }

    @Test
    void getobsTakesTheFirstFromAndToThatHaveAValue() {
        assertEquals("NUMOBS {From Robot1} {To Robot2} {ObstCount 2.0000}",
                answer("GETOBS {From Robot1} {From Robot2} {To Robot2} {to Robot1}"));
        assertEquals("NUMOBS {From Robot1} {To Robot2} {ObstCount 2.0000}", answer("GETOBS {From} {From Robot1} {To Robot2}"));
    }

    /** The segment grammar the control protocol and the simulator client read too (protocol.SegmentParser). */
    @ParameterizedTest
    @ValueSource(strings = {
        "GETOBS {} {From Robot1} {To Robot2}",
        "GETOBS {From Robot1} {To {Robot2}",
        "GETOBS {From Robot1} {To Robot2}}",
        "GETOBS} {From Robot1} {To Robot2}",
    })
    void aGetobsThatBreaksTheSegmentGrammarHasNoAnswer(String line) {
        assertNull(PositionProtocol.answer(line, () -> {
            throw new AssertionError("the world is not looked at for '" + line + "'");
        }), line);
    }

    @Test
    void getposIgnoresWhatFollows() {
        assertEquals(answer("GETPOS"), answer("GETPOS {Robot Robot1}"));
        assertEquals(answer("GETPOS"), answer("  GETPOS  "));
    }
}
