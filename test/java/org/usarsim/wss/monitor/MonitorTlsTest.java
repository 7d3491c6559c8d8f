package org.usarsim.wss.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStream;
import java.net.InetAddress;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.KeyStore;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import javax.net.ssl.SSLContext;
import javax.net.ssl.TrustManagerFactory;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.hub.ScriptedModel;
import org.usarsim.wss.hub.TestHub;
import org.usarsim.wss.shaping.ShapingConfig;

/** The monitor over HTTPS with a keystore made by keytool (a process: slow tier), and its password file's owner-only rule. */
@Tag("slow")
class MonitorTlsTest {

    private static final String PASSWORD = "keystore-password";

    @TempDir
    Path dir;

    @Test
    void withAKeystoreItAnswersOverHttpsAndAPasswordFileOthersMayReadIsRefused() throws Exception {
        Path keystore = dir.resolve("monitor.p12");
        Process keytool = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "keytool").toString(), "-genkeypair",
                "-alias", "wss", "-keyalg", "EC", "-groupname", "secp256r1", "-validity", "2", "-dname", "CN=localhost",
                "-ext", "SAN=ip:127.0.0.1", "-keystore", keystore.toString(), "-storetype", "PKCS12", "-storepass", PASSWORD)
                .redirectErrorStream(true).start();
        assertTrue(keytool.waitFor(60, TimeUnit.SECONDS) && keytool.exitValue() == 0, new String(keytool.getInputStream().readAllBytes()));
        Path password = dir.resolve("password");
        Files.writeString(password, PASSWORD + "\n");
        Files.setPosixFilePermissions(password, PosixFilePermissions.fromString("rw-r--r--"));
        Path tokens = MonitorServerTest.tokenFile(dir, "viewer " + MonitorServerTest.VIEWER + "\n");
        MonitorConfig config = new MonitorConfig(-1, InetAddress.getLoopbackAddress(), tokens, 4, keystore, password);
        try (TestHub server = new TestHub(new ScriptedModel(), true, 65536)) {
            Watched watched = new Watched(server.hub, new ScriptedModel(), Map.of(), ShapingConfig.OFF, "127.0.0.1");
            MonitorSetupException refused = assertThrows(MonitorSetupException.class, () -> MonitorServer.open(config, watched));
            assertTrue(refused.getMessage().contains(MonitorConfig.KEYSTORE_PASSWORD_FILE) && refused.getMessage().contains("chmod 600"),
                    refused.getMessage());
            Files.setPosixFilePermissions(password, PosixFilePermissions.fromString("rw-------"));
            try (MonitorServer monitor = MonitorServer.open(config, watched)) {
                monitor.start();
                KeyStore trusted = KeyStore.getInstance("PKCS12");
                try (InputStream in = Files.newInputStream(keystore)) {
                    trusted.load(in, PASSWORD.toCharArray());
                }
                TrustManagerFactory trust = TrustManagerFactory.getInstance(TrustManagerFactory.getDefaultAlgorithm());
                trust.init(trusted);
                SSLContext tls = SSLContext.getInstance("TLS");
                tls.init(null, trust.getTrustManagers(), null);
                HttpResponse<String> state = HttpClient.newBuilder().sslContext(tls).build().send(
                        HttpRequest.newBuilder(URI.create("https://127.0.0.1:" + monitor.port() + "/api/state"))
                                .header("Authorization", "Bearer " + MonitorServerTest.VIEWER).build(),
                        HttpResponse.BodyHandlers.ofString());
                assertEquals(200, state.statusCode(), state.body());
                assertEquals(false, MonitorServerTest.json(state.body()).get("operator"));
            }
        }
    }
}
