package org.usarsim.wss.model;

import java.io.IOException;
import java.net.URLClassLoader;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.ServiceConfigurationError;
import java.util.ServiceLoader;
import java.util.logging.Logger;

/**
 * The propagation models: the built-in ones, found with {@link ServiceLoader} on the application's
 * class path, the default model ({@link #DEFAULT_MODEL}) first; then those of the plugin jars in each given folder
 * ({@link PluginFolder}), folder by folder, jars in name order. A model that fails to load, whose
 * {@code settings()} declaration is broken ({@link Setting#declarationProblem}), or whose name is
 * taken by one loaded before it, is reported with a WARNING and skipped. Each model is offered as a
 * {@link ModelProvider}: the instance made when it was loaded, to ask what it declares, and a new
 * instance for each run (its {@link ServiceLoader.Provider}'s {@code get()}).
 */
public final class ModelCatalog {

    private static final Logger LOG = Logger.getLogger(ModelCatalog.class.getName());

    /** The model a run uses unless told otherwise (wss.model, the window's first run): the one that changes nothing. */
    public static final String DEFAULT_MODEL = "NoopPropagationModel";

    /** More failures than this from one source: its ServiceLoader is not getting anywhere. */
    private static final int MAX_FAILURES = 100;

    /** The models by name, in load order. */
    private final Map<String, ModelProvider> models;

    private ModelCatalog(Map<String, ModelProvider> models) {
        this.models = models;
    }

    /** The built-in models only. */
    public static ModelCatalog load(ClassLoader loader) {
        return load(loader, List.of());
    }

    /**
     * The built-in models that {@code loader} offers, then the plugins of each folder in order
     * (a folder that does not exist has none). Never fails: what cannot be loaded is logged.
     */
    public static ModelCatalog load(ClassLoader loader, List<Path> pluginFolders) {
        Map<String, ModelProvider> models = new LinkedHashMap<>();
        Map<String, String> sources = new LinkedHashMap<>();
        List<ModelProvider> builtIn = instantiate(ServiceLoader.load(PropagationModel.class, loader), "the class path");
        builtIn.sort((a, b) -> Boolean.compare(!a.name().equals(DEFAULT_MODEL), !b.name().equals(DEFAULT_MODEL)));
        for (ModelProvider model : builtIn) {
            add(models, sources, model, "the class path");
        }
        List<Path> seen = new ArrayList<>();
        for (Path folder : pluginFolders) {
            Path key = identity(folder);
            if (seen.contains(key)) {
                LOG.fine("plugin folder " + folder + " was searched already");
                continue;
            }
            seen.add(key);
            for (Path jar : PluginFolder.jars(folder)) {
                PluginFolder.open(jar, loader).ifPresent(jarLoader -> loadPlugin(jar, jarLoader, models, sources));
            }
        }
        return new ModelCatalog(models);
    }

    private static void loadPlugin(Path jar, URLClassLoader jarLoader, Map<String, ModelProvider> models,
            Map<String, String> sources) {
        boolean used = false;
        for (ModelProvider model : instantiate(ServiceLoader.load(PropagationModel.class, jarLoader), jar.toString())) {
            if (add(models, sources, model, jar.toString())) {
                LOG.info("loaded propagation model " + model.name() + " from " + jar);
                used = true;
            }
        }
        if (!used) {
            try {
                jarLoader.close();
            } catch (IOException e) {
                LOG.fine("cannot close the class loader of " + jar + ": " + e);
            }
        }
    }

    /** Adds the model unless its name is taken (first wins); whether it was added. */
    private static boolean add(Map<String, ModelProvider> models, Map<String, String> sources, ModelProvider model, String source) {
        String taken = sources.get(model.name());
        if (taken != null) {
            LOG.warning("skipping a propagation model in " + source + ": " + model.model().getClass().getName()
                    + " is called " + model.name() + ", the name of a model already loaded from " + taken);
            return false;
        }
        models.put(model.name(), model);
        sources.put(model.name(), source);
        return true;
    }

