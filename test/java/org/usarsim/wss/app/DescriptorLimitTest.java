package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.StringJoiner;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.hub.Sockets;
import org.usarsim.wss.hub.TestRobot;

/**
 * The real server under a limit of 256 open descriptors: a DNS that finds no descriptor left
 * gets Could.Not.Allocate.Port, and the server goes on; remembered ports of robots that left never
 * cost a robot that is here its port.
 */
@Tag("slow")
class DescriptorLimitTest {

    private static final int LIMIT = 256;

    @TempDir
    Path dir;

    /**
     * Runs every path the test goes through once, while descriptors are left: the child runs from
     * a folder of classes, and a class loaded for the first time needs a descriptor to be read
     * (run from wss.jar, the classes come from the jar, which is open already).
     */
    private static void warmUp(ServerProcess server, int port, ServerSocket r1Accepts, TestRobot r2) throws Exception {
        assertTrue(r2.ask("GETSS {Robot R1}").startsWith("SS {Robot R1} {Strength "));
        try (Socket source = r2.connect(r2.dns("R1", 0)); Socket target = r1Accepts.accept()) {
            Sockets.send(source, "hi");
            assertEquals("hi", Sockets.readExactly(target.getInputStream(), 2));
            source.close();
            Sockets.assertClosedByPeer(target, "the target");
        }
        try (TestRobot gone = new TestRobot(port, "127.0.0.1")) {
            gone.init("Gone", 5000);
            r2.dns("Gone", 0);
        }
        server.awaitLine(line -> line.contains("forgot 1 WSS port of Gone"));
    }

    @Test
    void outOfDescriptorsADnsGetsCouldNotAllocatePortAndTheServerGoesOn() throws Exception {
        Path config = dir.resolve("wss.properties");
        Files.writeString(config, "wss.port = 0\nwss.bindAddress = 127.0.0.1\nwss.portMemory = 0\n", StandardCharsets.UTF_8);
        ServerProcess server = ServerProcess.startWithDescriptorLimit(LIMIT, "--headless", "--config", config.toString());
        try {
            int port = Integer.parseInt(server.awaitListening().group(1));
            try (TestRobot r1 = new TestRobot(port, "127.0.0.1"); TestRobot r2 = new TestRobot(port, "127.0.0.1")) {
                ServerSocket r1Accepts = r1.listen();
                StringJoiner ports = new StringJoiner(",").add(String.valueOf(r1Accepts.getLocalPort()));
                for (int p = 1; p <= LIMIT; p++) {
                    ports.add(String.valueOf(p));
                }
                assertEquals("INITREPLY {Status OK}", r1.ask("INIT {Robot R1} {Port " + ports + "}"));
                r2.init("R2", 6000);
                warmUp(server, port, r1Accepts, r2);
                String reply = "";
                int allocated = 0;
                while (allocated < LIMIT) {
                    reply = r2.ask("DNS {Robot R1} {Port " + (allocated + 1) + "}");
                    if (!reply.startsWith("DNSREPLY {Robot R1} {Port ")) {
                        break;
                    }
                    allocated++;
                }
                assertEquals("ERROR {Reason Could.Not.Allocate.Port}", reply, "after " + allocated + " WSS ports");
                assertTrue(allocated > 50, allocated + " WSS ports before the descriptors ran out");
                String refused = "could not allocate a WSS port for R2 -> R1:" + (allocated + 1);
                server.awaitLine(line -> line.contains(refused));
                assertTrue(r2.ask("GETSS {Robot R1}").startsWith("SS {Robot R1} {Strength "), "R2's connection goes on");
            }
            // R2 and R1 left: their ports are forgotten at once (wss.portMemory = 0), the descriptors come back.
            server.awaitLine(line -> line.matches(".*forgot \\d{2,} WSS ports of R[12], gone for 0 s"));
            try (TestRobot r3 = new TestRobot(port, "127.0.0.1"); TestRobot r4 = new TestRobot(port, "127.0.0.1")) {
                r3.init("R3", 5000);
                r4.init("R4", 5000);
                assertTrue(r4.dns("R3", 0) > 0);
            }
        } catch (Exception | AssertionError e) {
            throw new AssertionError("server output: " + server.stdoutSoFar() + server.stderr(), e);
        } finally {
            server.kill();
        }
    }

    /**
     * Robots with ever new names come, ask a port, send through it and leave, with the default
     * port memory (600 s): their remembered ports would fill the descriptors after about 200
     * robots. None is refused: the remembered ports of the robots gone longest are given back.
     */
    @Test
    void rememberedPortsNeverCostARobotThatIsHereItsPort() throws Exception {
        Path config = dir.resolve("wss.properties");
        Files.writeString(config, "wss.port = 0\nwss.bindAddress = 127.0.0.1\n", StandardCharsets.UTF_8);
        ServerProcess server = ServerProcess.startWithDescriptorLimit(LIMIT, "--headless", "--config", config.toString());
        int robots = 2 * LIMIT;
        try {
            int port = Integer.parseInt(server.awaitListening().group(1));
            try (TestRobot base = new TestRobot(port, "127.0.0.1")) {
                ServerSocket baseAccepts = base.initAccepting("Base");
                for (int i = 0; i < robots; i++) {
                    try (TestRobot robot = new TestRobot(port, "127.0.0.1")) {
                        robot.init("Fresh" + i, 5000);
                        try (Socket data = robot.connect(robot.dns("Base", 0)); Socket arrived = baseAccepts.accept()) {
                            Sockets.send(data, "robot " + i + "\n");
                            assertEquals("robot " + i + "\n", Sockets.readLine(arrived), "through Fresh" + i + "'s port");
                        }
                    }
                }
                assertEquals("SS {Robot Fresh0} {Strength NaN} {Error Robot.Does.Not.Exist}", base.ask("GETSS {Robot Fresh0}"),
                        "Base's control connection goes on");
            }
            server.awaitLine(line -> line.contains("descriptors ran short: gave back "));
        } catch (Exception | AssertionError e) {
            throw new AssertionError("server output: " + server.stdoutSoFar() + server.stderr(), e);
        } finally {
            server.kill();
        }
    }
}
