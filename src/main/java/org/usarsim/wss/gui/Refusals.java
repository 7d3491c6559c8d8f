package org.usarsim.wss.gui;

import javax.swing.JComponent;
import javax.swing.JLabel;

/**
 * What OK found refused in a dialog's fields, in their order: the message names the first in full
 * and counts the others ("(and 2 more marked)"), and the first gets the focus.
 */
final class Refusals {

    private JComponent first;
    private String words;
    private int count;

    /** A field refused, with the words that say why. */
    void add(JComponent field, String why) {
        if (first == null) {
            first = field;
            words = why;
        }
        count++;
    }

    /** Whether any field was refused. */
    boolean any() {
        return first != null;
    }

    /** Says the first refusal in {@code message}, with the count of the others, and focuses its field; false when there is none. */
    boolean show(JLabel message) {
        if (first == null) {
            return false;
        }
        DialogParts.showMessage(message, words + (count > 1 ? " (and " + (count - 1) + " more marked)" : ""));
        first.requestFocusInWindow();
        return true;
    }
}
