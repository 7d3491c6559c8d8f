package org.usarsim.wss.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The token file's rules (wss.monitor.tokens) and the configuration's (docs/monitor.md, "Security"). */
class TokensTest {

    private static final String SECRET = "s3cret-0123456789abcdef";

    @TempDir
    Path dir;

    private Path file(String text, String permissions) throws Exception {
        Path file = dir.resolve("tokens");
        Files.writeString(file, text);
        Files.setPosixFilePermissions(file, PosixFilePermissions.fromString(permissions));
        return file;
    }

    @Test
    void eachLineGivesItsRoleAndAnythingElseNone() throws Exception {
        Tokens tokens = Tokens.read(file("# who\nviewer " + SECRET + "\n\noperator " + SECRET + "X\n", "rw-------"));
        assertEquals(Role.VIEWER, tokens.roleOf("Bearer " + SECRET));
        assertEquals(Role.OPERATOR, tokens.roleOf("bearer " + SECRET + "X"));
        assertNull(tokens.roleOf(null));
        assertNull(tokens.roleOf("Basic " + SECRET));
        assertNull(tokens.roleOf("Bearer " + SECRET.substring(1)));
        assertNull(tokens.roleOf("Bearer "));
    }

    @Test
    void aFileOthersMayReadOrWriteIsRefusedAndTheRefusalQuotesNoToken() throws Exception {
        for (String permissions : new String[] {"rw-r-----", "rw----r--", "rw--w----", "rw-rw-rw-"}) {
            MonitorSetupException refused = assertThrows(MonitorSetupException.class,
                    () -> Tokens.read(file("viewer " + SECRET + "\n", permissions)), permissions);
            assertTrue(refused.getMessage().contains("chmod 600"), refused.getMessage());
            assertFalse(refused.getMessage().contains(SECRET), refused.getMessage());
        }
    }

    @Test
    void aMissingEmptyOrMalformedFileIsRefused() throws Exception {
        assertThrows(MonitorSetupException.class, () -> Tokens.read(dir.resolve("none")));
        assertThrows(MonitorSetupException.class, () -> Tokens.read(file("# nothing\n\n", "rw-------")));
        MonitorSetupException malformed = assertThrows(MonitorSetupException.class,
                () -> Tokens.read(file("admin " + SECRET + "\n", "rw-------")));
        assertTrue(malformed.getMessage().contains("line 1"), malformed.getMessage());
        assertFalse(malformed.getMessage().contains(SECRET), malformed.getMessage());
        assertThrows(MonitorSetupException.class, () -> Tokens.read(file("viewer " + SECRET + " extra\n", "rw-------")));
        assertThrows(MonitorSetupException.class, () -> Tokens.read(file("viewer short\n", "rw-------")));
    }

    @Test
    void plainHttpOnAnAddressOtherMachinesReachIsRefusedNamingTheKeystoreAndTheTunnel() throws Exception {
        Path tokens = file("viewer " + SECRET + "\n", "rw-------");
        MonitorConfig open = new MonitorConfig(8443, InetAddress.getByName("0.0.0.0"), tokens, 16, null, null);
        MonitorSetupException refused = assertThrows(MonitorSetupException.class, open::check);
        assertTrue(refused.getMessage().contains(MonitorConfig.KEYSTORE) && refused.getMessage().contains("ssh -L 8443:127.0.0.1:8443 "),
                refused.getMessage());
        MonitorConfig anyPort = new MonitorConfig(-1, InetAddress.getByName("0.0.0.0"), tokens, 16, null, null);
        String hint = assertThrows(MonitorSetupException.class, anyPort::check).getMessage();
        assertTrue(hint.contains("ssh -L PORT:127.0.0.1:PORT "), "no -1 in the tunnel's hint: " + hint);
        new MonitorConfig(8443, InetAddress.getLoopbackAddress(), tokens, 16, null, null).check();
        new MonitorConfig(8443, InetAddress.getByName("0.0.0.0"), tokens, 16, dir.resolve("k.p12"), dir.resolve("pw")).check();
        assertThrows(MonitorSetupException.class, () -> new MonitorConfig(8443, InetAddress.getLoopbackAddress(), null, 16, null, null).check());
    }
}
