package org.usarsim.wss.protocol;

import java.util.List;

/**
 * One parsed control line: {@code TYPE {Key Value} {Key Value} ...}.
 *
 * @param type   the command word, case-sensitive (INIT, GETSS, DNS, REVERSEDNS, ...)
 * @param fields the segments in the order they were sent
 */
public record Command(String type, List<Field> fields) {

    /** One {@code {Key Value}} segment; the value is trimmed and may be empty. */
    public record Field(String key, String value) {
    }

    public Command {
        fields = List.copyOf(fields);
    }

    /** The value of the first segment with this key (case-sensitive), or null when there is none. */
    public String value(String key) {
        for (Field field : fields) {
            if (field.key().equals(key)) {
                return field.value();
            }
        }
        return null;
    }
}
