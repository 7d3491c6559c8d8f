package org.usarsim.wss.world;

/** A world file that cannot be read or is wrong; the message says where and what, in one line. */
public final class WorldFileException extends Exception {

    private static final long serialVersionUID = 1L;

    WorldFileException(String message) {
        super(message);
    }
}
