package org.usarsim.wss.hub;

/** What an operator forces a pair of robots to: down (no link, even in range) or up (a link the model would break). */
public enum Force {
    DOWN,
    UP
}
