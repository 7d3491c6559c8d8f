package org.usarsim.wss.hub.core;

/** A robot's control connection as the core sees it: whose a registration is, and what a kick closes. */
public interface RobotSession {

    /** Closes the control connection (a kick). */
    void close();
}
