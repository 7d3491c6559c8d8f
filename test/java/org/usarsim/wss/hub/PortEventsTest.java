package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.net.ServerSocket;
import java.net.Socket;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.model.WssEventListener;

/** The WSS port events the window follows, and the hub's snapshot, with a real hub and real robots. */
class PortEventsTest {

    private final List<String> events = new CopyOnWriteArrayList<>();

    private final WssEventListener recorder = new WssEventListener() {
        @Override
        public void portAllocated(String from, String to, int targetPort, int wssPort, boolean listening) {
            events.add("allocated " + from + " " + to + " " + targetPort + " " + wssPort + " " + listening);
        }

        @Override
        public void portListening(String from, String to, int targetPort, int wssPort, boolean listening) {
            events.add("listening " + from + " " + to + " " + targetPort + " " + wssPort + " " + listening);
        }

        @Override
        public void portForgotten(String from, String to, int targetPort, int wssPort) {
            events.add("forgotten " + from + " " + to + " " + targetPort + " " + wssPort);
        }
    };

    @Test
    void everyChangeOfAPortIsAnEventAndTheSnapshotIsTheTruth() throws Exception {
        ScriptedModel model = new ScriptedModel();
        try (TestHub server = new TestHub(model, true, 65536)) {
            server.hub.addListener(recorder);
            try (TestRobot r1 = server.robot(); TestRobot r2 = server.robot()) {
                r1.init("r1");
                ServerSocket r2Accepts = r2.initAccepting("r2");
                int target = r2Accepts.getLocalPort();
                int wss = r1.dns("r2", 0);
                String port = "r1 r2 " + target + " " + wss;
                Wait.until("allocated", () -> events.contains("allocated " + port + " true"));

                try (Socket out = r1.connect(wss); Socket in = r2Accepts.accept()) {
                    Wait.until("the link is in the snapshot", () -> server.hub.snapshot().links().size() == 1);
                    HubSnapshot snapshot = server.hub.snapshot();
                    assertEquals(List.of(new HubSnapshot.RobotEntry("r1", "127.0.0.1", List.of()),
                            new HubSnapshot.RobotEntry("r2", "127.0.0.1", List.of(target))), snapshot.robots());
                    assertEquals(List.of(new HubSnapshot.PortEntry("r1", "r2", target, wss, true)), snapshot.ports());
                    assertEquals(List.of(new HubSnapshot.LinkEntry("r1", "r2", target, wss, in.getPort())), snapshot.links());
                }

                model.links().breakConnectionsForPair("r2", "r1");
                Wait.until("stopped listening", () -> events.contains("listening " + port + " false"));
                assertEquals(List.of(new HubSnapshot.PortEntry("r1", "r2", target, wss, false)), server.hub.snapshot().ports());
                model.links().resumeConnectionsForPair("r1", "r2");
                Wait.until("listens again", () -> events.lastIndexOf("listening " + port + " true") > 0);

                model.links().kickOutRobot("r2");
                Wait.until("forgotten", () -> events.contains("forgotten " + port));
                assertEquals(List.of("allocated " + port + " true", "listening " + port + " false",
                        "listening " + port + " true", "forgotten " + port), events);
                HubSnapshot after = server.hub.snapshot();
                assertEquals(List.of("r1"), after.robots().stream().map(HubSnapshot.RobotEntry::name).toList());
                assertEquals(List.of(), after.ports());
                assertEquals(List.of(), after.links());
            }
        }
    }

    @Test
    void portsForgottenByPortMemoryAreEventsAndLeaveTheSnapshot() throws Exception {
        // wss.portMemory 0: a robot's ports are forgotten as it leaves.
        try (TestHub server = new TestHub(new ScriptedModel(), TestHub.config(true, 65536, 0, 1000, 30))) {
            server.hub.addListener(recorder);
            try (TestRobot r1 = server.robot()) {
                r1.init("r1");
                int target;
                int wss;
                try (TestRobot r2 = server.robot()) {
                    target = r2.initAccepting("r2").getLocalPort();
                    wss = r1.dns("r2", 0);
                }
                String port = "r1 r2 " + target + " " + wss;
                Wait.until("forgotten as r2 left", () -> events.contains("forgotten " + port));
                assertEquals(List.of("allocated " + port + " true", "listening " + port + " false", "forgotten " + port),
                        events);
                assertEquals(List.of(), server.hub.snapshot().ports());
            }
        }
    }
}
