package org.usarsim.wss.model;

import java.util.ArrayList;
import java.util.List;
import java.util.ServiceConfigurationError;
import java.util.ServiceLoader;
import java.util.logging.Level;
import java.util.logging.Logger;

/** The propagation models found with {@link ServiceLoader}, NoopPropagationModel first. */
public final class ModelCatalog {

    private static final Logger LOG = Logger.getLogger(ModelCatalog.class.getName());

    private final List<PropagationModel> models;

    private ModelCatalog(List<PropagationModel> models) {
        this.models = List.copyOf(models);
    }

    /** Loads every model the class loader offers; one that fails to load is logged and skipped. */
    public static ModelCatalog load(ClassLoader loader) {
        List<PropagationModel> found = new ArrayList<>();
        var iterator = ServiceLoader.load(PropagationModel.class, loader).iterator();
        while (true) {
            try {
                if (!iterator.hasNext()) {
                    break;
                }
                found.add(iterator.next());
            } catch (ServiceConfigurationError | RuntimeException | LinkageError e) {
                LOG.log(Level.WARNING, "skipping a propagation model that failed to load: " + e.getMessage(), e);
            }
        }
        found.sort((a, b) -> Boolean.compare(!isNoop(a), !isNoop(b)));
        return new ModelCatalog(found);
    }

    private static boolean isNoop(PropagationModel model) {
        return model.name().equals("NoopPropagationModel");
    }

    /** The model named by its {@link PropagationModel#name()}, its class's simple or its qualified name; or null. */
    public PropagationModel find(String name) {
        for (PropagationModel model : models) {
            Class<?> type = model.getClass();
            if (model.name().equals(name) || type.getSimpleName().equals(name) || type.getName().equals(name)) {
                return model;
            }
        }
        return null;
    }

    public List<String> names() {
        return models.stream().map(PropagationModel::name).toList();
    }
}
