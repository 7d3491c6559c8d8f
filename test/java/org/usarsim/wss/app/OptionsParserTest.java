package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.app.Options.Action;

/** The command line read into {@link Options}, before anything runs; its mistakes through Main: CommandLineTest. */
class OptionsParserTest {

    @Test
    void noOptionServesFromTheDefaults() throws Exception {
        assertEquals(new Options(Action.SERVE, false, false, null, null, 0, null, null, null, -1), OptionsParser.parse());
    }

    @Test
    void theWindowWithAConfigAndStart() throws Exception {
        assertEquals(new Options(Action.SERVE, false, true, Path.of("a.properties"), null, 0, null, null, null, -1),
                OptionsParser.parse("--config", "a.properties", "--start"));
    }

    @Test
    void theWorldServerGetsItsDefaultPortAndAddress() throws Exception {
        Options options = OptionsParser.parse("--world", "a.world");
        assertEquals(Action.WORLD, options.action());
        assertEquals(Path.of("a.world"), options.world());
        assertEquals(Defaults.WORLD_PORT, options.port());
        assertEquals(Defaults.ALL_INTERFACES, options.bind());
        Options given = OptionsParser.parse("--bind", "127.0.0.1", "--port", "0", "--world", "a.world");
        assertEquals(0, given.port());
        assertEquals("127.0.0.1", given.bind());
        assertEquals(-1, given.rosbridge(), "no rosbridge unless asked");
        assertEquals(9090, OptionsParser.parse("--world", "a.world", "--rosbridge", "9090").rosbridge());
        assertEquals(20, given.rosRate(), "the rosbridge publishers' rate");
        assertEquals(5, OptionsParser.parse("--world", "a.world", "--rosbridge", "0", "--ros-rate", "5").rosRate());
        assertEquals(0.5, OptionsParser.parse("--world", "a.world", "--rosbridge", "0", "--ros-rate", "0.5").rosRate());
    }

    @Test
    void rosbridgeIsTheWorldServersAndAPort() {
        assertTrue(assertThrows(OptionsParser.Mistake.class, () -> OptionsParser.parse("--rosbridge", "9090")).getMessage()
                .startsWith("--port, --bind and --rosbridge are for the world server: they need --world FILE\n"));
        assertTrue(assertThrows(OptionsParser.Mistake.class, () -> OptionsParser.parse("--world", "a.world", "--rosbridge", "ws"))
                .getMessage().startsWith("--rosbridge ws is not a port number from 0 to 65535"));
    }

    @Test
    void exportWorldWithItsOut() throws Exception {
        assertEquals(new Options(Action.EXPORT_WORLD, false, false, null, null, 0, null, Path.of("run.rec"), Path.of("run.world"), -1),
                OptionsParser.parse("--export-world", "run.rec", "--out", "run.world"));
    }

    /** As before the parser: --version and --help end the reading; what follows them is not looked at. */
    @Test
    void versionAndHelpStopTheReading() throws Exception {
        assertEquals(Action.VERSION, OptionsParser.parse("--headless", "--version", "--no-such").action());
        assertEquals(Action.HELP, OptionsParser.parse("-h", "--start", "--headless").action());
        assertThrows(OptionsParser.Mistake.class, () -> OptionsParser.parse("--no-such", "--version"));
    }

    @Test
    void theLastOfARepeatedOptionCounts() throws Exception {
        assertEquals(Path.of("b.properties"), OptionsParser.parse("--config", "a.properties", "--config", "b.properties").config());
    }

    @Test
    void aMissingValueNamesTheOptionAndShowsTheUsage() {
        OptionsParser.Mistake mistake = assertThrows(OptionsParser.Mistake.class, () -> OptionsParser.parse("--out"));
        assertTrue(mistake.getMessage().startsWith("--out needs a file\nusage: "), mistake.getMessage());
    }

    @Test
    void theHelpListsEveryOptionInItsColumn() {
        String help = OptionsParser.help(OptionsParser.COMMAND);
        assertTrue(help.startsWith(OptionsParser.USAGE + "\n  (no option)         open the WSS's window"), help);
        assertTrue(help.contains("\n  --export-world RUN.rec  write a world file"), help);
        assertTrue(help.contains("\n                      for this session\n  --world FILE        instead of the WSS"), help);
        assertTrue(help.endsWith("\n  --help, -h          print this and every property of --config FILE, and exit"), help);
    }
}
