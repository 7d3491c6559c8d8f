package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Headless, a monitor configured unsafely is refused before anything listens: exit 2, one line (docs/monitor.md). */
class MonitorConfigRefusalTest {

    @TempDir
    Path dir;

    private MainRun run(String tokensPermissions, String bindAddress) throws Exception {
        Path tokens = dir.resolve("tokens");
        Files.writeString(tokens, "operator abcdefghijklmnopqrstuvwxyz\n");
        Files.setPosixFilePermissions(tokens, PosixFilePermissions.fromString(tokensPermissions));
        Path config = dir.resolve("wss.properties");
        Files.writeString(config, "wss.port = 0\nwss.bindAddress = 127.0.0.1\nwss.monitor.port = -1\nwss.monitor.bindAddress = " + bindAddress
                + "\nwss.monitor.tokens = " + tokens + "\n");
        return MainRun.of("--headless", "--config", config.toString());
    }

    @Test
    void aTokenFileOthersMayReadIsRefusedWithExit2AndNoToken() throws Exception {
        MainRun server = run("rw-r--r--", "127.0.0.1");
        assertEquals(2, server.exitCode(), server.stderr());
        String error = server.stderr().strip();
        assertFalse(error.contains("\n"), error);
        assertTrue(error.contains("wss.monitor.tokens") && error.contains("chmod 600"), error);
        assertFalse(error.contains("abcdefghijklmnopqrstuvwxyz"), error);
    }

    @Test
    void plainHttpOnAnAddressOtherMachinesReachIsRefusedWithExit2() throws Exception {
        MainRun server = run("rw-------", "0.0.0.0");
        assertEquals(2, server.exitCode(), server.stderr());
        assertTrue(server.stderr().contains("wss.monitor.keystore") && server.stderr().contains("ssh -L"), server.stderr());
    }
}
