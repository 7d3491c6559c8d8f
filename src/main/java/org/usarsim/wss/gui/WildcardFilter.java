package org.usarsim.wss.gui;

import java.util.regex.Pattern;
import javax.swing.RowFilter;
import javax.swing.table.TableModel;

/**
 * The filter of the ports and connections tables, as the original's: the text, case-insensitive,
 * with {@code *} for any characters and {@code ?} for one, found anywhere in "from to" (the first
 * two columns joined by a space). Empty text shows every row.
 */
final class WildcardFilter {

    private WildcardFilter() {
    }

    /** The row filter for that text; null (no filter) when it is blank. */
    static RowFilter<TableModel, Integer> of(String text) {
        if (text.isBlank()) {
            return null;
        }
        Pattern pattern = pattern(text.strip());
        return new RowFilter<>() {
            @Override
            public boolean include(Entry<? extends TableModel, ? extends Integer> entry) {
                return pattern.matcher(entry.getStringValue(0) + " " + entry.getStringValue(1)).find();
            }
        };
    }

    static Pattern pattern(String text) {
        StringBuilder regex = new StringBuilder();
        StringBuilder literal = new StringBuilder();
        for (char c : text.toCharArray()) {
            if (c == '*' || c == '?') {
                if (literal.length() > 0) {
                    regex.append(Pattern.quote(literal.toString()));
                    literal.setLength(0);
                }
                regex.append(c == '*' ? ".*" : ".");
            } else {
                literal.append(c);
            }
        }
        if (literal.length() > 0) {
            regex.append(Pattern.quote(literal.toString()));
        }
        return Pattern.compile(regex.toString(), Pattern.CASE_INSENSITIVE | Pattern.UNICODE_CASE);
    }
}
