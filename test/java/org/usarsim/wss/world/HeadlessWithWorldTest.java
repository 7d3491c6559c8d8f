package org.usarsim.wss.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.app.ServerProcess;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.hub.Sockets;
import org.usarsim.wss.model.simulator.PathLoss;
import org.usarsim.wss.protocol.Replies;

/** The real server process, configured by a properties file, with the DistanceOnly model reading our world server. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
@Tag("slow")
class HeadlessWithWorldTest {

    @TempDir
    Path dir;

    private WorldServer world;
    private ServerProcess wss;

    @AfterEach
    void stop() throws Exception {
        if (wss != null) {
            wss.kill();
        }
        if (world != null) {
            world.close();
        }
    }

    private Path config(int simulatorPort, String model) throws Exception {
        return Files.writeString(dir.resolve("wss.properties"), String.join("\n",
                "wss.port = 0", "wss.bindAddress = 127.0.0.1", "wss.model = " + model,
                "usarsim.host = 127.0.0.1", "usarsim.port = " + simulatorPort, "usarsim.interval = 100",
                "distance.n = 3", ""));
    }

    @Test
    void theHeadlessServerTakesTheModelAndItsSettingsFromTheFile() throws Exception {
        world = WorldServer.start(Files.writeString(dir.resolve("w.world"), "robot Base 0,0,0\nrobot Far 40,30,0\n"),
                InetAddress.getByName("127.0.0.1"), 0);
        wss = ServerProcess.start("--headless", "--config", config(world.port(), "DistanceOnlyPropagationModel").toString());
        wss.awaitLine(line -> line.contains("DistanceOnlyPropagationModel polls the simulator at 127.0.0.1:" + world.port()
                + " every 100 ms; range 55.64 m"));
        int port = Integer.parseInt(wss.awaitListening().group(1));
        try (TestRobot base = new TestRobot(port, "127.0.0.1"); TestRobot far = new TestRobot(port, "127.0.0.1");
                TestRobot ghost = new TestRobot(port, "127.0.0.1")) {
            base.init("Base", 5000);
            far.init("Far", 5001);
            ghost.init("Ghost", 5002);
            Sockets.assertClosedByPeer(ghost.control, "Ghost, not in the world, kicked at the next poll");
            String expected = Replies.signal("Far", new PathLoss(-49.67, 3, 2, -93).strength(50));
            assertEquals(expected, base.ask("GETSS {Robot Far}"), "50 m with n = 3 from the file");
        }
    }

    @Test
    void anUnreachableSimulatorStopsTheServerWithHostAndPort() throws Exception {
        int free;
        try (ServerSocket probe = new ServerSocket(0, 1, InetAddress.getByName("127.0.0.1"))) {
            free = probe.getLocalPort();
        }
        wss = ServerProcess.start("--headless", "--config", config(free, "ObstaclePropagationModel").toString());
        assertEquals(1, wss.awaitExit());
        assertTrue(wss.stderr().contains("wss: ObstaclePropagationModel did not start: cannot reach the simulator at 127.0.0.1:"
                + free + " ("), wss.stderr());
    }
}
