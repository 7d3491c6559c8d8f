package org.usarsim.wss.model;

/**
 * The tests' model that does nothing of its own: every pair may connect, at 0 dBm; active from
 * start to shutdown; the server it is given kept for the test ({@link #links()}). A test's model
 * extends it and overrides only what the test is about.
 */
public abstract class StubModel implements PropagationModel {

    private volatile RobotLinkModel links;
    private volatile boolean active;

    @Override
    public void setRobotLinkModel(RobotLinkModel linkModel) {
        links = linkModel;
    }

    @Override
    public void setEventListener(WssEventListener listener) {
    }

    @Override
    public void start() throws ModelStartException {
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

    /** The server the model was given; null before. */
    protected RobotLinkModel links() {
        return links;
    }
}
