package org.usarsim.wss.protocol;

/** A line that breaks the segment grammar ({@link SegmentParser}): the first problem, read from the left. */
public final class SegmentException extends Exception {

    /** What is wrong with the line, in the order the parser meets them. */
    public enum Problem {
        /** The line begins with {@code {}: it has no word. */
        NO_WORD("no word before the first {"),
        /** Text after the word that is not in braces, a stray {@code }}, or a {@code }} inside the word. */
        TEXT_OUTSIDE_BRACES("text outside {...}"),
        /** A {@code {} that is never closed. */
        UNCLOSED_BRACE("a { is not closed"),
        /** A {@code {} inside a segment. */
        NESTED_BRACE("a { inside {...}"),
        /** A segment with nothing but whitespace in it. */
        EMPTY_SEGMENT("an empty {}");

        private final String description;

        Problem(String description) {
            this.description = description;
        }

        /** A few words for a log line. */
        public String description() {
            return description;
        }
    }

    private final Problem problem;

    SegmentException(Problem problem) {
        super(problem.description());
        this.problem = problem;
    }

    public Problem problem() {
        return problem;
    }
}
