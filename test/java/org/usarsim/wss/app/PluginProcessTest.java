package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.usarsim.wss.hub.Sockets.readLine;
import static org.usarsim.wss.hub.Sockets.send;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.model.PluginJars;

/**
 * Model plugins in the real server process: from the folder named by wss.pluginDir, and from the
 * plugins/ folder beside wss.jar when run with {@code java -jar}. The settings a plugin's
 * presence decides are checked through Main.run in the test JVM (exit 2 before anything runs).
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
@Tag("slow")
class PluginProcessTest {

    @TempDir
    static Path compiled;

    private static Path classes;

    @TempDir
    Path dir;

    private final List<ServerProcess> servers = new ArrayList<>();
    private final List<Socket> sockets = new ArrayList<>();

    @BeforeAll
    static void compilePlugins() throws IOException {
        classes = PluginJars.compile(compiled);
    }

    @AfterEach
    void stopEverything() throws Exception {
        for (Socket socket : sockets) {
            socket.close();
        }
        for (ServerProcess server : servers) {
            server.kill();
        }
    }

    @Test
    void aPluginFromPluginDirIsSelectedAndAnswers() throws Exception {
        Path plugins = dir.resolve("my plugins");
        Path jar = PluginJars.fixedStrengthJar(plugins.resolve("fixed.jar"), classes);
        ServerProcess server = start(List.of("-cp", PluginJars.serverClasses().toString(), Main.class.getName()),
                config("wss.pluginDir = " + plugins, "wss.model = FixedStrength"));

        Matcher listening = server.awaitListening();
        assertEquals("FixedStrength", listening.group(2));
        assertTrue(server.stdoutSoFar().stream().anyMatch(line -> line.endsWith("INFO loaded propagation model FixedStrength from " + jar)),
                server.stdoutSoFar().toString());
        assertStrength(Integer.parseInt(listening.group(1)), "-42.5");
    }

    @Test
    void aPluginBesideWssJarIsSelectedAndAnswersEvenNextToABrokenOne() throws Exception {
        Path app = dir.resolve("app");
        Path wssJar = PluginJars.serverJar(app.resolve("wss.jar"));
        Path jar = PluginJars.fixedStrengthJar(app.resolve("plugins").resolve("fixed.jar"), classes);
        Path broken = PluginJars.jar(app.resolve("plugins").resolve("broken.jar"), classes, List.of("Base", "ConstructorThrows"),
                List.of("ConstructorThrows"));
        ServerProcess server = start(List.of("-jar", wssJar.toString()), config("wss.model = " + PluginJars.FIXED));

        Matcher listening = server.awaitListening();
        assertEquals("FixedStrength", listening.group(2));
        List<String> log = server.stdoutSoFar();
        assertTrue(log.stream().anyMatch(line -> line.endsWith("INFO loaded propagation model FixedStrength from " + jar)), log.toString());
        assertTrue(log.stream().anyMatch(line -> line.contains("WARNING skipping a propagation model in " + broken)
                && line.contains("the constructor fails")), log.toString());
        assertStrength(Integer.parseInt(listening.group(1)), "-42.5");
    }

    @Test
    void aPluginDirThatDoesNotExistExitsTwoBeforeBinding() throws Exception {
        Path absent = dir.resolve("no such folder");
        MainRun server = MainRun.of("--headless", "--config", config("wss.pluginDir = " + absent).toString());
        assertEquals(2, server.exitCode(), "stderr: " + server.stderr());
        String error = server.stderr().strip();
        assertFalse(error.contains("\n"), "a one-line error: " + error);
        assertTrue(error.contains("wss.pluginDir = '" + absent + "'"), "names the key and the value: " + error);
        assertTrue(server.stdoutLines().stream().noneMatch(line -> line.contains("listening")), server.stdoutLines().toString());
    }

    // ---- a plugin's settings ----

    @Test
    void aPluginsSettingsComeFromThePropertiesFile() throws Exception {
        Path plugins = dir.resolve("plugins");
        PluginJars.tunedJar(plugins.resolve("tuned.jar"), classes);
        Path config = config("wss.pluginDir = " + plugins, "wss.model = Tuned", "tuned.level = 5", "tuned.gain = 0.25 ",
                "usarsim.port = 7000");
        ServerProcess server = start(List.of("-cp", PluginJars.serverClasses().toString(), Main.class.getName()), config);

        Matcher listening = server.awaitListening();
        assertEquals("Tuned", listening.group(2));
        List<String> log = server.stdoutSoFar();
        assertTrue(log.stream().anyMatch(line -> line.endsWith("INFO Tuned configured with tuned.level 5, tuned.gain 0.25")),
                log.toString());
        assertTrue(log.stream().anyMatch(line -> line.endsWith("WARNING " + config + ": usarsim.port is not a setting of Tuned"
                + " (it is one of DistanceOnlyPropagationModel, ObstaclePropagationModel, RFComms): ignored")), log.toString());
        assertStrength(Integer.parseInt(listening.group(1)), "-50.25");
    }

    @Test
    void aPluginsDefaultsApplyWhenTheFileSetsNone() throws Exception {
        Path plugins = dir.resolve("plugins");
        PluginJars.tunedJar(plugins.resolve("tuned.jar"), classes);
        ServerProcess server = start(List.of("-cp", PluginJars.serverClasses().toString(), Main.class.getName()),
                config("wss.pluginDir = " + plugins, "wss.model = Tuned"));
        assertStrength(Integer.parseInt(server.awaitListening().group(1)), "-32.5");
    }

    @Test
    void aBadValueForAPluginsKeyExitsTwoBeforeBinding() throws Exception {
        Path plugins = dir.resolve("plugins");
        PluginJars.tunedJar(plugins.resolve("tuned.jar"), classes);
        MainRun server = MainRun.of("--headless", "--config",
                config("wss.pluginDir = " + plugins, "wss.model = Tuned", "tuned.level = 11").toString());
        assertEquals(2, server.exitCode(), "stderr: " + server.stderr());
        String error = server.stderr().strip();
        assertFalse(error.contains("\n"), "a one-line error: " + error);
        assertTrue(error.endsWith(": tuned.level = '11' is not a whole number from 1 to 10"), error);
        assertTrue(server.stdoutLines().stream().noneMatch(line -> line.contains("listening")), server.stdoutLines().toString());
    }

    @Test
    void aPluginsKeyWithoutThePluginIsAnUnknownKey() throws Exception {
        MainRun server = MainRun.of("--headless", "--config", config("tuned.gain = 1").toString());
        assertEquals(2, server.exitCode(), "stderr: " + server.stderr());
        String error = server.stderr().strip();
        assertFalse(error.contains("\n"), "a one-line error: " + error);
        assertTrue(error.contains("unknown key tuned.gain (value '1'); known keys: wss.port, "), error);
    }

    @Test
    void helpListsThePluginsSettings() throws Exception {
        Path app = dir.resolve("app");
        Path wssJar = PluginJars.serverJar(app.resolve("wss.jar"));
        PluginJars.tunedJar(app.resolve("plugins").resolve("tuned.jar"), classes);
        ServerProcess server = ServerProcess.startJava(List.of("-jar", wssJar.toString(), "--help"));
        servers.add(server);
        assertEquals(0, server.awaitExit(), "stderr: " + server.stderr());
        String help = String.join("\n", server.stdoutSoFar());
        assertTrue(help.contains("  wss.port = 50000\n      a port number from 0 to 65535 (0: any free port). "), help);
        assertTrue(help.contains("model Tuned:\n  tuned.level = 3\n      a whole number from 1 to 10. How many steps of 10 dB"), help);
        assertTrue(help.contains("  tuned.gain = 2.5\n      a number of dB, 0 or more. Taken off the level's strength"), help);
    }

    // ---- helpers ----

    /** Two robots register; B's strength as A sees it is the plugin's. */
    private void assertStrength(int port, String strength) throws Exception {
        Socket a = connect(port);
        Socket b = connect(port);
        send(a, "INIT {Robot A} {Port 5000}\r\n");
        assertEquals("INITREPLY {Status OK}\r\n", readLine(a));
        send(b, "INIT {Robot B} {Port 5001}\r\n");
        assertEquals("INITREPLY {Status OK}\r\n", readLine(b));
        send(a, "GETSS {Robot B}\r\n");
        assertEquals("SS {Robot B} {Strength " + strength + "}\r\n", readLine(a));
    }

    private Path config(String... lines) throws IOException {
        List<String> all = new ArrayList<>(List.of("wss.bindAddress = 127.0.0.1", "wss.port = 0"));
        all.addAll(List.of(lines));
        // Properties files treat a backslash as an escape: a Windows path needs it doubled.
        all.replaceAll(line -> line.replace("\\", "\\\\"));
        return Files.write(Files.createTempFile(dir, "wss", ".properties"), all, StandardCharsets.UTF_8);
    }

    private ServerProcess start(List<String> javaArguments, Path config) throws IOException {
        List<String> arguments = new ArrayList<>(javaArguments);
        arguments.addAll(List.of("--headless", "--config", config.toString()));
        ServerProcess server = ServerProcess.startJava(arguments);
        servers.add(server);
        return server;
    }

    private Socket connect(int port) throws IOException {
        Socket socket = new Socket();
        sockets.add(socket);
        socket.connect(new InetSocketAddress(InetAddress.getByName("127.0.0.1"), port), (int) ServerProcess.WAIT.toMillis());
        socket.setSoTimeout((int) ServerProcess.WAIT.toMillis());
        return socket;
    }
}
