package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.util.List;
import java.util.Properties;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.usarsim.wss.hub.FixedSetup;
import org.usarsim.wss.hub.core.DeclaredRobot;
import org.usarsim.wss.hub.core.FixedPort;
import org.usarsim.wss.hub.core.PortKey;
import org.usarsim.wss.shaping.LossTable;

/** Declared robots, fixed ports, the UDP session expiry and the loss table in a properties file (docs/fixed-ports.md). */
class FixedPortsConfigTest {

    /** A number the OS just handed out on 127.0.0.1 and took back: free to name as a fixed port. */
    private static int free() {
        try (ServerSocket socket = new ServerSocket(0, 1, InetAddress.getByName("127.0.0.1"))) {
            return socket.getLocalPort();
        } catch (java.io.IOException e) {
            throw new IllegalStateException(e);
        }
    }

    private static ConfigFile config(String... keysAndValues) throws ConfigFileException {
        Properties properties = new Properties();
        properties.setProperty("wss.bindAddress", "127.0.0.1");
        properties.setProperty("wss.port", "0");
        for (int i = 0; i < keysAndValues.length; i += 2) {
            properties.setProperty(keysAndValues[i], keysAndValues[i + 1]);
        }
        return ConfigFile.of(properties, "t.properties");
    }

    private static String refused(String... keysAndValues) {
        String message = assertThrows(ConfigFileException.class, () -> config(keysAndValues)).getMessage();
        assertFalse(message.contains("\n"), "one line: " + message);
        assertTrue(message.startsWith("t.properties: "), message);
        return message;
    }

    @Test
    void declaredRobotsAndFixedPortsReachTheHubsConfiguration() throws Exception {
        int tcp = free();
        int udp = free();
        FixedSetup setup = config("wss.robot.Scout", "", "wss.robot.Base", "127.0.0.2",
                "wss.fixed", "Scout->Base:1883@" + tcp + ", udp Scout -> Base : 7400 @ " + udp,
                "wss.udpIdleSeconds", "5").hubConfig().fixed();
        assertEquals(List.of(new DeclaredRobot("Base", InetAddress.getByName("127.0.0.2")),
                new DeclaredRobot("Scout", InetAddress.getByName("127.0.0.1"))), setup.robots());
        assertEquals(List.of(new FixedPort(FixedPort.Transport.TCP, new PortKey("Scout", "Base", 1883), tcp),
                new FixedPort(FixedPort.Transport.UDP, new PortKey("Scout", "Base", 7400), udp)), setup.ports());
        assertEquals(5, setup.udpIdleSeconds());
        assertEquals(List.of(1883, 7400), setup.portsOf("Base"));
        assertEquals(List.of(), setup.portsOf("Scout"));
        assertEquals("tcp Scout->Base:1883@" + tcp, setup.ports().get(0).toString());
    }

    /**
     * Issue 36, the grammar of wss.fixed as docs/fixed-ports.md writes it, the accepted side: the
     * transport in any case, spaces and tabs around the items and the separators, a name with '-'
     * or '>' (not "->"), even first. N stands for a free number.
     */
    @ParameterizedTest(name = "''{0}''")
    @CsvSource(delimiter = '|', quoteCharacter = '"', value = {
        "UDP A->B:7400@N|udp A->B:7400@N",
        "Udp A->B:7400@N|udp A->B:7400@N",
        "TCP A->B:7400@N|tcp A->B:7400@N",
        "udp\\tA->B:7400@N|udp A->B:7400@N",
        "\\t udp  A -> B : 7400 @ N \\t|udp A->B:7400@N",
        "A\\t->\\tB\\t:\\t80\\t@\\tN|tcp A->B:80@N",
        "-x->B:80@N|tcp -x->B:80@N",
        "A-->B:80@N|tcp A-->B:80@N",
        ">y->A-:80@N|tcp >y->A-:80@N",
        "A->B:08080@N|tcp A->B:8080@N",
    })
    void theGrammarAcceptsWhatTheDocsSay(String given, String expected) throws Exception {
        String number = String.valueOf(free());
        FixedSetup setup = config("wss.robot.A", "", "wss.robot.B", "", "wss.robot.-x", "", "wss.robot.A-", "", "wss.robot.>y", "",
                "wss.fixed", given.replace("\\t", "\t").replace("N", number)).hubConfig().fixed();
        assertEquals(expected.replace("N", number), setup.ports().get(0).toString());
    }

