package org.usarsim.wss.monitor;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.util.EnumSet;
import java.util.Set;

/**
 * The one rule for a file holding a secret (the tokens, the keystore's password): it exists and
 * neither its group nor others may read or write it (POSIX permissions; a file system without them
 * is not checked).
 */
final class OwnerOnly {

    private static final Set<PosixFilePermission> OTHERS = EnumSet.of(PosixFilePermission.GROUP_READ, PosixFilePermission.GROUP_WRITE,
            PosixFilePermission.OTHERS_READ, PosixFilePermission.OTHERS_WRITE);

    private OwnerOnly() {
    }

    /** Reads the file whole, once it passed the rule; {@code key} names the setting in the refusal. */
    static String read(Path file, String key) throws MonitorSetupException {
        if (!Files.isRegularFile(file)) {
            throw new MonitorSetupException(key + " = " + file + ": no such file");
        }
        try {
            Set<PosixFilePermission> permissions = Files.getPosixFilePermissions(file);
            Set<PosixFilePermission> open = EnumSet.copyOf(OTHERS);
            open.retainAll(permissions);
            if (!open.isEmpty()) {
                throw new MonitorSetupException(key + " = " + file + ": readable or writable by others than its owner ("
                        + java.nio.file.attribute.PosixFilePermissions.toString(permissions) + "); make it owner-only: chmod 600 " + file);
            }
        } catch (UnsupportedOperationException e) {
            // no POSIX permissions here (Windows): nothing to check
        } catch (IOException e) {
            throw new MonitorSetupException(key + " = " + file + ": cannot read its permissions: " + e.getMessage());
        }
        try {
            return Files.readString(file);
        } catch (IOException e) {
            throw new MonitorSetupException(key + " = " + file + ": cannot read it: " + e.getMessage());
        }
    }
}
