package org.usarsim.wss.model;

import java.util.Objects;
import java.util.ServiceConfigurationError;
import java.util.function.Supplier;

/**
 * A model as the catalog offers it: its name, the instance made when it was loaded (asked what it
 * declares and shown in the dialogs, never started), and a new instance for each run, so that
 * nothing of one run (its values, its state) reaches the next.
 *
 * <p>The one exception: a model that shows a dialog of its own ({@code isConfigurable()}) keeps
 * what that dialog set in the instance it was shown on, so that instance is each run's, as before
 * the window made one per run.
 */
public final class ModelProvider {

    private final String name;
    private final PropagationModel model;
    private final Supplier<? extends PropagationModel> factory;

    ModelProvider(String name, PropagationModel model, Supplier<? extends PropagationModel> factory) {
        this.name = name;
        this.model = model;
        this.factory = factory;
    }

    /**
     * The model {@code factory} makes, named by its {@code name()}: one instance is made now, to
     * ask; {@link #instanceForRun} makes another each time. A factory that always returns the same
     * instance (a test's {@code () -> model}) runs that instance every time.
     */
    public static ModelProvider of(Supplier<? extends PropagationModel> factory) {
        PropagationModel model = Objects.requireNonNull(factory.get(), "the factory made no model");
        return new ModelProvider(model.name(), model, factory);
    }

    /** The name users pick the model by, as it gave it when it was loaded. */
    public String name() {
        return name;
    }

    /**
     * The instance made when the model was loaded: ask it what it declares ({@code settings()},
     * {@code dialogLayout()}, {@code isConfigurable()}) and show it in the dialogs. A run never
     * uses it (but see the class comment).
     */
    public PropagationModel model() {
        return model;
    }

    /**
     * A new instance, not configured yet, for one run (the {@code ServiceLoader} provider's
     * {@code get()}: the public no-argument constructor); {@link #model()} itself for a model with
     * a dialog of its own.
     *
     * @throws ModelStartException when the instance cannot be made; the message says why
     */
    public PropagationModel instanceForRun() throws ModelStartException {
        try {
            if (model.isConfigurable()) {
                return model;
            }
            PropagationModel made = factory.get();
            if (made == null) {
                throw new ModelStartException("cannot make a new instance: its provider gave none");
            }
            return made;
        } catch (ServiceConfigurationError | RuntimeException e) {
            throw new ModelStartException("cannot make a new instance: " + ModelCatalog.reason(e), e);
        }
    }
}
