package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Map;
import java.util.Properties;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.gui.Servers;
import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.hub.core.RatePin;
import org.usarsim.wss.hub.HubSnapshot;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.hub.Wait;
import org.usarsim.wss.model.ModelProvider;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.shaping.RateTable;
import org.usarsim.wss.shaping.ShapingConfig;
import org.usarsim.wss.model.noop.NoopPropagationModel;

/**
 * The window's servers as the application builds them ({@link WindowServers}): the --config
 * file's forced pairs hold there too, and the window's force and release reach the hub, with a
 * pinned rate too.
 */
class WindowServersForceTest {

    @Test
    void theFilesForcedPairsHoldAndTheWindowForcesAndReleases() throws Exception {
        Properties file = new Properties();
        file.setProperty("wss.bindAddress", "127.0.0.1");
        file.setProperty("wss.force.down", "r1:r2");
        WindowServers servers = new WindowServers(ConfigFile.of(file, "test"));
        Servers.Running running = servers.start("0", ModelProvider.of(NoopPropagationModel::new), new ModelSettings(Map.of()), false, false,
                ShapingConfig.OFF, new WssEventListener() { });
        try (TestRobot r1 = new TestRobot(running.port(), "127.0.0.1"); TestRobot r2 = new TestRobot(running.port(), "127.0.0.1")) {
            r1.init("r1");
            r2.initAccepting("r2");
            r1.dns("r2", 0);
            assertEquals(List.of(false), listening(running), "forced down by the file");
            running.release("r2", "r1");
            assertEquals(List.of(true), listening(running), "released to NoopPropagationModel");
            running.force("r1", "r2", Force.DOWN);
            assertEquals(List.of(false), listening(running), "forced down by the window");
        } finally {
            running.stop();
        }
        Wait.until("stopped", () -> running.snapshot().robots().isEmpty());
    }

    private static List<Boolean> listening(Servers.Running running) {
        return running.snapshot().ports().stream().map(HubSnapshot.PortEntry::listening).toList();
    }

    @Test
    void theWindowsPinnedRateReachesTheHub() throws Exception {
        Properties file = new Properties();
        file.setProperty("wss.bindAddress", "127.0.0.1");
        WindowServers servers = new WindowServers(ConfigFile.of(file, "test"));
        ShapingConfig shaped = new ShapingConfig(true, RateTable.DEFAULT, ShapingConfig.DEFAULT_DELAY_MS, true); // the window's Link shaping
        Servers.Running running = servers.start("0", ModelProvider.of(NoopPropagationModel::new), new ModelSettings(Map.of()), false, false,
                shaped, new WssEventListener() { });
        try (TestRobot r1 = new TestRobot(running.port(), "127.0.0.1"); TestRobot r2 = new TestRobot(running.port(), "127.0.0.1")) {
            r1.init("r1");
            r2.initAccepting("r2");
            r1.dns("r2", 0);
            running.force("r2", "r1", Force.UP, new RatePin(1_000_000, 50));
            Wait.until("the pinned rate both ways", () -> rates(running).equals(List.of(1_000_000L, 1_000_000L)));
            running.release("r1", "r2");
            Wait.until("the table's rate again (Noop: its top rate)", () -> rates(running).equals(List.of(54_000_000L, 54_000_000L)));
        } finally {
            running.stop();
        }
    }

    private static List<Long> rates(Servers.Running running) {
        return running.snapshot().pairs().stream().flatMap(pair -> java.util.stream.Stream.of(pair.linkRateFirstToSecond(),
                pair.linkRateSecondToFirst())).toList();
    }
}
