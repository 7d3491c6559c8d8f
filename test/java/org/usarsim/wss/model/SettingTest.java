package org.usarsim.wss.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The one rule of a declared setting, and the words it gives for what it expects. */
class SettingTest {

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "integer, from 1 to 10                 | a whole number from 1 to 10",
        "integer port, from 1 to 65535         | a port number from 1 to 65535",
        "integer ms, from 100 to 60000         | a whole number of milliseconds from 100 to 60000",
        "number                                | a number",
        "number dBm                            | a number (dBm)",
        "number, above 0                       | a number above 0",
        "number m, above 0                     | a number of metres above 0",
        "number dB, from 0                     | a number of dB, 0 or more",
        "number s, from 0                      | a number of seconds, 0 or more",
        "number, to 5                          | a number, 5 or less",
        "number, below 5                       | a number below 5",
        "number, above 0 below 0.5             | a number above 0 and below 0.5",
        "number, from 0 below 1                | a number, 0 or more and below 1",
    })
    void expectedSaysWhatAValueMustBe(String declaration, String words) {
        assertEquals(words, declared(declaration).expected());
    }

    /** "type [unit], [from A] [above A] [to B] [below B]", a small language for the cases above. */
    private static Setting declared(String declaration) {
        String[] halves = declaration.split(",", -1);
        String[] head = halves[0].strip().split(" ");
        Setting setting = head[0].equals("integer") ? Setting.integer("k", "K", 1) : Setting.number("k", "K", "1");
        if (head.length > 1) {
            setting = head[1].equals("port") ? setting.noun("a port number") : setting.unit(head[1]);
        }
        String[] range = halves.length > 1 ? halves[1].strip().split(" ") : new String[0];
        for (int i = 0; i + 1 < range.length; i += 2) {
            double bound = Double.parseDouble(range[i + 1]);
            setting = switch (range[i]) {
                case "from" -> setting.from(bound);
                case "above" -> setting.above(bound);
                case "to" -> setting.to(bound);
                default -> setting.below(bound);
            };
        }
        return setting;
    }

    @Test
    void integersInTheirRange() {
        Setting level = Setting.integer("x.level", "Level", 3).from(1).to(10);
        assertNull(level.problem("1"));
        assertNull(level.problem(" 10 "), "stripped");
        for (String bad : new String[] {"0", "11", "1.5", "", "one", "0x5", "1e1", "99999999999"}) {
            assertEquals("a whole number from 1 to 10", level.problem(bad), bad);
        }
        assertEquals("a whole number from 1 to 10", level.problem(null));
    }

    @Test
    void numbersAreFiniteAndTheBoundsExactAsDeclared() {
        Setting above = Setting.number("x", "X", "1").above(0).below(1);
        assertNull(above.problem("0.5"));
        assertEquals(above.expected(), above.problem("0"));
        assertEquals(above.expected(), above.problem("1"));
        Setting any = Setting.number("x", "X", "1");
        assertNull(any.problem("-1e300"));
        for (String bad : new String[] {"NaN", "Infinity", "-Infinity", "1e999", "2,5", ""}) {
            assertEquals("a number", any.problem(bad), bad);
        }
    }

    @Test
    void theOtherTypes() {
        assertNull(Setting.bool("b", "B", true).problem("FALSE"));
        assertEquals("true or false", Setting.bool("b", "B", true).problem("yes"));
        assertEquals("some text", Setting.text("t", "T", "x").problem("  "));
        assertEquals("a name", Setting.text("t", "T", "x").noun("a name").problem(""));
        assertNull(Setting.host("h", "H", "localhost").problem("sim.example.org"));
        assertEquals("a host name or IP address", Setting.host("h", "H", "localhost").problem("my host"));
        Setting level = Setting.choice("l", "L", "INFO", List.of("INFO", "FINE"));
        assertNull(level.problem("FINE"));
        assertEquals("one of INFO, FINE", level.problem("info"));
        Setting folder = Setting.directory("d", "D", "").orEmpty("none");
        assertNull(folder.problem(""));
        assertEquals("an existing directory (empty: none)", folder.problem("/no/such/folder/here"));
        assertEquals("an IP address of this machine (0.0.0.0: all)", Setting.address("a", "A", "0.0.0.0").note("0.0.0.0: all").expected());
    }

    @Test
    void refinementsMakeNewSettingsAndLeaveTheOldAlone() {
        Setting plain = Setting.integer("k", "Level", 3);
        Setting ranged = plain.from(1).to(10).unit("ms").help("how long");
        assertEquals("a whole number", plain.expected());
        assertEquals("", plain.help());
        assertEquals("Level", plain.labelWithUnit());
        assertEquals("Level (ms)", ranged.labelWithUnit());
        assertEquals("how long", ranged.help());
        assertEquals("3", ranged.defaultValue());
    }

    @Test
    void aDeclarationIsCheckedWhole() {
        Setting good = Setting.integer("x.a", "A", 1);
        assertNull(Setting.declarationProblem(List.of(good, Setting.number("x.b", "B", "2"))));
        assertEquals("setting x.a is declared twice", Setting.declarationProblem(List.of(good, good)));
        assertEquals("setting x.a: the default '1' is not a whole number from 2 to 3",
                Setting.declarationProblem(List.of(good.from(2).to(3))));
        assertEquals("setting wss.x: the wss.* keys are the server's", Setting.declarationProblem(List.of(Setting.text("wss.x", "X", "y"))));
        assertEquals("setting key 'a b' is blank or holds whitespace", Setting.declarationProblem(List.of(Setting.text("a b", "X", "y"))));
        assertEquals("settings() returned null", Setting.declarationProblem(null));
        assertEquals(Map.of("x.a", "1"), Setting.defaults(List.of(good)));
    }
}
