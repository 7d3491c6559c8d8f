package org.usarsim.wss.monitor;

import com.sun.net.httpserver.HttpServer;
import com.sun.net.httpserver.HttpsConfigurator;
import com.sun.net.httpserver.HttpsServer;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.security.SecureRandom;
import java.util.HexFormat;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.logging.Logger;
import javax.net.ssl.SSLContext;
import org.usarsim.wss.Version;
import org.usarsim.wss.net.LogLimiter;

/**
 * The monitor endpoint of a run (docs/monitor.md): an HTTP server (HTTPS with a keystore) of the
 * JDK's {@code com.sun.net.httpserver}, its requests answered on threads of its own
 * ({@code wss-monitor-http-N}), its events by the {@link Publisher}'s thread, each stream written
 * by its own. {@link #open} reads the tokens and the keystore and binds the port (nothing answers
 * yet); {@link #start} answers; {@link #close} stops it all.
 */
public final class MonitorServer implements AutoCloseable {

    private static final Logger LOG = Logger.getLogger(MonitorServer.class.getName());
    /** Threads answering requests (a stream's writing is its own thread's). */
    static final int REQUEST_THREADS = 4;

    private final MonitorConfig config;
    private final Watched watched;
    private final HttpServer server;
    private final Streams streams;
    private final Publisher publisher;
    private final LogEvents logEvents;
    private final LogLimiter limiter = LogLimiter.standard("wss-monitor-warnings");
    private final ExecutorService requests;

    private MonitorServer(MonitorConfig config, Watched watched, Tokens tokens, HttpServer server) {
        this.config = config;
        this.watched = watched;
        this.server = server;
        this.streams = new Streams(config.maxClients());
        String run = HexFormat.of().formatHex(new SecureRandom().generateSeed(4));
        StateJson.Server about = new StateJson.Server(Version.current(), watched.bindAddress(), 0, watched.shaping());
        this.publisher = new Publisher(watched, about, streams, new EventHistory(run, EventHistory.MAX_EVENTS, EventHistory.MAX_BYTES));
        this.logEvents = new LogEvents(publisher);
        AtomicInteger numbers = new AtomicInteger();
        this.requests = Executors.newFixedThreadPool(REQUEST_THREADS, task -> {
            Thread thread = new Thread(task, "wss-monitor-http-" + numbers.incrementAndGet());
            thread.setDaemon(true);
            return thread;
        });
        server.createContext("/", new Requests(tokens, publisher, streams, watched, limiter));
        server.setExecutor(requests);
    }

    /**
     * Checks the configuration, reads the token file (and the keystore), binds the port.
     *
     * @throws MonitorSetupException a configuration the server must not run with (exit 2)
     * @throws IOException           the port cannot be bound
     */
    public static MonitorServer open(MonitorConfig config, Watched watched) throws MonitorSetupException, IOException {
        config.check();
        Tokens tokens = Tokens.read(config.tokens());
        SSLContext tls = config.tls() ? Tls.context(config.keystore(), config.keystorePasswordFile()) : null;
        InetSocketAddress address = new InetSocketAddress(config.bindAddress(), config.port() < 0 ? 0 : config.port());
        HttpServer server;
        if (tls != null) {
            HttpsServer https = HttpsServer.create(address, 0);
            https.setHttpsConfigurator(new HttpsConfigurator(tls));
            server = https;
        } else {
            server = HttpServer.create(address, 0);
        }
        return new MonitorServer(config, watched, tokens, server);
    }

    /** Answers from now on: the hub's events and the log reach the publisher. */
    public void start() {
        publisher.server(new StateJson.Server(Version.current(), watched.bindAddress(), watched.hub().controlPort(), watched.shaping()));
        watched.hub().addListener(publisher);
        watched.hub().addRouteListener(publisher);
        Logger.getLogger("").addHandler(logEvents);
        publisher.start();
        server.start();
        LOG.info("monitor listening on " + (config.tls() ? "https" : "http") + "://" + config.bindAddress().getHostAddress() + ":" + port()
                + " (docs/monitor.md)");
    }

    /** The port it listens on (the OS's choice when configured as -1). */
    public int port() {
        return server.getAddress().getPort();
    }

    @Override
    public void close() {
        Logger.getLogger("").removeHandler(logEvents);
        watched.hub().removeListener(publisher);
        watched.hub().removeRouteListener(publisher);
        publisher.stop();
        streams.closeAll();
        server.stop(0);
        requests.shutdownNow();
        limiter.close();
    }
}
