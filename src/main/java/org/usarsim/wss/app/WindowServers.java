package org.usarsim.wss.app;

import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicReference;
import org.usarsim.wss.gui.Servers;
import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.hub.core.RatePin;
import org.usarsim.wss.hub.HubConfig;
import org.usarsim.wss.hub.HubSnapshot;
import org.usarsim.wss.model.ModelProvider;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.routes.RouteListener;
import org.usarsim.wss.routes.RouteTable;
import org.usarsim.wss.recording.Recorder;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * The window's servers, built as headless mode builds its one ({@link Server}): the settings of
 * the --config file or the defaults, with the window's port, event log choice, recording (to the
 * file's wss.record, or else to a new {@code run-yyyy.MM.dd-HH.mm.ss.SSS.rec} in the event log's
 * folder) and link shaping (the file's wss.force.up pins kept).
 */
final class WindowServers implements Servers {

    private final ConfigFile configFile;
    private final AtomicReference<Server> current = new AtomicReference<>();

    WindowServers(ConfigFile configFile) {
        this.configFile = configFile;
    }

    @Override
    public Running start(String port, ModelProvider model, ModelSettings values, boolean eventLog, boolean record, ShapingConfig shaping,
            WssEventListener listener) throws Server.StartFailure {
        String problem = Setting.find(ConfigKeys.SERVER, "wss.port").problem(port);
        if (problem != null) {
            throw new Server.StartFailure("the port '" + port + "' is not " + problem);
        }
        try {
            configFile.checkFixedPortsFree();
        } catch (IllegalArgumentException e) {
            throw new Server.StartFailure(e.getMessage(), true);
        }
        HubConfig file = configFile.hubConfig();
        HubConfig config = file.withControlPort(Integer.parseInt(port.strip())).withShaping(shaping.withLoss(file.shaping().loss())
                .withSeed(file.shaping().jitter().seed()), file.pins());
        Path recording = record ? configFile.record().orElseGet(() -> Recorder.runFileIn(configFile.eventLogDir())) : null;
        Server server = Server.create(config, model, values, eventLog ? configFile.eventLogDir() : null, recording);
        server.hub().addListener(listener);
        server.monitor(configFile.monitorConfig());
        server.hub().setRouteBase(configFile.routeBase());
        current.set(server);
        try {
            server.start();
        } catch (Server.StartFailure e) {
            current.compareAndSet(server, null);
            throw e;
        }
        return new Running() {
            @Override
            public int port() {
                return server.hub().controlPort();
            }

            @Override
            public PropagationModel model() {
                return server.model();
            }

            @Override
            public HubSnapshot snapshot() {
                return server.hub().snapshot();
            }

            @Override
            public void force(String robotA, String robotB, Force force, RatePin pin) {
                server.hub().force(robotA, robotB, force, pin);
            }

            @Override
            public void release(String robotA, String robotB) {
                server.hub().release(robotA, robotB);
            }

            @Override
            public RouteTable routes() {
                return server.hub().routes();
            }

            @Override
            public void addRouteListener(RouteListener listener) {
                server.hub().addRouteListener(listener);
            }

            @Override
            public void removeRouteListener(RouteListener listener) {
                server.hub().removeRouteListener(listener);
            }

            @Override
            public void stop() {
                current.compareAndSet(server, null);
                server.close();
            }
        };
    }

    /** Stops the server that runs or starts now, if any (SIGTERM while the window is open). */
    void stopCurrent() {
        Server server = current.getAndSet(null);
        if (server != null) {
            server.close();
        }
    }
}
