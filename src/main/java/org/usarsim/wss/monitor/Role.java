package org.usarsim.wss.monitor;

/** What a token lets its holder do: a viewer reads; an operator also forces pairs and moves the replay. */
enum Role {
    VIEWER, OPERATOR
}
