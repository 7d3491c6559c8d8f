package org.usarsim.wss.hub.core;

/** The outcome of a DNS ({@link HubCore#dns}). */
public enum DnsOutcome { OK, NO_SUCH_ROBOT, NO_SUCH_TARGET_PORT, NO_PORT, NEEDS_NUMBER }
