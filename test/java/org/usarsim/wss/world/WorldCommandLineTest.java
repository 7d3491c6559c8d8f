package org.usarsim.wss.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.usarsim.wss.app.MainRun;

/**
 * {@code Main --world ...} mistakes and --help through Main.run in the test JVM: exit 2 (0 for
 * --help) and the lines written, before anything listens. Serving: WorldProcessTest.
 */
class WorldCommandLineTest {

    private static final String CORRIDOR = "docs/examples/corridor.world";

    @TempDir
    Path dir;

    @Test
    void aBadWorldFileExitsTwoBeforeBinding() throws Exception {
        Path world = dir.resolve("bad.world");
        Files.writeString(world, "# a mistake on line 3\nrobot A 0,0,0\npath A speed 0 loop 5,5\n", StandardCharsets.UTF_8);
        MainRun server = MainRun.of("--world", world.toString(), "--bind", "127.0.0.1", "--port", "0");
        assertEquals(2, server.exitCode(), "stderr: " + server.stderr());
        assertEquals("wss: " + world + ":3: the speed must be above 0 metres per second: 0 (path A speed 0 loop 5,5)\n",
                server.stderr().replace("\r\n", "\n"));
        assertTrue(server.stdoutLines().stream().noneMatch(line -> line.contains("listening")), server.stdoutLines().toString());
    }

    @Test
    void aMissingWorldFileExitsTwo() throws Exception {
        Path absent = dir.resolve("absent.world");
        MainRun server = MainRun.of("--world", absent.toString(), "--bind", "127.0.0.1", "--port", "0");
        assertEquals(2, server.exitCode());
        assertEquals("wss: " + absent + ": no such file", server.stderr().strip());
    }

    @ParameterizedTest(name = "[{index}] {0}")
    @CsvSource(delimiter = '|', value = {
        "--port 7435                                      | --port, --bind and --rosbridge are for the world server",
        "--bind 127.0.0.1                                 | --port, --bind and --rosbridge are for the world server",
        "--headless --port 0                              | --port, --bind and --rosbridge are for the world server",
        "--world " + CORRIDOR + " --headless              | without --headless or --config",
        "--world " + CORRIDOR + " --port 65536            | --port 65536 is not a port number from 0 to 65535",
        "--world " + CORRIDOR + " --port seven            | --port seven is not a port number",
        "--world " + CORRIDOR + " --bind no.such.host.invalid | --bind no.such.host.invalid is not an address",
        "--world                                          | --world needs a value",
        "--world " + CORRIDOR + " --port                  | --port needs a value",
        "--rosbridge 9090                                 | --port, --bind and --rosbridge are for the world server",
        "--world " + CORRIDOR + " --rosbridge 70000       | --rosbridge 70000 is not a port number from 0 to 65535",
        "--world " + CORRIDOR + " --ros-rate 5            | --ros-rate is the rate of the world server's rosbridge: it needs",
        "--export-world run.rec --ros-rate 5              | --ros-rate is the rate of the world server's rosbridge: it needs",
        "--world " + CORRIDOR + " --rosbridge 0 --ros-rate 0 | --ros-rate 0 is not a rate in Hz above 0 and at most 1000",
        "--world " + CORRIDOR + " --rosbridge 0 --ros-rate 1001 | --ros-rate 1001 is not a rate in Hz",
        "--world " + CORRIDOR + " --rosbridge 0 --ros-rate 1e3 | --ros-rate 1e3 is not a rate in Hz",
    })
    void commandLineMistakesExitTwo(String args, String message) throws Exception {
        MainRun server = MainRun.of(args.strip().split(" +"));
        assertEquals(2, server.exitCode(), "stderr: " + server.stderr());
        assertTrue(server.stderr().startsWith("wss: "), server.stderr());
        assertTrue(server.stderr().contains(message), server.stderr());
        assertTrue(server.stdoutLines().isEmpty(), server.stdoutLines().toString());
    }

    @Test
    void helpDescribesTheWorldServer() throws Exception {
        MainRun server = MainRun.of("--help");
        assertEquals(0, server.exitCode());
        String help = String.join("\n", server.stdoutLines());
        assertTrue(help.contains("--world FILE [--port N] [--bind ADDRESS] [--rosbridge PORT [--ros-rate HZ]]"), help);
        assertTrue(help.contains("--ros-rate HZ"), help);
        assertTrue(help.contains("default 7435"), help);
    }
}
