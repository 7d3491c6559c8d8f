package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.util.Map;
import java.util.Properties;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.gui.Servers;
import org.usarsim.wss.model.ModelProvider;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.model.noop.NoopPropagationModel;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * A fixed port whose number is taken after the --config file was read (the window open, Start not
 * yet pressed): the window's Start is refused with the one line naming wss.fixed and its value,
 * which the window shows in its dialog, and starts once the number is free again.
 */
class WindowServersFixedPortTest {

    /** A number the OS just handed out on 127.0.0.1 and took back. */
    private static int free() throws IOException {
        try (ServerSocket socket = new ServerSocket(0, 1, InetAddress.getByName("127.0.0.1"))) {
            return socket.getLocalPort();
        }
    }

    private static WindowServers servers(String fixed) throws ConfigFileException {
        Properties file = new Properties();
        file.setProperty("wss.bindAddress", "127.0.0.1");
        file.setProperty("wss.robot.Scout", "");
        file.setProperty("wss.robot.Base", "");
        file.setProperty("wss.fixed", fixed);
        return new WindowServers(ConfigFile.of(file, "test"));
    }

    private static Servers.Running start(WindowServers servers) throws Server.StartFailure {
        return servers.start("0", ModelProvider.of(NoopPropagationModel::new), new ModelSettings(Map.of()), false, false,
                ShapingConfig.OFF, new WssEventListener() { });
    }

    private static void refusedNamingKeyAndValue(WindowServers servers, String fixed, String why) {
        Server.StartFailure failure = assertThrows(Server.StartFailure.class, () -> start(servers));
        String message = failure.getMessage();
        assertFalse(message.contains("\n"), "one line: " + message);
        assertTrue(message.startsWith("wss.fixed = '" + fixed + "' is not "), message);
        assertTrue(message.contains(why), message);
        assertTrue(failure.badInput(), "a configuration the number no longer fits");
    }

    @Test
    void aTcpNumberTakenSinceTheFileWasReadIsSaidAndStartWorksOnceItIsFree() throws Exception {
        int number = free();
        String fixed = "Scout->Base:1883@" + number;
        WindowServers servers = servers(fixed);
        try (ServerSocket taken = new ServerSocket(number, 50, InetAddress.getByName("127.0.0.1"))) {
            refusedNamingKeyAndValue(servers, fixed, "tcp Scout->Base:1883@" + number + ": tcp port " + number + " is in use");
        }
        Servers.Running running = start(servers);
        try {
            assertEquals(1, running.snapshot().ports().size(), "the fixed port: " + running.snapshot().ports());
        } finally {
            running.stop();
        }
    }

    @Test
    void aUdpNumberTakenSinceTheFileWasReadIsSaid() throws Exception {
        int number;
        try (DatagramSocket probe = new DatagramSocket(0, InetAddress.getByName("127.0.0.1"))) {
            number = probe.getLocalPort();
        }
        String fixed = "udp Scout->Base:7400@" + number;
        WindowServers servers = servers(fixed);
        try (DatagramSocket taken = new DatagramSocket(new InetSocketAddress("127.0.0.1", number))) {
            refusedNamingKeyAndValue(servers, fixed, "udp Scout->Base:7400@" + number + ": udp port " + number + " is in use");
        }
    }
}
