package org.usarsim.wss;

import java.io.IOException;
import java.io.InputStream;
import java.util.Properties;

/**
 * The WSS's version: the pom's, written into {@code version.properties} by the build. Shown by
 * {@code wss --version}, the window's title and its About dialog.
 */
public final class Version {

    private static final String CURRENT = read();

    private Version() {
    }

    /** The version, e.g. {@code 0.1.0-SNAPSHOT}; "unknown" when the classes were not built by Maven. */
    public static String current() {
        return CURRENT;
    }

    private static String read() {
        try (InputStream in = Version.class.getResourceAsStream("version.properties")) {
            if (in == null) {
                return "unknown";
            }
            Properties properties = new Properties();
            properties.load(in);
            String version = properties.getProperty("version", "").strip();
            return version.isEmpty() || version.startsWith("${") ? "unknown" : version;
        } catch (IOException e) {
            return "unknown";
        }
    }
}
