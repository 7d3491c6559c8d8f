package org.usarsim.wss.model.simulator;

import java.io.IOException;

/** The simulator answered something that is not a reply we understand. */
final class SimulatorReplyException extends IOException {

    SimulatorReplyException(String message) {
        super(message);
    }
}
