package org.usarsim.wss.protocol;

import java.util.ArrayList;
import java.util.List;

/**
 * Parses one control line (without its line end) into a {@link Command}.
 *
 * <p>More tolerant than the original: whitespace around and between segments, {@code }{}
 * and whitespace inside a segment are accepted. Anything outside braces after the command
 * word, a brace that is never closed, a nested brace or an empty segment is malformed.
 */
public final class CommandParser {

    private CommandParser() {
    }

    /**
     * @return the command, or null for a blank line (empty or spaces only: ignored, never
     *     answered). A line of other whitespace only (tabs, vertical tab, form feed, the separators
     *     0x1C-0x1F, a CR that is not the line end's) is a command with an empty word and no
     *     segment: an unknown method, answered as the original answers one.
     * @throws ProtocolException with the reason to answer
     */
    public static Command parse(String line) throws ProtocolException {
        if (line.chars().allMatch(c -> c == ' ')) {
            return null;
        }
        String text = line.strip();
        if (text.isEmpty()) {
            return new Command("", List.of());
        }
        int i = 0;
        while (i < text.length() && !Character.isWhitespace(text.charAt(i)) && text.charAt(i) != '{') {
            i++;
        }
        String type = text.substring(0, i);
        if (type.isEmpty()) {
            throw new ProtocolException(Replies.MALFORMED_NO_COMMAND);
        }
        if (type.indexOf('}') >= 0) {
            throw new ProtocolException(Replies.MALFORMED_TEXT_OUTSIDE_BRACES);
        }
        List<Command.Field> fields = new ArrayList<>();
        while (true) {
            while (i < text.length() && Character.isWhitespace(text.charAt(i))) {
                i++;
            }
            if (i == text.length()) {
                return new Command(type, fields);
            }
            if (text.charAt(i) != '{') {
                throw new ProtocolException(Replies.MALFORMED_TEXT_OUTSIDE_BRACES);
            }
            int close = text.indexOf('}', i + 1);
            int nested = text.indexOf('{', i + 1);
            if (close < 0) {
                throw new ProtocolException(Replies.MALFORMED_UNCLOSED_BRACE);
            }
            if (nested >= 0 && nested < close) {
                throw new ProtocolException(Replies.MALFORMED_NESTED_BRACE);
            }
            fields.add(field(text.substring(i + 1, close)));
            i = close + 1;
        }
    }

    private static Command.Field field(String segment) throws ProtocolException {
        String content = segment.strip();
        if (content.isEmpty()) {
            throw new ProtocolException(Replies.MALFORMED_EMPTY_SEGMENT);
        }
        int space = 0;
        while (space < content.length() && !Character.isWhitespace(content.charAt(space))) {
            space++;
        }
        return new Command.Field(content.substring(0, space), content.substring(space).strip());
    }
}
