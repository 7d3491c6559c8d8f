package org.usarsim.wss.model.simulator;

import java.util.function.Consumer;
import org.usarsim.wss.ros.Json;
import org.usarsim.wss.ros.JsonException;
import org.usarsim.wss.ros.JsonLimits;
import org.usarsim.wss.ros.JsonNode;

/**
 * Whole rosbridge messages out of their pieces, up to a size limit: the WebSocket's fragments of
 * one text message, and rosbridge's own {@code fragment} ops (a message longer than a
 * connection's {@code fragment_size}, sent as {@code {"op":"fragment","id":ID,"data":PART,
 * "num":I,"total":N}} in order, as rosbridge_library's {@code fragmentation.py} writes them: the
 * id 0 for every publish, {@code total} by Python 3's true division: 3.95 for 3 parts). A longer message
 * is dropped, said to {@link Problems}, and the next is whole again. Used by the WebSocket's
 * thread only.
 */
final class MessageAssembler {

    /** Where what cannot be assembled is said. */
    interface Problems {
        void said(String what);
    }

    private final int maxChars;
    private final Problems problems;
    private final Consumer<String> whole;

    /** The WebSocket message being reassembled. */
    private final StringBuilder message = new StringBuilder();
    private boolean dropping;
    /** The rosbridge fragments being put together: their id, how many, the next expected. */
    private final StringBuilder fragments = new StringBuilder();
    private String fragmentId;
    private long fragmentTotal;
    private long fragmentNext;

    /** @param whole what takes each whole message */
    MessageAssembler(int maxChars, Problems problems, Consumer<String> whole) {
        this.maxChars = maxChars;
        this.problems = problems;
        this.whole = whole;
    }

    /** A fragment of a WebSocket message: kept up to the size limit, the whole handed on at its last; a longer one dropped. */
    void piece(CharSequence data, boolean last) {
        if (!dropping && message.length() + data.length() > maxChars) {
            dropping = true;
            message.setLength(0);
            problems.said("a message longer than " + maxChars + " characters (rosbridge.maxMessage): dropped");
        }
        if (!dropping) {
            message.append(data);
        }
        if (last) {
            if (!dropping) {
                String text = message.toString();
                message.setLength(0);
                whole.accept(text);
            }
            dropping = false;
            if (message.capacity() > 1 << 20) {
                message.trimToSize();
            }
        }
    }

    /**
     * A rosbridge {@code fragment} op: its data kept until the last of its message, which is then
     * handed on; one out of order, or of another message before the last, drops what was kept.
     */
    void fragment(JsonNode op) throws JsonException {
        // rosbridge writes the id 0 (a number) for every publish, and total as ((length - 1) / size) + 1 by Python 3's
        // true division (3.95 for 3 parts): the number of parts is its whole part.
        String id = Json.write(op.get("id").value());
        String data = op.get("data").string();
        long num = op.get("num").integer(0, Integer.MAX_VALUE);
        double count = op.get("total").number();
        if (!(count >= 1 && count <= Integer.MAX_VALUE)) {
            throw op.get("total").problem("a number of fragments, not " + count);
        }
        long total = (long) Math.floor(count);
        if (num == 0) {
            if (fragmentId != null) {
                problems.said("the fragments of message " + fragmentId + " without their last: dropped");
            }
            fragmentId = id;
            fragmentTotal = total;
            fragmentNext = 0;
            fragments.setLength(0);
        } else if (!id.equals(fragmentId) || num != fragmentNext || total != fragmentTotal) {
            if (fragmentId != null) {
                problems.said("fragment " + num + " of " + total + " of message " + id + " out of order: dropped");
                forget();
            }
            return;
        }
        if (fragments.length() + data.length() > maxChars) {
            problems.said("a message longer than " + maxChars + " characters (rosbridge.maxMessage) in fragments: dropped");
            forget();
            return;
        }
        fragments.append(data);
        fragmentNext++;
        if (fragmentNext == fragmentTotal) {
            String text = fragments.toString();
            forget();
            whole.accept(text);
        }
    }

    private void forget() {
        fragmentId = null;
        fragments.setLength(0);
        if (fragments.capacity() > 1 << 20) {
            fragments.trimToSize();
        }
    }

    /** The limits a whole message is parsed with. */
    JsonLimits limits() {
        return JsonLimits.DEFAULT.withMaxChars(maxChars);
    }
}
