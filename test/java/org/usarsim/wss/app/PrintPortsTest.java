package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code --print-ports [--config FILE]} through {@link Main#run} in the test JVM: the fixed ports
 * one a line on standard output, exit 0, nothing started; a bad file as headless reports it.
 */
class PrintPortsTest {

    @TempDir
    Path dir;

    private Path config(String... lines) throws IOException {
        Path file = dir.resolve("ports.properties");
        Files.write(file, List.of(lines), StandardCharsets.UTF_8);
        return file;
    }

    /** A number the OS just handed out on 127.0.0.1 and took back. */
    private static int free() throws IOException {
        try (ServerSocket socket = new ServerSocket(0, 1, InetAddress.getByName("127.0.0.1"))) {
            return socket.getLocalPort();
        }
    }

    @Test
    void everyFixedPortOnItsLineWithTheWssNumberAndTheRobotsAddresses() throws Exception {
        int tcp = free();
        int udp = free();
        Path file = config("wss.port = 0", "wss.bindAddress = 127.0.0.1", "wss.robot.Scout =", "wss.robot.Base = 127.0.0.2",
                "wss.fixed = Scout->Base:1883@" + tcp + ", udp Base->Scout:7400@" + udp);
        MainRun run = MainRun.of("--print-ports", "--config", file.toString());
        assertEquals(0, run.exitCode(), run.stderr());
        assertEquals(List.of(
                "tcp Scout->Base:1883@" + tcp + ": Scout (127.0.0.1) connects to the WSS at 127.0.0.1:" + tcp
                        + " for Base (127.0.0.2) port 1883",
                "udp Base->Scout:7400@" + udp + ": Base (127.0.0.2) sends to the WSS at 127.0.0.1:" + udp
                        + " for Scout (127.0.0.1) port 7400"),
                run.stdoutLines());
        try (ServerSocket again = new ServerSocket(tcp, 1, InetAddress.getByName("127.0.0.1"))) {
            assertEquals(tcp, again.getLocalPort(), "nothing kept the fixed port");
        }
    }

    @Test
    void theWildcardAddressIsAnyAddressOfThisMachine() throws Exception {
        int tcp = free();
        Path file = config("wss.port = 0", "wss.robot.A = 127.0.0.1", "wss.robot.B = 127.0.0.1", "wss.fixed = A->B:80@" + tcp);
        MainRun run = MainRun.of("--print-ports", "--config", file.toString());
        assertEquals(0, run.exitCode(), run.stderr());
        assertEquals(List.of("tcp A->B:80@" + tcp + ": A (127.0.0.1) connects to the WSS at port " + tcp
                + " (any address of this machine) for B (127.0.0.1) port 80"), run.stdoutLines());
    }

    @Test
    void noFixedPortPrintsNothingAndSaysSoOnStandardError() {
        MainRun run = MainRun.of("--print-ports");
        assertEquals(0, run.exitCode(), run.stderr());
        assertTrue(run.stdoutLines().isEmpty(), run.stdoutLines().toString());
        assertTrue(run.stderr().contains("no fixed port in the defaults"), run.stderr());
    }

    @Test
    void aBadFixedPortIsHeadlesssOneLineAndExitTwo() throws Exception {
        Path file = config("wss.port = 0", "wss.bindAddress = 127.0.0.1", "wss.robot.Scout =", "wss.fixed = Scout->Nobody:80@11880");
        MainRun printed = MainRun.of("--print-ports", "--config", file.toString());
        assertEquals(2, printed.exitCode(), printed.stderr());
        String error = printed.stderr().strip();
        assertFalse(error.contains("\n"), "one line: " + error);
        assertTrue(error.contains("wss.fixed = 'Scout->Nobody:80@11880'") && error.contains("Nobody is not declared"), error);
        assertTrue(printed.stdoutLines().isEmpty(), printed.stdoutLines().toString());
        MainRun headless = MainRun.of("--headless", "--config", file.toString());
        assertEquals(2, headless.exitCode(), headless.stderr());
        assertEquals(error, headless.stderr().strip(), "the same line as headless");
    }

    @Test
    void aFixedPortInUseIsRefusedAsHeadlessRefusesIt() throws Exception {
        try (ServerSocket taken = new ServerSocket(0, 50, InetAddress.getByName("127.0.0.1"))) {
            Path file = config("wss.port = 0", "wss.bindAddress = 127.0.0.1", "wss.robot.A =", "wss.robot.B =",
                    "wss.fixed = A->B:80@" + taken.getLocalPort());
            MainRun run = MainRun.of("--print-ports", "--config", file.toString());
            assertEquals(2, run.exitCode(), run.stderr());
            assertTrue(run.stderr().contains("tcp port " + taken.getLocalPort() + " is in use"), run.stderr());
        }
    }

    @Test
    void onlyConfigGoesWithIt() throws Exception {
        assertEquals(new Options.PrintPorts(Path.of("a.properties")), OptionsParser.parse("--config", "a.properties", "--print-ports"));
        assertEquals(new Options.PrintPorts(Path.of("a.properties")), OptionsParser.parse("--print-ports", "--config", "a.properties"));
        for (List<String> args : List.of(List.of("--print-ports", "--headless"), List.of("--print-ports", "--start"),
                List.of("--world", "w.world", "--print-ports"))) {
            OptionsParser.Mistake mistake = assertThrows(OptionsParser.Mistake.class, () -> OptionsParser.parse(args.toArray(String[]::new)));
            assertTrue(mistake.getMessage().startsWith("--print-ports only prints the fixed ports of --config FILE"), mistake.getMessage());
        }
        assertTrue(OptionsParser.help(OptionsParser.COMMAND).contains("\n  --print-ports       print every fixed port"),
                OptionsParser.help(OptionsParser.COMMAND));
    }
}