    /** The refused side: whitespace inside a part, other whitespace than spaces and tabs, a name with "->", glued words. */
    @ParameterizedTest(name = "''{0}''")
    @CsvSource(delimiter = '|', quoteCharacter = '"', value = {
        "A - > B:80@N|is not [tcp|udp] FROM->TO:PORT@NUMBER",
        "A->B->C:80@N|is not [tcp|udp] FROM->TO:PORT@NUMBER",
        "A->B:80 80@N|is not [tcp|udp] FROM->TO:PORT@NUMBER",
        "A->B:80@N extra|is not [tcp|udp] FROM->TO:PORT@NUMBER",
        "udp\\fA->B:80@N|is not [tcp|udp] FROM->TO:PORT@NUMBER",
        "A->B:80\\f@N|is not [tcp|udp] FROM->TO:PORT@NUMBER",
        "A->B:80@\\u000BN|is not [tcp|udp] FROM->TO:PORT@NUMBER",
        "udpA->B:80@N|udpA is not declared",
        "udp tcp A->B:80@N|is not [tcp|udp] FROM->TO:PORT@NUMBER",
        "A->B:+80@N|+80 is not a port number",
        "A->B:0x50@N|0x50 is not a port number",
    })
    void theGrammarRefusesWhatTheDocsDoNotSay(String given, String why) {
        String value = given.replace("\\t", "\t").replace("\\f", "\f").replace("\\u000B", "\u000B").replace("N", String.valueOf(free()));
        String message = refused("wss.robot.A", "", "wss.robot.B", "", "wss.robot.C", "", "wss.fixed", value);
        assertTrue(message.contains(why), message);
    }

    /**
     * Issue 36: an IPv6 address (written as numbers, as every address setting takes it) declares
     * a robot when the WSS ports can hear and reach it: on the wildcard; refused when they listen on
     * one address of the other family, where its fixed ports would never work.
     */
    @Test
    void anIpv6RobotIsDeclaredWhereTheWssPortsCanReachIt() throws Exception {
        String message = refused("wss.robot.A", "::1");
        assertTrue(message.contains("wss.robot.A = '::1' is an IPv6 address, but the WSS ports listen on the IPv4 address"
                + " wss.bindAddress = 127.0.0.1"), message);
        FixedSetup setup = FixedPorts.setup(java.util.Map.of("wss.robot.A", "::1", "wss.robot.B", " 127.0.0.1 "), "", 60, 50000,
                InetAddress.getByName("0.0.0.0"));
        assertTrue(setup.robots().contains(new DeclaredRobot("A", InetAddress.getByName("::1"))), setup.robots().toString());
        assertTrue(setup.robots().contains(new DeclaredRobot("B", InetAddress.getByName("127.0.0.1"))), setup.robots().toString());
        IllegalArgumentException ipv4 = assertThrows(IllegalArgumentException.class, () -> FixedPorts.setup(
                java.util.Map.of("wss.robot.B", "127.0.0.1"), "", 60, 50000, InetAddress.getByName("::1")));
        assertTrue(ipv4.getMessage().contains("is an IPv4 address, but the WSS ports listen on the IPv6 address"), ipv4.getMessage());
        assertEquals(1, FixedPorts.setup(java.util.Map.of("wss.robot.A", "::1"), "", 60, 50000, InetAddress.getByName("::")).robots().size());
    }

    @Test
    void aTcpAndAUdpPortMayShareANumber() throws Exception {
        int number = free();
        FixedSetup setup = config("wss.robot.A", "", "wss.robot.B", "",
                "wss.fixed", "A->B:5201@" + number + ",udp A->B:5201@" + number).hubConfig().fixed();
        assertEquals(2, setup.ports().size());
    }

    @Test
    void noneByDefaultAndTheLossTableIsRead() throws Exception {
        assertEquals(FixedSetup.NONE, config().hubConfig().fixed());
        assertEquals(LossTable.parse("-85:1,-88:10,-91:50"),
                config("wss.shaping.loss", "-85:1,-88:10,-91:50").hubConfig().shaping().loss());
        assertEquals(LossTable.NONE, config("wss.shaping.loss", "").hubConfig().shaping().loss());
    }

