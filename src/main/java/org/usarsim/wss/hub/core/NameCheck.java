package org.usarsim.wss.hub.core;

/** Whether a name is free for a registration ({@link HubCore#register}). */
public enum NameCheck { REGISTERED, TAKEN, TAKEN_BY_LEAVING, CLOSED }
