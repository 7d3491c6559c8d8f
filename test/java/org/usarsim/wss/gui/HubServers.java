package org.usarsim.wss.gui;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.hub.core.RatePin;
import org.usarsim.wss.hub.Hub;
import org.usarsim.wss.hub.HubConfig;
import org.usarsim.wss.hub.HubSnapshot;
import org.usarsim.wss.model.ModelProvider;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * The window's {@link Servers} for tests and benchmarks in the test tree: a {@link Hub} of the
 * given configuration per start (the port field and the window's link shaping are not read: the
 * configuration's port and shaping count),
 * with the model's instance for the run, configured with the values, as the application's own
 * servers build one, without the event log.
 */
public final class HubServers implements Servers {

    private final HubConfig config;
    private final List<Hub> hubs = new CopyOnWriteArrayList<>();
    private volatile Running running;

    public HubServers(HubConfig config) {
        this.config = config;
    }

    /** Every hub started so far, in order. */
    public List<Hub> hubs() {
        return hubs;
    }

    /** The server started last (stopped or not), or null before any start. */
    public Running running() {
        return running;
    }

    @Override
    public Running start(String port, ModelProvider model, ModelSettings values, boolean eventLog, boolean record, ShapingConfig shaping,
            WssEventListener listener) throws Exception {
        PropagationModel instance = model.instanceForRun();
        instance.configure(values);
        Hub hub = new Hub(config, instance);
        hub.addListener(listener);
        hub.start();
        hubs.add(hub);
        running = new Running() {
            @Override
            public int port() {
                return hub.controlPort();
            }

            @Override
            public PropagationModel model() {
                return instance;
            }

            @Override
            public HubSnapshot snapshot() {
                return hub.snapshot();
            }

            @Override
            public void force(String robotA, String robotB, Force force, RatePin pin) {
                hub.force(robotA, robotB, force, pin);
            }

            @Override
            public void release(String robotA, String robotB) {
                hub.release(robotA, robotB);
            }

            @Override
            public org.usarsim.wss.routes.RouteTable routes() {
                return hub.routes();
            }

            @Override
            public void stop() {
                hub.close();
            }
        };
        return running;
    }
}
