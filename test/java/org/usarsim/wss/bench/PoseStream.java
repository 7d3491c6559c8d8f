package org.usarsim.wss.bench;

import java.util.List;

/** A rosbridge publishing the CPU run's moving robots ({@link Circles}) while it lasts. */
interface PoseStream extends AutoCloseable {

    /** The WSS's settings that read it: positions, the address, the topic and its type. */
    List<String> wssSettings();

    /** Stops publishing, and says what was published (for the report). */
    String finish() throws Exception;
}
