package org.usarsim.wss.hub.core;

/** Why a forwarded connection closed: what the statistics of its pair show as the last close. */
public enum CloseReason {
    /** The model broke the pair (out of range, say). */
    OUT_OF_RANGE("out of range"),
    /** The model kicked one of the robots out. */
    KICKED("kicked"),
    /** Either end closed its connection, or reset it. */
    PEER_CLOSED("peer closed"),
    /** The target robot did not accept the WSS's connection. */
    TARGET_REFUSED("target refused"),
    /** An operator forced the pair down. */
    FORCED("forced"),
    /** The server stopped (Stop in the window, SIGTERM headless): it closed every connection. */
    SERVER_STOPPED("server stopped");

    private final String text;

    CloseReason(String text) {
        this.text = text;
    }

    /** How the window and the log say it. */
    @Override
    public String toString() {
        return text;
    }
}
