package org.usarsim.wss.attach;

import java.io.IOException;
import java.io.InputStream;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.KeyStore;
import java.security.cert.Certificate;
import java.security.cert.CertificateFactory;
import java.time.Duration;
import javax.net.ssl.SSLContext;
import javax.net.ssl.TrustManagerFactory;
import org.usarsim.wss.ros.JsonException;
import org.usarsim.wss.ros.JsonLimits;
import org.usarsim.wss.ros.JsonNode;

/**
 * The requests an attached window makes of a WSS's monitor endpoint (docs/monitor.md), through the
 * JDK's HttpClient, each with {@code Authorization: Bearer TOKEN} (the token never in a URL, a log
 * line or an error). Over https it trusts the JDK's default trust store, or only the certificate
 * given ({@code --trust-cert}, PEM as {@code keytool -exportcert -rfc} writes it). Blocking: never
 * on the event thread.
 */
final class MonitorHttp {

    private static final Duration CONNECT_TIMEOUT = Duration.ofSeconds(5);
    private static final Duration REQUEST_TIMEOUT = Duration.ofSeconds(10);

    private final URI base;
    private final String token;
    private final HttpClient client;

    MonitorHttp(URI base, String token, Path trustCert) throws IOException {
        this.base = base;
        this.token = token;
        HttpClient.Builder builder = HttpClient.newBuilder().connectTimeout(CONNECT_TIMEOUT).version(HttpClient.Version.HTTP_1_1);
        if (trustCert != null) {
            builder.sslContext(trusting(trustCert));
        }
        client = builder.build();
    }

    /** {@code host:port}, as the title and the banner name the server. */
    String server() {
        int port = base.getPort() >= 0 ? base.getPort() : "https".equals(base.getScheme()) ? 443 : 80;
        return base.getHost() + ":" + port;
    }

    /** GET /api/state: the state object; an IOException saying why when it is not had (a refused token: 401). */
    JsonNode state() throws IOException, InterruptedException {
        HttpResponse<String> answer;
        try {
            answer = client.send(request("/api/state").timeout(REQUEST_TIMEOUT).GET().build(),
                    HttpResponse.BodyHandlers.ofString(StandardCharsets.UTF_8));
        } catch (javax.net.ssl.SSLHandshakeException e) {
            throw new IOException("the certificate of the server at " + server() + " is not trusted (a certificate of its own:"
                    + " give it with --trust-cert FILE, or the dialog's Certificate): " + e.getMessage(), e);
        }
        refused(answer.statusCode(), answer.body());
        return json(answer.body());
    }

    /** GET /api/events from after {@code lastEventId} (null: from a snapshot): the stream's body. */
    InputStream events(String lastEventId) throws IOException, InterruptedException {
        HttpRequest.Builder request = request("/api/events").header("Accept", "text/event-stream").GET();
        if (lastEventId != null) {
            request.header("Last-Event-ID", lastEventId);
        }
        HttpResponse<InputStream> answer = client.send(request.build(), HttpResponse.BodyHandlers.ofInputStream());
        if (answer.statusCode() != 200) {
            try (InputStream body = answer.body()) {
                refused(answer.statusCode(), new String(body.readNBytes(4096), StandardCharsets.UTF_8));
            }
        }
        return answer.body();
    }

    /** POST {@code path} with a control line's segments: the control port's reply; an IOException with its ERROR otherwise. */
    String post(String path, String segments) throws IOException, InterruptedException {
        HttpResponse<String> answer = client.send(request(path).timeout(REQUEST_TIMEOUT)
                        .header("Content-Type", "text/plain; charset=utf-8")
                        .POST(HttpRequest.BodyPublishers.ofString(segments, StandardCharsets.UTF_8)).build(),
                HttpResponse.BodyHandlers.ofString(StandardCharsets.UTF_8));
        refused(answer.statusCode(), answer.body());
        try {
            return json(answer.body()).get("reply").string();
        } catch (JsonException e) {
            throw new IOException("the server's answer to " + path + " is not what docs/monitor.md says: " + e.getMessage());
        }
    }

    private HttpRequest.Builder request(String path) {
        return HttpRequest.newBuilder(base.resolve(path)).header("Authorization", "Bearer " + token);
    }

    /** Nothing when the status is 200; else an IOException in words (the server's error field, or its reply's reason). */
    private void refused(int status, String body) throws IOException {
        if (status == 200) {
            return;
        }
        String error = "";
        try {
            JsonNode answer = json(body);
            JsonNode field = answer.optional("reply") != null ? answer.get("reply") : answer.get("error");
            error = ": " + field.string();
        } catch (IOException | JsonException | RuntimeException e) {
            // no JSON: the status alone says it
        }
        throw new IOException(switch (status) {
            case 401 -> "the server at " + server() + " refused the token (401)";
            case 403 -> "the server at " + server() + " wants an operator's token for that (403)";
            case 503 -> "the server at " + server() + " has too many windows attached (503)";
            default -> "the server at " + server() + " answered " + status;
        } + error);
    }

    private static JsonNode json(String text) throws IOException {
        try {
            return JsonNode.parse(text, JsonLimits.DEFAULT);
        } catch (JsonException e) {
            throw new IOException("the server's answer is not JSON: " + e.getMessage());
        }
    }

    /** An SSLContext that trusts only the PEM certificate of that file. */
    static SSLContext trusting(Path pem) throws IOException {
        try (InputStream in = Files.newInputStream(pem)) {
            Certificate certificate = CertificateFactory.getInstance("X.509").generateCertificate(in);
            KeyStore store = KeyStore.getInstance(KeyStore.getDefaultType());
            store.load(null, null);
            store.setCertificateEntry("wss", certificate);
            TrustManagerFactory trust = TrustManagerFactory.getInstance(TrustManagerFactory.getDefaultAlgorithm());
            trust.init(store);
            SSLContext context = SSLContext.getInstance("TLS");
            context.init(null, trust.getTrustManagers(), null);
            return context;
        } catch (GeneralSecurityException e) {
            throw new IOException(pem + " is not a certificate (PEM, as keytool -exportcert -rfc writes it): " + e.getMessage(), e);
        }
    }
}
