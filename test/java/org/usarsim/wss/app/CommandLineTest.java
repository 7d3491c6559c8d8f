package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.usarsim.wss.Version;

/**
 * A bad command line or properties file, and --help, through {@link Main#run} in the test JVM:
 * the exit code and the lines written, before anything listens. Every config binds 127.0.0.1
 * and lets the OS choose the control port.
 */
class CommandLineTest {

    @TempDir
    Path dir;

    @ParameterizedTest
    @CsvSource({
        "wss.colour, blue",
        "wss.chunkSize, big",
        "distance.n, zero",
        "wss.model, NoSuchModel",
    })
    void badConfigExitsTwoBeforeBinding(String key, String value) throws Exception {
        MainRun server = MainRun.of("--headless", "--config", config(Map.of(key, value)).toString());
        assertEquals(2, server.exitCode(), "exit code; stderr: " + server.stderr());
        String error = server.stderr().strip();
        assertFalse(error.isEmpty(), "an error on standard error");
        assertFalse(error.contains("\n"), "a one-line error: " + error);
        assertTrue(error.contains(key), "names the key: " + error);
        assertTrue(error.contains(value), "names the value: " + error);
        assertTrue(server.stdoutLines().stream().noneMatch(line -> line.contains("listening")),
                "never listened: " + server.stdoutLines());
    }

    /** With the configured port held by someone else, a bad config still gives 2: checked before binding. */
    @Test
    void badModelIsReportedBeforeTheControlPortIsBound() throws Exception {
        try (ServerSocket taken = new ServerSocket(0, 50, InetAddress.getByName("127.0.0.1"))) {
            Map<String, String> overrides = new LinkedHashMap<>();
            overrides.put("wss.port", String.valueOf(taken.getLocalPort()));
            overrides.put("wss.model", "NoSuchModel");
            MainRun server = MainRun.of("--headless", "--config", config(overrides).toString());
            assertEquals(2, server.exitCode(), "exit code; stderr: " + server.stderr());
            assertTrue(server.stderr().contains("NoSuchModel"), server.stderr());
        }
    }

    @Test
    void versionPrintsThePomsVersionAndExitsZero() {
        MainRun run = MainRun.of("--version");
        assertEquals(0, run.exitCode(), run.stderr());
        assertEquals(List.of("wss " + Version.current()), run.stdoutLines());
        assertTrue(Version.current().matches("\\d+\\.\\d+\\.\\d+.*"), "the pom's version, filtered in: " + Version.current());
        assertTrue(MainRun.of("--help").stdoutLines().stream().anyMatch(line -> line.startsWith("  --version ")), "--help names it");
    }

    @Test
    void unknownArgumentExitsTwo() throws Exception {
        MainRun server = MainRun.of("--headless", "--verbose", "--config", config(Map.of()).toString());
        assertEquals(2, server.exitCode());
        assertTrue(server.stderr().contains("--verbose"), "names the argument: " + server.stderr());
        assertTrue(server.stderr().contains("usage"), "shows the usage: " + server.stderr());
        assertTrue(server.stdoutLines().isEmpty(), server.stdoutLines().toString());
    }

    @Test
    void configWithoutAFileExitsTwo() {
        MainRun server = MainRun.of("--headless", "--config");
        assertEquals(2, server.exitCode());
        assertTrue(server.stderr().contains("--config"), server.stderr());
    }

    @Test
    void missingConfigFileExitsTwo() {
        Path absent = dir.resolve("absent.properties");
        MainRun server = MainRun.of("--headless", "--config", absent.toString());
        assertEquals(2, server.exitCode());
        String error = server.stderr().strip();
        assertTrue(error.contains(absent.toString()), "names the file: " + error);
        assertFalse(error.contains("\n"), "a one-line error: " + error);
    }

    @Test
    void helpPrintsUsageAndExitsZero() {
        MainRun server = MainRun.of("--help");
        assertEquals(0, server.exitCode());
        assertTrue(String.join("\n", server.stdoutLines()).contains("usage"), server.stdoutLines().toString());
    }

    @Test
    void startWithHeadlessIsAMistake() {
        MainRun server = MainRun.of("--headless", "--start");
        assertEquals(2, server.exitCode());
        assertTrue(server.stderr().startsWith("wss: --start is for the window; headless, the server starts at once"), server.stderr());
    }

    @Test
    void helpNamesTheWindowAndStart() {
        MainRun server = MainRun.of("--help");
        assertEquals(0, server.exitCode());
        String help = String.join("\n", server.stdoutLines());
        assertTrue(help.contains("java -jar wss.jar [--config FILE] [--start]"), help);
        assertTrue(help.contains("--start             in the window, press Start at once"), help);
    }

    /** As the Debian package's launcher runs it: the usage says wss, the docs are where the package puts them. */
    @Test
    void helpOfTheInstalledCommandNamesWssAndTheInstalledDocs() {
        String help = Main.help("wss", "/usr/share/doc/wss/");
        assertTrue(help.startsWith("usage: wss [--config FILE] [--start]\n       wss --headless [--config FILE]\n"), help);
        assertTrue(help.contains("(/usr/share/doc/wss/gui.md)"), help);
        assertTrue(help.contains("properties of --config FILE (/usr/share/doc/wss/headless.md)"), help);
        assertFalse(help.contains("java -jar"), help);
        assertFalse(help.contains(" docs/") || help.contains("(docs/"), help);
    }

    /** The log went to run's own stream while it ran; the root logger is as it was when it returns. */
    @Test
    void aRunThatEndsEarlyLeavesTheRootLoggerAsItWas() throws Exception {
        Logger root = Logger.getLogger("");
        List<Handler> handlers = List.of(root.getHandlers());
        Level level = root.getLevel();
        MainRun server = MainRun.of("--headless", "--config", config(Map.of("wss.logLevel", "FINE", "distance.n", "zero")).toString());
        assertEquals(2, server.exitCode(), "exit code; stderr: " + server.stderr());
        assertEquals(handlers, List.of(root.getHandlers()));
        assertEquals(level, root.getLevel());
    }

    /** A config binding 127.0.0.1 on a port of the OS's choosing, with these overrides. */
    private Path config(Map<String, String> overrides) throws IOException {
        return ServerProcess.config(dir, overrides);
    }
}
