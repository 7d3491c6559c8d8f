package org.usarsim.wss.app;

import java.io.IOException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import org.usarsim.wss.hub.CsvEventLog;
import org.usarsim.wss.hub.Hub;
import org.usarsim.wss.hub.HubConfig;
import org.usarsim.wss.hub.core.HubClock;
import org.usarsim.wss.model.ModelInputException;
import org.usarsim.wss.model.ModelProvider;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.model.simulator.Shadowing;
import org.usarsim.wss.monitor.MonitorConfig;
import org.usarsim.wss.monitor.MonitorServer;
import org.usarsim.wss.monitor.MonitorSetupException;
import org.usarsim.wss.monitor.Watched;
import org.usarsim.wss.recording.Recorder;
import org.usarsim.wss.shaping.JitterConfig;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * One run of the WSS: the hub, its model, the CSV event log and the recording. Headless mode and the window
 * build and start it the same way, through here: each run gets its own model instance, configured
 * here with the values of the run ({@link ModelProvider#instanceForRun}); a failure is a
 * {@link StartFailure} whose message is the one line to show.
 */
final class Server implements AutoCloseable {

    /** Why a server did not start, in one line. */
    static final class StartFailure extends Exception {
        private final boolean badInput;

        StartFailure(String message) {
            this(message, false);
        }

        StartFailure(String message, boolean badInput) {
            super(message);
            this.badInput = badInput;
        }

        /** Whether the model refused its input (a {@link ModelInputException}: a bad recording), not a resource. */
        boolean badInput() {
            return badInput;
        }
    }

    /** A run's one clock: the hub's and its event log's. */

    private final HubConfig config;
    private final PropagationModel model;
    private final Hub hub;
    private final CsvEventLog eventLog;
    private final Recorder recorder;
    /** The run's values of the model's settings (the monitor shows them). */
    private final Map<String, String> modelValues;
    private MonitorConfig monitorConfig = MonitorConfig.OFF;
    private MonitorServer monitor;

    private Server(HubConfig config, PropagationModel model, CsvEventLog eventLog, Recorder recorder, Map<String, String> modelValues) {
        this.config = config;
        this.model = model;
        this.modelValues = modelValues;
        this.hub = new Hub(config, model, HubClock.SYSTEM);
        this.eventLog = eventLog;
        this.recorder = recorder;
        if (eventLog != null) {
            hub.addListener(eventLog);
        }
        if (recorder != null) {
            hub.addListener(recorder);
        }
    }

    /** As {@link #create(HubConfig, ModelProvider, ModelSettings, Path, Path)}, not recording. */
    static Server create(HubConfig config, ModelProvider provider, ModelSettings values, Path eventLogDir) throws StartFailure {
        return create(config, provider, values, eventLogDir, null);
    }

    /**
     * The hub, a new instance of the model configured with {@code values}, (when
     * {@code eventLogDir} is not null) the event log there, and (when {@code record} is not null)
     * the recording of the run to that file (docs/replay.md); nothing listens yet.
     */
    static Server create(HubConfig config, ModelProvider provider, ModelSettings values, Path eventLogDir, Path record)
            throws StartFailure {
        values = withRunSeed(values, config);
        PropagationModel model = configured(provider, values);
        CsvEventLog eventLog = null;
        if (eventLogDir != null) {
            try {
                eventLog = CsvEventLog.create(eventLogDir, HubClock.SYSTEM);
                randomSettings(model, values).forEach(eventLog::setting);
            } catch (IOException e) {
                throw new StartFailure("cannot write the event log in " + eventLogDir + ": " + e);
            }
        }
        Recorder recorder = null;
        if (record != null) {
            try {
                recorder = Recorder.create(record, model.name(), recordedSettings(model, values, config.shaping()));
            } catch (IOException | RuntimeException e) {
                if (eventLog != null) {
                    eventLog.close();
                }
                throw new StartFailure("cannot record the run to " + record + ": " + e);
            }
        }
        Map<String, String> modelValues = new LinkedHashMap<>();
        for (Setting setting : model.settings()) {
            modelValues.put(setting.key(), values.getString(setting.key(), setting.defaultValue()));
        }
        return new Server(config, model, eventLog, recorder, modelValues);
    }

    /**
     * The model's values with the run's seed, {@code wss.seed}, as the hub's shaping has it: every
     * model is handed it as a value (docs/models.md, the SPI), the one seed of the run.
     */
    static ModelSettings withRunSeed(ModelSettings values, HubConfig config) {
        return values.with(ModelSettings.SEED, String.valueOf(config.shaping().jitter().seed()));
    }

    /**
     * The settings the run's random draws depend on, with this run's values: the shadowing's the
     * model declares (shadowing.*), then the run's seed (wss.seed, always): the event log's SETTING lines.
     */
    static Map<String, String> randomSettings(PropagationModel model, ModelSettings values) {
        Map<String, String> settings = new LinkedHashMap<>();
        for (String key : Shadowing.KEYS) {
            Setting setting = Setting.find(model.settings(), key);
            if (setting != null) {
                settings.put(key, values.getString(key, setting.defaultValue()));
            }
        }
        settings.put(ModelSettings.SEED, values.getString(ModelSettings.SEED, String.valueOf(JitterConfig.DEFAULT_SEED)));
        return settings;
    }

    /** A recording's settings: every setting the model declares with this run's value, then the wss.shaping* keys and wss.seed. */
    static Map<String, String> recordedSettings(PropagationModel model, ModelSettings values, ShapingConfig shaping) {
        Map<String, String> settings = new LinkedHashMap<>();
        for (Setting setting : model.settings()) {
            settings.put(setting.key(), values.getString(setting.key(), setting.defaultValue()));
        }
        settings.put(ShapingConfig.SHAPING, shaping.on() ? "on" : "off");
        settings.put(ShapingConfig.RATES, shaping.rates().toString());
        settings.put(ShapingConfig.DELAY_MS, String.valueOf(shaping.delayMs()));
        settings.put(ShapingConfig.AIRTIME, String.valueOf(shaping.airtime()));
        settings.put(ShapingConfig.LOSS, shaping.loss().toString());
        settings.put(ShapingConfig.QUEUE_MS, String.valueOf(shaping.queueMs()));
        settings.put(ShapingConfig.JITTER, String.valueOf(shaping.jitter().ms()));
        settings.put(ShapingConfig.JITTER_DISTRIBUTION, shaping.jitter().distribution().word());
        settings.put(ShapingConfig.REORDER, String.valueOf(shaping.jitter().reorder()));
        settings.put(ShapingConfig.SEED, String.valueOf(shaping.jitter().seed()));
        return settings;
    }

    /** The model's instance for this run, made and configured by {@link #create}. */
    private static PropagationModel configured(ModelProvider provider, ModelSettings values) throws StartFailure {
        try {
            PropagationModel model = provider.instanceForRun();
            model.configure(values);
            return model;
        } catch (ModelStartException | RuntimeException e) {
            throw new StartFailure(provider.name() + " did not start: " + e.getMessage());
        }
    }

    Hub hub() {
        return hub;
    }

    /** This run's model instance (the window's map asks it). */
    PropagationModel model() {
        return model;
    }

    /**
     * Binds the control port and starts the model (configured before); once both are done, the log
     * says where the run is recorded. On failure nothing listens (the hub closes what it opened),
     * the event log is closed and the recording's file deleted: a run that did not start is not
     * recorded (docs/replay.md, "The file").
     */
    void start() throws StartFailure {
        MonitorServer opened = openMonitor();
        try {
            hub.start();
        } catch (IOException e) {
            closeMonitor(opened);
            endRecords(false);
            throw new StartFailure("cannot listen for robots on " + config.bindAddress().getHostAddress() + ":"
                    + config.controlPort() + ": " + e.getMessage());
        } catch (ModelStartException | RuntimeException e) {
            closeMonitor(opened);
            endRecords(false);
            throw new StartFailure(model.name() + " did not start: " + e.getMessage(), e instanceof ModelInputException);
        }
        if (opened != null) {
            opened.start();
            monitor = opened;
        }
        if (recorder != null) {
            recorder.started();
        }
        // A team must be able to tell from the log that wss.shaping took effect.
        ShapingConfig shaping = config.shaping();
        java.util.logging.Logger.getLogger(Server.class.getName()).info(shaping.on()
                ? "links are shaped (wss.shaping = on): rate table " + shaping.rates() + ", delay " + shaping.delayMs() + " ms, airtime "
                        + (shaping.airtime() ? "shared" : "not shared") + ", queue " + shaping.queueMs() + " ms"
                        + (shaping.jitter().ms() > 0 ? ", jitter " + shaping.jitter().ms() + " ms " + shaping.jitter().distribution().word()
                                + (shaping.jitter().reorder() ? ", datagrams reordered" : "") + ", seed " + shaping.jitter().seed() : "")
                : "links are not shaped (wss.shaping = off): forwarded as fast as the sockets go");
    }

    /** The run's monitor endpoint (docs/monitor.md) from these settings; off unless its port is set. Before {@link #start}. */
    void monitor(MonitorConfig settings) {
        monitorConfig = settings;
    }

    /** The monitor's port, or -1 when none runs. */
    int monitorPort() {
        return monitor == null ? -1 : monitor.port();
    }

    /** Reads the monitor's tokens (and keystore) and binds its port, before the hub listens; null when off. */
    private MonitorServer openMonitor() throws StartFailure {
        if (!monitorConfig.on()) {
            return null;
        }
        try {
            return MonitorServer.open(monitorConfig, new Watched(hub, model, modelValues, config.shaping(), config.bindAddress().getHostAddress()));
        } catch (MonitorSetupException e) {
            endRecords(false);
            throw new StartFailure(e.getMessage(), true);
        } catch (IOException e) {
            endRecords(false);
            throw new StartFailure("cannot listen for the monitor on " + monitorConfig.bindAddress().getHostAddress() + ":"
                    + monitorConfig.port() + ": " + e.getMessage());
        }
    }

    private static void closeMonitor(MonitorServer opened) {
        if (opened != null) {
            opened.close();
        }
    }

    /** Closes the event log and the recording (what this run writes besides its sockets); the recording's file is deleted unless {@code kept}. */
    private void endRecords(boolean kept) {
        try {
            if (eventLog != null) {
                eventLog.close();
            }
        } finally {
            if (recorder != null && kept) {
                recorder.close();
            } else if (recorder != null) {
                recorder.discard();
            }
        }
    }

    /** The file this run is recorded to (not the one asked for when that one existed); null when not recording. */
    Path recording() {
        return recorder != null ? recorder.file() : null;
    }

    /** Closes every socket, the event log and the recording. */
    @Override
    public void close() {
        closeMonitor(monitor);
        try {
            hub.close();
        } finally {
            endRecords(true);
        }
    }
}
