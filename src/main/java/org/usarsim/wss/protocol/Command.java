package org.usarsim.wss.protocol;

import java.util.List;

/**
 * One parsed line of the segment grammar ({@link SegmentParser}): {@code TYPE {Key Value} {Key Value} ...}.
 * A control command, a simulator's reply or a world server's request; {@link #value} and
 * {@link #hasNoSegment} are the control protocol's rules.
 *
 * @param type   the word as sent (on a control line, case-sensitive: INIT, GETSS, DNS, REVERSEDNS, ...)
 * @param fields the segments in the order they were sent
 */
public record Command(String type, List<Field> fields) {

    /** One {@code {Key Value}} segment; the value is trimmed and may be empty. */
    public record Field(String key, String value) {
    }

    public Command {
        fields = List.copyOf(fields);
    }

    /**
     * The value of the last segment with this key (case-sensitive), or null when there is none.
     * The last one counts, as in the original: {@code GETSS {Robot A} {Robot B}} asks for B.
     */
    public String value(String key) {
        for (int i = fields.size() - 1; i >= 0; i--) {
            if (fields.get(i).key().equals(key)) {
                return fields.get(i).value();
            }
        }
        return null;
    }

    /** True for a line with no segment at all ({@code INIT}, {@code GETSS} alone): the original takes it for an unknown method. */
    public boolean hasNoSegment() {
        return fields.isEmpty();
    }
}
