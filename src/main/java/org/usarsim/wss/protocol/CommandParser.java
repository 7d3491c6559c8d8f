package org.usarsim.wss.protocol;

import java.util.List;

/**
 * Parses one control line (without its line end) into a {@link Command}: the segment grammar of
 * {@link SegmentParser}, with the control protocol's own blank lines, and each problem answered
 * with its {@code Malformed.Line.*} reason ({@link Replies#malformed}).
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
        if (line.isBlank()) {
            return new Command("", List.of());
        }
        try {
            return SegmentParser.parse(line);
        } catch (SegmentException e) {
            throw new ProtocolException(Replies.malformed(e.problem()));
        }
    }
}
