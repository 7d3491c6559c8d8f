package org.usarsim.wss.monitor;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.KeyStore;
import javax.net.ssl.KeyManagerFactory;
import javax.net.ssl.SSLContext;

/** The monitor's HTTPS: a PKCS12 keystore (wss.monitor.keystore) and its password, the first line of an owner-only file. */
final class Tls {

    private Tls() {
    }

    static SSLContext context(Path keystore, Path passwordFile) throws MonitorSetupException {
        String text = OwnerOnly.read(passwordFile, MonitorConfig.KEYSTORE_PASSWORD_FILE);
        char[] password = text.lines().findFirst().orElse("").toCharArray();
        try (InputStream in = Files.newInputStream(keystore)) {
            KeyStore store = KeyStore.getInstance("PKCS12");
            store.load(in, password);
            KeyManagerFactory keys = KeyManagerFactory.getInstance(KeyManagerFactory.getDefaultAlgorithm());
            keys.init(store, password);
            SSLContext context = SSLContext.getInstance("TLS");
            context.init(keys.getKeyManagers(), null, null);
            return context;
        } catch (IOException | GeneralSecurityException e) {
            throw new MonitorSetupException(MonitorConfig.KEYSTORE + " = " + keystore + ": cannot use it as a PKCS12 keystore with that password: "
                    + e.getMessage());
        } finally {
            java.util.Arrays.fill(password, '\0');
        }
    }
}
