package org.usarsim.wss.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/** The one parser of {@code WORD {Key Value} ...}, which the control protocol, the simulator client and the world server share. */
class SegmentParserTest {

    private static Command.Field field(String key, String value) {
        return new Command.Field(key, value);
    }

    private static SegmentException.Problem problem(String line) {
        return assertThrows(SegmentException.class, () -> SegmentParser.parse(line), line).problem();
    }

    @Test
    void theWordAndTheSegmentsInOrder() throws Exception {
        assertEquals(new Command("POSITIONS", List.of(field("Robots", "1"), field("Name", "R1 Location 1,2,3 BatteryEmpty False"))),
                SegmentParser.parse("POSITIONS {Robots 1} {Name R1 Location 1,2,3 BatteryEmpty False}"));
        assertEquals(new Command("GETOBS", List.of(field("To", "B"), field("From", "A"), field("To", "C"))),
                SegmentParser.parse("GETOBS {To B} {From A} {To C}"), "repeated keys are all kept, in order");
        assertEquals(new Command("GETPOS", List.of()), SegmentParser.parse("GETPOS"));
    }

    @Test
    void nothingIsMatchedOrChangedInCase() throws Exception {
        assertEquals(new Command("GetObs", List.of(field("from", "rObOt1"), field("TO", "B"))),
                SegmentParser.parse("GetObs {from rObOt1} {TO B}"));
    }

    @ParameterizedTest
    @ValueSource(strings = {
        "GETOBS {From A} {To B}",
        "  GETOBS   {From A}   {To B}  ",
        "GETOBS{From A}{To B}",
        "GETOBS\t{ From\tA }\u000B{\fTo  B\t}\r",
        "GETOBS\u001C{From\u001CA}\u2003{To\u3000B}",
    })
    void whitespaceIsJavasWhitespaceAndAnyAmountOfIt(String line) throws Exception {
        assertEquals(new Command("GETOBS", List.of(field("From", "A"), field("To", "B"))), SegmentParser.parse(line));
    }

    @Test
    void aValueIsEverythingAfterTheKeyStrippedAndMayBeEmpty() throws Exception {
        assertEquals(List.of(field("Robot", "R 1"), field("Port", ""), field("Port", "")),
                SegmentParser.parse("GETSS {Robot   R 1  } {Port} { Port  }").fields());
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "POSITIONS{Robots 0}  | POSITIONS",
        "  NUMOBS {From A}    | NUMOBS",
        "garbage              | garbage",
        "GETPOS}{x}           | GETPOS}",
        "{Robots 2}           | ''",
        "'\t'                 | ''",
        "''                   | ''",
    })
    void theWordEndsAtWhitespaceOrABrace(String line, String word) {
        assertEquals(word, SegmentParser.word(line));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "{Robot R1}              | NO_WORD",
        "''                      | NO_WORD",
        "' \t '                  | NO_WORD",
        "INIT} {Robot R1}        | TEXT_OUTSIDE_BRACES",
        "INIT Robot R1           | TEXT_OUTSIDE_BRACES",
        "INIT {Robot R1}}        | TEXT_OUTSIDE_BRACES",
        "INIT {Robot R1          | UNCLOSED_BRACE",
        "INIT {Robot {R1         | UNCLOSED_BRACE",
        "INIT {Robot {R1}}       | NESTED_BRACE",
        "INIT {}                 | EMPTY_SEGMENT",
        "INIT {Robot R1} { \t }  | EMPTY_SEGMENT",
        // The first problem from the left is the one named.
        "INIT {} {Robot R1       | EMPTY_SEGMENT",
        "INIT {} junk            | EMPTY_SEGMENT",
        "INIT junk {}            | TEXT_OUTSIDE_BRACES",
        "INIT {A {B}} {          | NESTED_BRACE",
        "INIT {A} x {B {C}}      | TEXT_OUTSIDE_BRACES",
    })
    void theFirstProblemFromTheLeft(String line, SegmentException.Problem expected) {
        assertEquals(expected, problem(line));
    }

    @Test
    void eachProblemHasAReasonOnAControlLineAndWordsForALog() {
        for (SegmentException.Problem problem : SegmentException.Problem.values()) {
            assertTrue(Replies.malformed(problem).startsWith("Malformed.Line."), problem.name());
            assertFalse(problem.description().isBlank(), problem.name());
        }
        assertEquals(Replies.MALFORMED_EMPTY_SEGMENT, Replies.malformed(SegmentException.Problem.EMPTY_SEGMENT));
    }
}
