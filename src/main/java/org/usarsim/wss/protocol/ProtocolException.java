package org.usarsim.wss.protocol;

/** A request that gets {@code ERROR {Reason <reason>}}: a malformed line or a bad argument. */
public final class ProtocolException extends Exception {

    private final String reason;

    ProtocolException(String reason) {
        super(reason);
        this.reason = reason;
    }

    /** The reason token, without whitespace. */
    public String reason() {
        return reason;
    }

    /** The whole reply to send. */
    public String reply() {
        return Replies.error(reason);
    }
}
