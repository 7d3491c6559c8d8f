package org.usarsim.wss.shaping;

import java.nio.channels.WritableByteChannel;

/** A target the tests write a direction's bytes to: always open, nothing to close. */
interface OpenTarget extends WritableByteChannel {

    @Override
    default boolean isOpen() {
        return true;
    }

    @Override
    default void close() {
    }
}
