package org.usarsim.wss.protocol;

import java.util.ArrayList;
import java.util.List;

/**
 * The one parser of the segment grammar the three text protocols share,
 * {@code WORD {Key Value} {Key Value} ...}: the control protocol ({@link CommandParser}), the
 * simulator's replies ({@code model.simulator.SimulatorReplies}) and the world server's requests
 * ({@code world.PositionProtocol}).
 *
 * <p>Whitespace is {@link Character#isWhitespace}; any amount of it (or none) is accepted around the
 * line, between the word and the segments, between segments, and inside a segment around the key and
 * the value. The word ends at the first whitespace or {@code {}. A segment's key is its first word, its
 * value everything after the key's first whitespace, stripped; it may be empty and may hold whitespace.
 * The line is read from the left and the first problem is thrown ({@link SegmentException.Problem}).
 *
 * <p>What a caller does with what it gets is its own: which of two segments with one key counts, whether
 * keys and the word are matched in any case, and whether a problem is an ERROR reply, a refused reply or
 * silence.
 */
public final class SegmentParser {

    private SegmentParser() {
    }

    /** The line's word: after the leading whitespace, up to the first whitespace or {@code {}; may be empty. */
    public static String word(String line) {
        String text = line.strip();
        int end = 0;
        while (end < text.length() && !Character.isWhitespace(text.charAt(end)) && text.charAt(end) != '{') {
            end++;
        }
        return text.substring(0, end);
    }

    /**
     * @return the word (as {@link Command#type()}) and the segments in the order they came
     * @throws SegmentException naming the first problem from the left; a line of whitespace only has
     *     no word
     */
    public static Command parse(String line) throws SegmentException {
        String text = line.strip();
        String word = word(text);
        if (word.isEmpty()) {
            throw new SegmentException(SegmentException.Problem.NO_WORD);
        }
        if (word.indexOf('}') >= 0) {
            throw new SegmentException(SegmentException.Problem.TEXT_OUTSIDE_BRACES);
        }
        List<Command.Field> fields = new ArrayList<>();
        int i = word.length();
        while (true) {
            while (i < text.length() && Character.isWhitespace(text.charAt(i))) {
                i++;
            }
            if (i == text.length()) {
                return new Command(word, fields);
            }
            if (text.charAt(i) != '{') {
                throw new SegmentException(SegmentException.Problem.TEXT_OUTSIDE_BRACES);
            }
            int close = text.indexOf('}', i + 1);
            int nested = text.indexOf('{', i + 1);
            if (close < 0) {
                throw new SegmentException(SegmentException.Problem.UNCLOSED_BRACE);
            }
            if (nested >= 0 && nested < close) {
                throw new SegmentException(SegmentException.Problem.NESTED_BRACE);
            }
            fields.add(field(text.substring(i + 1, close)));
            i = close + 1;
        }
    }

    private static Command.Field field(String segment) throws SegmentException {
        String content = segment.strip();
        if (content.isEmpty()) {
            throw new SegmentException(SegmentException.Problem.EMPTY_SEGMENT);
        }
        int space = 0;
        while (space < content.length() && !Character.isWhitespace(content.charAt(space))) {
            space++;
        }
        return new Command.Field(content.substring(0, space), content.substring(space).strip());
    }
}