    @ParameterizedTest(name = "{0} = ''{1}''")
    @CsvSource(delimiter = '|', value = {
        "wss.fixed|A->C:80@40021|C is not declared (add wss.robot.C = ADDRESS)",
        "wss.fixed|C->A:80@40021|C is not declared",
        "wss.fixed|sctp A->B:80@40021|sctp is not tcp or udp",
        "wss.fixed|A->B:80|'A->B:80' is not [tcp|udp] FROM->TO:PORT@NUMBER",
        "wss.fixed|A->B:80@70000|70000 is not a port number from 1 to 65535",
        "wss.fixed|A->B:0@40021|0 is not a port number from 1 to 65535",
        "wss.fixed|A->A:80@40021|a robot's port to itself",
        "wss.fixed|A->B:80@40021,B->A:81@40021|take the same tcp port 40021",
        "wss.fixed|udp A->B:80@40021,udp B->A:81@40021|take the same udp port 40021",
        "wss.fixed|A->B:80@40021,A->B:80@40022|are the same way to the same port",
        "wss.fixed|A->B:80@40021,|'' is not [tcp|udp] FROM->TO:PORT@NUMBER",
        "wss.udpIdleSeconds|0|wss.udpIdleSeconds = '0' is not",
        "wss.shaping.loss|-88:10,-85:1|rows must go from the strongest to the weakest signal",
        "wss.shaping.loss|-85:200|200 is not a percent from 0 to 100",
    })
    void aBadFixedPortIsOneLineNamingTheKeyAndTheValue(String key, String given, String why) {
        String number = String.valueOf(free());
        String value = given.replace("40021", number).replace("40022", String.valueOf(free()));
        String message = refused("wss.robot.A", "", "wss.robot.B", "", key, value);
        assertTrue(message.contains(key + " = '" + value + "' is not "), message);
        assertTrue(message.contains(why.replace("40021", number)), message);
    }

    @ParameterizedTest(name = "wss.robot.{0} = ''{1}''")
    @CsvSource(delimiter = '|', value = {
        "A|localhost|is not an IP address", "A|0.0.0.0|is not an IP address", "A|127.0.0.1,127.0.0.2|is not an IP address",
        "A|256.1.1.1|is not an IP address", "A:B|127.0.0.1|is not a robot name", "A->B|127.0.0.1|is not a robot name",
        "''|127.0.0.1|is not a robot name",
    })
    void aBadDeclarationNamesTheKeyAndTheValue(String name, String address, String why) {
        String message = refused("wss.robot." + name, address);
        assertTrue(message.contains("wss.robot." + name + " = '" + address + "'"), message);
        assertTrue(message.contains(why), message);
    }

    @Test
    void aFixedPortOnTheControlPortIsRefused() {
        int number = free();
        String message = refused("wss.port", "" + number, "wss.robot.A", "", "wss.robot.B", "", "wss.fixed", "A->B:80@" + number);
        assertTrue(message.contains("takes the control port (wss.port = " + number + ")"), message);
    }

    @Test
    void aPortInUseIsRefusedForItsProtocolOnly() throws Exception {
        InetAddress local = InetAddress.getByName("127.0.0.1");
        try (ServerSocket tcp = new ServerSocket(0, 1, local)) {
            int number = tcp.getLocalPort();
            String message = refused("wss.robot.A", "", "wss.robot.B", "", "wss.fixed", "A->B:80@" + number);
            assertTrue(message.contains("tcp port " + number + " is in use"), message);
            try (DatagramSocket probe = new DatagramSocket(new InetSocketAddress(local, 0))) {
                int udp = probe.getLocalPort();
                String udpMessage = refused("wss.robot.A", "", "wss.robot.B", "", "wss.fixed", "udp A->B:80@" + udp);
                assertTrue(udpMessage.contains("udp port " + udp + " is in use"), udpMessage);
            }
        }
    }

    @Test
    void theServerExitsTwoWithOneLineAndStartsNothing() throws Exception {
        java.nio.file.Path file = java.nio.file.Files.createTempFile("fixed", ".properties");
        try {
            java.nio.file.Files.writeString(file, "wss.bindAddress=127.0.0.1\nwss.port=0\nwss.robot.A=\nwss.fixed=A->Nobody:80@" + free() + "\n");
            MainRun server = MainRun.of("--headless", "--config", file.toString());
            assertEquals(2, server.exitCode(), server.stderr());
            String error = server.stderr().strip();
            assertFalse(error.contains("\n"), error);
            assertTrue(error.contains("wss.fixed = 'A->Nobody:80@") && error.contains("Nobody is not declared"), error);
        } finally {
            java.nio.file.Files.delete(file);
        }
    }
}
