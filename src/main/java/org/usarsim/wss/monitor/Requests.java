package org.usarsim.wss.monitor;

import com.sun.net.httpserver.HttpExchange;
import com.sun.net.httpserver.HttpHandler;
import java.io.IOException;
import java.io.InputStream;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;
import java.util.logging.Level;
import java.util.logging.Logger;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.usarsim.wss.net.LogLimiter;
import org.usarsim.wss.protocol.LineSplitter;
import org.usarsim.wss.protocol.Replies;

/**
 * Every request to the monitor (docs/monitor.md): the token first (401), then the path (404), the
 * method (405) and the role (403), then the answer. A token is never logged, quoted or echoed; a
 * refused token is one line naming the address, limited as the hub's warnings are.
 */
final class Requests implements HttpHandler {

    private static final Logger LOG = Logger.getLogger(Requests.class.getName());
    private static final Pattern REASON = Pattern.compile("^ERROR \\{Reason ([^}]*)\\}");

    private final Tokens tokens;
    private final Publisher publisher;
    private final Streams streams;
    private final Watched watched;
    private final LogLimiter limiter;
    private final AtomicLong unauthorized = new AtomicLong();

    Requests(Tokens tokens, Publisher publisher, Streams streams, Watched watched, LogLimiter limiter) {
        this.tokens = tokens;
        this.publisher = publisher;
        this.streams = streams;
        this.watched = watched;
        this.limiter = limiter;
    }

    long unauthorized() {
        return unauthorized.get();
    }

    @Override
    public void handle(HttpExchange exchange) throws IOException {
        try {
            answer(exchange);
        } catch (IOException e) {
            LOG.fine(() -> "monitor: a request from " + who(exchange) + " failed: " + e);
            exchange.close();
        } catch (RuntimeException e) {
            LOG.log(Level.WARNING, "monitor: failed to answer " + exchange.getRequestMethod() + " " + exchange.getRequestURI().getPath()
                    + " from " + who(exchange) + ": " + e, e);
            Answers.error(exchange, 500, "internal error");
        }
    }

    private void answer(HttpExchange exchange) throws IOException {
        Role role = tokens.roleOf(exchange.getRequestHeaders().getFirst("Authorization"));
        if (role == null) {
            unauthorized.incrementAndGet();
            InetSocketAddress from = exchange.getRemoteAddress();
            limiter.log(LOG, Level.WARNING, "unauthorized monitor requests", from.getAddress(),
                    "monitor: refused a request from " + from.getAddress().getHostAddress() + " (401: no token or a wrong one)", null);
            exchange.getResponseHeaders().set("WWW-Authenticate", "Bearer realm=\"wss\"");
            Answers.error(exchange, 401, "unauthorized");
            return;
        }
        String path = exchange.getRequestURI().getPath();
        boolean operator = role == Role.OPERATOR;
        switch (path) {
            case "/api/state" -> {
                if (method(exchange, "GET")) {
                    Answers.json(exchange, 200, publisher.state(operator));
                }
            }
            case "/api/events" -> {
                if (method(exchange, "GET")) {
                    events(exchange, operator);
                }
            }
            case "/metrics" -> {
                if (method(exchange, "GET")) {
                    Metrics.Own own = new Metrics.Own(streams.count(), streams.cut(), streams.dropped() + publisher.dropped(), unauthorized());
                    Answers.send(exchange, 200, Metrics.CONTENT_TYPE, Metrics.text(watched.hub().snapshot(), own, publisher.routes()));
                }
            }
            case "/api/force" -> command(exchange, operator, "FORCE");
            case "/api/replay" -> command(exchange, operator, "REPLAY");
            default -> Answers.error(exchange, 404, "not found");
        }
    }

    /** Whether the request's method is the one the path takes; else answered 405. */
    private static boolean method(HttpExchange exchange, String wanted) throws IOException {
        if (exchange.getRequestMethod().equals(wanted)) {
            return true;
        }
        exchange.getResponseHeaders().set("Allow", wanted);
        Answers.error(exchange, 405, "method not allowed");
        return false;
    }

    private void events(HttpExchange exchange, boolean operator) throws IOException {
        if (!streams.reserve()) {
            Answers.error(exchange, 503, "too many streams");
            return;
        }
        exchange.getResponseHeaders().set("Content-Type", "text/event-stream; charset=utf-8");
        exchange.getResponseHeaders().set("Cache-Control", "no-store");
        exchange.getResponseHeaders().set("X-Accel-Buffering", "no");
        EventStream stream = new EventStream(exchange, who(exchange), streams::release);
        try {
            exchange.sendResponseHeaders(200, 0);
        } catch (IOException e) {
            streams.release(null);
            throw e;
        }
        if (!publisher.join(stream, exchange.getRequestHeaders().getFirst("Last-Event-ID"), operator)) {
            streams.release(null);
            exchange.close();
        }
    }

    /** POST /api/force and /api/replay: the body is the command's segments, answered as the control port answers them. */
    private void command(HttpExchange exchange, boolean operator, String word) throws IOException {
        if (!method(exchange, "POST")) {
            return;
        }
        if (!operator) {
            Answers.error(exchange, 403, "operator token needed");
            return;
        }
        String body = body(exchange);
        if (body == null) {
            answerReply(exchange, Replies.error(Replies.LINE_TOO_LONG));
            return;
        }
        body = body.replaceFirst("[\r\n]+$", "");
        if (body.indexOf('\n') >= 0 || body.indexOf('\r') >= 0) {
            Answers.error(exchange, 400, "the body is one line");
            return;
        }
        String line = body.isBlank() ? word : word + " " + body;
        InetSocketAddress from = exchange.getRemoteAddress();
        answerReply(exchange, watched.hub().operatorLine(line, from.getAddress(), who(exchange) + " (monitor)"));
    }

    private static void answerReply(HttpExchange exchange, String reply) throws IOException {
        Map<String, Object> json = new LinkedHashMap<>();
        Matcher error = REASON.matcher(reply);
        if (error.find()) {
            json.put("error", error.group(1));
        }
        json.put("reply", reply);
        Answers.json(exchange, json.containsKey("error") ? 400 : 200, json);
    }

    /** The body as text, or null when it is longer than a control line may be. */
    private static String body(HttpExchange exchange) throws IOException {
        try (InputStream in = exchange.getRequestBody()) {
            byte[] bytes = in.readNBytes(LineSplitter.MAX_LINE_BYTES + 1);
            return bytes.length > LineSplitter.MAX_LINE_BYTES ? null : new String(bytes, StandardCharsets.UTF_8);
        }
    }

    private static String who(HttpExchange exchange) {
        InetSocketAddress from = exchange.getRemoteAddress();
        return from.getAddress().getHostAddress() + ":" + from.getPort();
    }
}
