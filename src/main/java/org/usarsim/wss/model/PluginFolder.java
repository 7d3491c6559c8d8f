package org.usarsim.wss.model;

import java.io.IOException;
import java.net.MalformedURLException;
import java.net.URISyntaxException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.FileSystemNotFoundException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.CodeSource;
import java.util.Collections;
import java.util.Comparator;
import java.util.Enumeration;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.jar.JarFile;
import java.util.logging.Logger;
import java.util.stream.Stream;

/**
 * Where plugin jars are and how each one is opened: the jars of a folder in name order, each with a
 * class loader of its own whose parent is the application's, so that one jar cannot hide or break
 * another. {@link ModelCatalog} loads the models from what this opens.
 */
public final class PluginFolder {

    /** The services file that lists a jar's models. */
    static final String SERVICES = "META-INF/services/" + PropagationModel.class.getName();

    private static final Logger LOG = Logger.getLogger(PluginFolder.class.getName());

    private PluginFolder() {
    }

    /**
     * The {@code plugins} folder beside the jar (or classes directory) this class was loaded from:
     * {@code target/plugins} for {@code target/wss.jar}. Empty when that place is not a file.
     */
    public static Optional<Path> besideCodeOf(Class<?> type) {
        CodeSource source = type.getProtectionDomain().getCodeSource();
        URL location = source == null ? null : source.getLocation();
        try {
            Path code = location == null ? null : Path.of(location.toURI());
            Path folder = code == null ? null : code.toAbsolutePath().getParent();
            if (folder != null) {
                return Optional.of(folder.resolve("plugins"));
            }
        } catch (URISyntaxException | IllegalArgumentException | FileSystemNotFoundException e) {
            // not a file: no folder beside it
        }
        LOG.fine("no plugins folder: " + type.getName() + " was not loaded from a file (" + location + ")");
        return Optional.empty();
    }

    /** The jars in the folder, in name order; none when it does not exist (FINE) or cannot be read (WARNING). */
    static List<Path> jars(Path folder) {
        if (!Files.isDirectory(folder)) {
            LOG.fine("no plugin folder " + folder);
            return List.of();
        }
        try (Stream<Path> entries = Files.list(folder)) {
            List<Path> jars = entries
                    .filter(entry -> entry.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".jar"))
                    .filter(Files::isRegularFile)
                    .sorted(Comparator.comparing(entry -> entry.getFileName().toString()))
                    .toList();
            LOG.fine("plugin folder " + folder + ": " + (jars.isEmpty() ? "no jars" : jars.size() + " jar(s)"));
            return jars;
        } catch (IOException | RuntimeException e) {
            LOG.warning("cannot list the plugin folder " + folder + ": " + e);
            return List.of();
        }
    }

    /**
     * A class loader for the jar alone (its parent the given one), or empty after a WARNING when the
     * jar cannot be read or lists no model. Through it, a {@link java.util.ServiceLoader} sees the
     * services file of this jar only, not the parent's again.
     */
    static Optional<URLClassLoader> open(Path jar, ClassLoader parent) {
        try (JarFile file = new JarFile(jar.toFile())) {
            if (file.getJarEntry(SERVICES) == null) {
                LOG.warning("skipping plugin " + jar + ": it lists no propagation model (it has no " + SERVICES + ")");
                return Optional.empty();
            }
        } catch (IOException | RuntimeException e) {
            LOG.warning("skipping plugin " + jar + ": cannot read it as a jar: " + e);
            return Optional.empty();
        }
        try {
            return Optional.of(new OneJarLoader(jar.toUri().toURL(), parent));
        } catch (MalformedURLException | RuntimeException e) {
            LOG.warning("skipping plugin " + jar + ": " + e);
            return Optional.empty();
        }
    }

    /** Loads classes parent first, as usual, but offers the services file of its own jar only. */
    private static final class OneJarLoader extends URLClassLoader {

        static {
            registerAsParallelCapable();
        }

        OneJarLoader(URL jar, ClassLoader parent) {
            super(new URL[] {jar}, parent);
        }

        @Override
        public Enumeration<URL> getResources(String name) throws IOException {
            if (!name.equals(SERVICES)) {
                return super.getResources(name);
            }
            // The jar comes first in the search path, before any jar its manifest's Class-Path names.
            URL own = findResource(name);
            return own == null ? Collections.emptyEnumeration() : Collections.enumeration(List.of(own));
        }
    }
}
