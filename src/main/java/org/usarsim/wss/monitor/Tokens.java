package org.usarsim.wss.monitor;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * The monitor's tokens (wss.monitor.tokens): lines {@code viewer TOKEN} or {@code operator TOKEN},
 * {@code #} comments and blank lines. A token is asked of every request as
 * {@code Authorization: Bearer TOKEN} and compared with each of the file's in constant time (their
 * SHA-256 digests, {@link MessageDigest#isEqual}, every one of them). No token is ever kept as text
 * or written anywhere.
 */
final class Tokens {

    /** The shortest token taken: a short one is guessed. */
    static final int MIN_LENGTH = 16;
    static final String KEY = "wss.monitor.tokens";
    private static final String BEARER = "Bearer ";

    private record Held(Role role, byte[] digest) {
    }

    private final List<Held> held;

    private Tokens(List<Held> held) {
        this.held = List.copyOf(held);
    }

    /** The file's tokens, once the file passed {@link OwnerOnly}; a missing, empty or malformed file is refused. */
    static Tokens read(Path file) throws MonitorSetupException {
        return parse(OwnerOnly.read(file, KEY), KEY + " = " + file);
    }

    /** The tokens of the text; {@code source} names it in a refusal (which never quotes a token). */
    static Tokens parse(String text, String source) throws MonitorSetupException {
        List<Held> held = new ArrayList<>();
        String[] lines = text.split("\r?\n", -1);
        for (int i = 0; i < lines.length; i++) {
            String line = lines[i].strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            String[] words = line.split("\\s+");
            Role role = switch (words[0].toLowerCase(Locale.ROOT)) {
                case "viewer" -> Role.VIEWER;
                case "operator" -> Role.OPERATOR;
                default -> null;
            };
            if (role == null || words.length != 2) {
                throw new MonitorSetupException(source + ", line " + (i + 1) + ": not 'viewer TOKEN' or 'operator TOKEN'");
            }
            if (words[1].length() < MIN_LENGTH) {
                throw new MonitorSetupException(source + ", line " + (i + 1) + ": a token of fewer than " + MIN_LENGTH
                        + " characters (make one with: openssl rand -hex 32)");
            }
            held.add(new Held(role, digest(words[1])));
        }
        if (held.isEmpty()) {
            throw new MonitorSetupException(source + ": no token (lines 'viewer TOKEN' or 'operator TOKEN')");
        }
        return new Tokens(held);
    }

    /**
     * The role of an {@code Authorization} header's bearer token, or null (no header, another scheme,
     * a token of no line). Every token is compared, whatever matched first.
     */
    Role roleOf(String authorization) {
        if (authorization == null || !authorization.regionMatches(true, 0, BEARER, 0, BEARER.length())) {
            return null;
        }
        byte[] given = digest(authorization.substring(BEARER.length()).strip());
        Role found = null;
        for (Held token : held) {
            if (MessageDigest.isEqual(token.digest(), given) && found != Role.OPERATOR) {
                found = token.role();
            }
        }
        return found;
    }

    private static byte[] digest(String token) {
        try {
            return MessageDigest.getInstance("SHA-256").digest(token.getBytes(StandardCharsets.UTF_8));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every JDK has SHA-256", e);
        }
    }
}
