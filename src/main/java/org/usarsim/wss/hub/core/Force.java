package org.usarsim.wss.hub.core;

/** What an operator forces a pair of robots to: down (no link, even in range) or up (a link the model would break). */
public enum Force {
    DOWN,
    UP
}
