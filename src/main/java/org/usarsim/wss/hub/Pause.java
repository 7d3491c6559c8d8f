package org.usarsim.wss.hub;

/** A short pause before trying again after a failure that may pass (no descriptors left). */
final class Pause {

    private static final long MILLIS = 100;

    private Pause() {
    }

    static void briefly() {
        try {
            Thread.sleep(MILLIS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
