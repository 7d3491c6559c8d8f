package org.usarsim.wss.monitor;

import java.net.InetAddress;
import java.nio.file.Path;

/**
 * The wss.monitor.* settings of a run (docs/monitor.md): the port (0: no monitor), the address it
 * listens on, the token file, the most streams at once, and for TLS a PKCS12 keystore and the file
 * whose first line is its password (both null: plain HTTP, loopback only).
 */
public record MonitorConfig(int port, InetAddress bindAddress, Path tokens, int maxClients, Path keystore, Path keystorePasswordFile) {

    public static final String PORT = "wss.monitor.port";
    public static final String BIND_ADDRESS = "wss.monitor.bindAddress";
    public static final String TOKENS = Tokens.KEY;
    public static final String MAX_CLIENTS = "wss.monitor.maxClients";
    public static final String KEYSTORE = "wss.monitor.keystore";
    public static final String KEYSTORE_PASSWORD_FILE = "wss.monitor.keystorePasswordFile";
    public static final String DEFAULT_BIND_ADDRESS = "127.0.0.1";
    public static final int DEFAULT_MAX_CLIENTS = 16;

    /** No monitor. */
    public static final MonitorConfig OFF = new MonitorConfig(0, InetAddress.getLoopbackAddress(), null, DEFAULT_MAX_CLIENTS, null, null);

    /** Whether the monitor runs: a port was configured. */
    public boolean on() {
        return port != 0;
    }

    /** Whether it serves HTTPS. */
    boolean tls() {
        return keystore != null;
    }

    /**
     * The rules across keys, checked before anything listens: a token file, a keystore with its
     * password file, and no plain HTTP on an address other machines reach.
     */
    void check() throws MonitorSetupException {
        if (tokens == null) {
            throw new MonitorSetupException(PORT + " = " + port + " needs " + TOKENS + ": a file of lines 'viewer TOKEN' / 'operator TOKEN' (docs/monitor.md)");
        }
        if (keystore != null && keystorePasswordFile == null) {
            throw new MonitorSetupException(KEYSTORE + " needs " + KEYSTORE_PASSWORD_FILE + " (a file whose first line is its password)");
        }
        if (keystore == null && !bindAddress.isLoopbackAddress()) {
            throw new MonitorSetupException(BIND_ADDRESS + " = " + bindAddress.getHostAddress() + " without TLS would send the tokens in clear:"
                    + " set " + KEYSTORE + " and " + KEYSTORE_PASSWORD_FILE + " (HTTPS), or keep " + BIND_ADDRESS + " = "
                    + DEFAULT_BIND_ADDRESS + " and watch through an SSH tunnel (ssh -L " + tunnelPort() + ":127.0.0.1:" + tunnelPort() + " server)");
        }
    }

    /** The port an SSH tunnel's hint names: the configured one, or PORT when the OS chooses it (-1). */
    private String tunnelPort() {
        return port > 0 ? String.valueOf(port) : "PORT";
    }
}
