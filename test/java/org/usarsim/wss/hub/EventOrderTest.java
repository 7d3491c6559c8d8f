package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.model.WssEventListener;

/** The hub's events reach its listeners in the order its state changed. */
class EventOrderTest {

    private static final int RECONNECTS = 150;

    @Test
    void aFastReconnectIsDeregisteredBeforeItIsRegisteredAgain() throws Exception {
        try (TestHub hub = new TestHub()) {
            List<String> seen = new CopyOnWriteArrayList<>();
            hub.hub.addListener(new WssEventListener() {
                @Override
                public void robotRegistered(String robot, String address, List<Integer> ports) {
                    seen.add("REGISTERED");
                }

                @Override
                public void robotDeregistered(String robot) {
                    seen.add("DEREGISTERED");
                }
            });
            TestRobot robot = hub.robot();
            robot.init("R1");
            for (int i = 0; i < RECONNECTS; i++) {
                TestRobot again = hub.robot(); // connected before the old one drops, INIT right after
                robot.close();
                again.init("R1");
                robot = again;
            }
            robot.close();
            Wait.until("every event arrived", () -> seen.size() == 2 * (RECONNECTS + 1));
            for (int i = 0; i < seen.size(); i++) {
                assertEquals(i % 2 == 0 ? "REGISTERED" : "DEREGISTERED", seen.get(i), "event " + i + " of " + seen.size());
            }
        }
    }
}