    /**
     * Every model the loader offers, built once and named; each one that throws while being found,
     * built or named is logged as a WARNING naming {@code source} and the reason, and skipped.
     */
    private static List<ModelProvider> instantiate(ServiceLoader<PropagationModel> loader, String source) {
        List<ModelProvider> found = new ArrayList<>();
        Iterator<ServiceLoader.Provider<PropagationModel>> iterator = loader.stream().iterator();
        int failures = 0;
        while (true) {
            PropagationModel model = null;
            try {
                if (!iterator.hasNext()) {
                    break;
                }
                ServiceLoader.Provider<PropagationModel> provider = iterator.next();
                model = provider.get();
                String name = model.name();
                if (name == null || name.isBlank()) {
                    LOG.warning("skipping a propagation model in " + source + ": " + model.getClass().getName()
                            + ".name() returned " + (name == null ? "null" : "'" + name + "'"));
                    continue;
                }
                String declared = declarationProblem(model);
                if (declared != null) {
                    LOG.warning("skipping the propagation model " + name + " in " + source + ": " + declared);
                } else {
                    found.add(new ModelProvider(name, model, provider::get));
                }
            } catch (RuntimeException | Error e) {
                if (e instanceof VirtualMachineError && !(e instanceof StackOverflowError)) {
                    throw e; // out of memory, or the JVM itself broke: not something a plugin did alone
                }
                String what = model == null ? "" : model.getClass().getName() + ".name() failed: ";
                LOG.warning("skipping a propagation model in " + source + ": " + what + reason(e));
                if (++failures == MAX_FAILURES) {
                    LOG.warning("giving up on " + source + " after " + failures + " failures");
                    break;
                }
            }
        }
        return found;
    }

    /** What is wrong with the model's {@code settings()}, or null; a settings() that throws is a problem too. */
    private static String declarationProblem(PropagationModel model) {
        try {
            return Setting.declarationProblem(model.settings());
        } catch (RuntimeException e) {
            return "settings() failed: " + reason(e);
        }
    }

    /**
     * The error's message without the service's name, its root cause, and where that was thrown
     * when that is the model's code (a frame outside the JDK's modules).
     */
    static String reason(Throwable e) {
        String prefix = PropagationModel.class.getName() + ": ";
        String message = e instanceof ServiceConfigurationError && e.getMessage() != null && e.getMessage().startsWith(prefix)
                ? e.getMessage().substring(prefix.length()) : e.toString();
        Throwable root = e;
        while (root.getCause() != null && root.getCause() != root) {
            root = root.getCause();
        }
        StringBuilder reason = new StringBuilder(message);
        if (root != e) {
            reason.append(": ").append(root);
        }
        StackTraceElement[] trace = root.getStackTrace();
        if (trace.length > 0 && trace[0].getModuleName() == null) {
            reason.append(" (at ").append(trace[0]).append(')');
        }
        return reason.toString();
    }

    /** The folder as a file system object, so that one folder named twice is searched once. */
    private static Path identity(Path folder) {
        try {
            return folder.toRealPath();
        } catch (IOException | RuntimeException e) {
            return folder.toAbsolutePath().normalize();
        }
    }

    /**
     * The model named by its {@link PropagationModel#name()}, its class's simple or its qualified
     * name; or null.
     */
    public ModelProvider provider(String name) {
        for (Map.Entry<String, ModelProvider> entry : models.entrySet()) {
            Class<?> type = entry.getValue().model().getClass();
            if (entry.getKey().equals(name) || type.getSimpleName().equals(name) || type.getName().equals(name)) {
                return entry.getValue();
            }
        }
        return null;
    }

    /** The instance made when the model {@link #provider} finds was loaded (to ask what it declares); or null. */
    public PropagationModel find(String name) {
        ModelProvider provider = provider(name);
        return provider == null ? null : provider.model();
    }

    /** The models, in load order: NoopPropagationModel, the other built-ins, the plugins. */
    public List<ModelProvider> providers() {
        return List.copyOf(models.values());
    }

    /** The instances made when the models were loaded, in load order, to ask what they declare. */
    public List<PropagationModel> models() {
        return models.values().stream().map(ModelProvider::model).toList();
    }

    /** The names of the models, in load order: NoopPropagationModel, the other built-ins, the plugins. */
    public List<String> names() {
        return List.copyOf(models.keySet());
    }
}
