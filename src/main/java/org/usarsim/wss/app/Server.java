package org.usarsim.wss.app;

import java.io.IOException;
import java.nio.file.Path;
import org.usarsim.wss.hub.CsvEventLog;
import org.usarsim.wss.hub.Hub;
import org.usarsim.wss.hub.HubConfig;
import org.usarsim.wss.model.ModelInputException;
import org.usarsim.wss.model.ModelProvider;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.ModelSettings;

/**
 * One run of the WSS: the hub, its model and the CSV event log. Headless mode and the window
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

    private final HubConfig config;
    private final PropagationModel model;
    private final Hub hub;
    private final CsvEventLog eventLog;

    private Server(HubConfig config, PropagationModel model, CsvEventLog eventLog) {
        this.config = config;
        this.model = model;
        this.hub = new Hub(config, model);
        this.eventLog = eventLog;
        if (eventLog != null) {
            hub.addListener(eventLog);
        }
    }

    /**
     * The hub, a new instance of the model configured with {@code values}, and (when
     * {@code eventLogDir} is not null) the event log there; nothing listens yet.
     */
    static Server create(HubConfig config, ModelProvider provider, ModelSettings values, Path eventLogDir) throws StartFailure {
        PropagationModel model = configured(provider, values);
        CsvEventLog eventLog = null;
        if (eventLogDir != null) {
            try {
                eventLog = CsvEventLog.create(eventLogDir);
            } catch (IOException e) {
                throw new StartFailure("cannot write the event log in " + eventLogDir + ": " + e);
            }
        }
        return new Server(config, model, eventLog);
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
     * Binds the control port and starts the model (configured before). On failure nothing listens
     * (the hub closes what it opened) and the event log is closed.
     */
    void start() throws StartFailure {
        try {
            hub.start();
        } catch (IOException e) {
            closeEventLog();
            throw new StartFailure("cannot listen for robots on " + config.bindAddress().getHostAddress() + ":"
                    + config.controlPort() + ": " + e.getMessage());
        } catch (ModelStartException | RuntimeException e) {
            closeEventLog();
            throw new StartFailure(model.name() + " did not start: " + e.getMessage(), e instanceof ModelInputException);
        }
    }

    private void closeEventLog() {
        if (eventLog != null) {
            eventLog.close();
        }
    }

    /** Closes every socket and the event log. */
    @Override
    public void close() {
        try {
            hub.close();
        } finally {
            closeEventLog();
        }
    }
}
