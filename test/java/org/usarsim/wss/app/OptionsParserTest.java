package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** The command line read into {@link Options}, before anything runs; its mistakes through Main: CommandLineTest. */
class OptionsParserTest {

    @Test
    void noOptionServesFromTheDefaults() throws Exception {
        assertEquals(new Options.Serve(false, false, null), OptionsParser.parse());
    }

    @Test
    void theWindowWithAConfigAndStart() throws Exception {
        assertEquals(new Options.Serve(false, true, Path.of("a.properties")),
                OptionsParser.parse("--config", "a.properties", "--start"));
    }

    @Test
    void theWorldServerGetsItsDefaultPortAndAddress() throws Exception {
        assertEquals(new Options.World(Path.of("a.world"), Defaults.WORLD_PORT, Defaults.ALL_INTERFACES, -1, 20),
                OptionsParser.parse("--world", "a.world"), "no rosbridge unless asked; its publishers at 20 Hz");
        assertEquals(new Options.World(Path.of("a.world"), 0, "127.0.0.1", -1, 20),
                OptionsParser.parse("--bind", "127.0.0.1", "--port", "0", "--world", "a.world"));
        assertEquals(new Options.World(Path.of("a.world"), Defaults.WORLD_PORT, Defaults.ALL_INTERFACES, 9090, 20),
                OptionsParser.parse("--world", "a.world", "--rosbridge", "9090"));
        assertEquals(5, ((Options.World) OptionsParser.parse("--world", "a.world", "--rosbridge", "0", "--ros-rate", "5")).rosRate());
        assertEquals(0.5, ((Options.World) OptionsParser.parse("--world", "a.world", "--rosbridge", "0", "--ros-rate", "0.5")).rosRate());
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
        assertEquals(new Options.ExportWorld(Path.of("run.rec"), Path.of("run.world")),
                OptionsParser.parse("--export-world", "run.rec", "--out", "run.world"));
    }

    /** As before the parser: --version and --help end the reading; what follows them is not looked at. */
    @Test
    void versionAndHelpStopTheReading() throws Exception {
        assertEquals(new Options.Version(), OptionsParser.parse("--headless", "--version", "--no-such"));
        assertEquals(new Options.Help(), OptionsParser.parse("-h", "--start", "--headless"));
        assertThrows(OptionsParser.Mistake.class, () -> OptionsParser.parse("--no-such", "--version"));
    }

    @Test
    void theLastOfARepeatedOptionCounts() throws Exception {
        assertEquals(new Options.Serve(false, false, Path.of("b.properties")),
                OptionsParser.parse("--config", "a.properties", "--config", "b.properties"));
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

    @Test
    void attachTakesAUrlATokenFileAndACertificateAndNothingElse() throws Exception {
        assertEquals(new Options.Attach("https://wss.lan:8443", Path.of("t"), Path.of("c.pem")),
                OptionsParser.parse("--attach", "https://wss.lan:8443", "--token-file", "t", "--trust-cert", "c.pem"));
        assertEquals(new Options.Attach("http://127.0.0.1:9000", null, null), OptionsParser.parse("--attach", "http://127.0.0.1:9000"));
        assertTrue(assertThrows(OptionsParser.Mistake.class, () -> OptionsParser.parse("--attach", "https://a:1", "--start"))
                .getMessage().startsWith("--attach only opens a window attached to a running WSS"));
        assertTrue(assertThrows(OptionsParser.Mistake.class, () -> OptionsParser.parse("--token-file", "t"))
                .getMessage().startsWith("--token-file and --trust-cert are for the window --attach opens"));
        assertTrue(assertThrows(OptionsParser.Mistake.class, () -> OptionsParser.parse("--attach", "wss.lan:8443"))
                .getMessage().startsWith("--attach wss.lan:8443 is not a monitor's URL"));
        assertTrue(assertThrows(OptionsParser.Mistake.class, () -> OptionsParser.parse("--attach", "https://TOKEN@wss.lan"))
                .getMessage().startsWith("--attach https://TOKEN@wss.lan is not"), "no token in the URL");
    }
}
