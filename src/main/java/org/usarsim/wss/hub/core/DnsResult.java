package org.usarsim.wss.hub.core;

/**
 * A DNS's answer ({@link HubCore#dns}): the port's number when OK; the key of a new port when
 * NEEDS_NUMBER (the hub had no number to offer); {@code numberUsed} when the number the hub offered
 * is the port's now.
 */
public record DnsResult(DnsOutcome outcome, int port, PortKey key, boolean numberUsed) {
    static DnsResult of(DnsOutcome outcome) {
        return new DnsResult(outcome, -1, null, false);
    }
}
