package org.usarsim.wss.model.noop;

import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.RobotLinkModel;
import org.usarsim.wss.model.WssEventListener;

/** Every pair may connect, at 0 dBm: for testing a team's network code without a simulator. */
public final class NoopPropagationModel implements PropagationModel {

    private volatile boolean active;

    @Override
    public void setRobotLinkModel(RobotLinkModel linkModel) {
    }

    @Override
    public void setEventListener(WssEventListener listener) {
    }

    @Override
    public void start() {
        active = true;
    }

    @Override
    public void shutdown() {
        active = false;
    }

    @Override
    public boolean isActive() {
        return active;
    }

    @Override
    public double getSignalStrengthForPair(String from, String to) {
        return 0;
    }

    @Override
    public boolean connectionIsPossibleForPair(String from, String to) {
        return true;
    }
}
