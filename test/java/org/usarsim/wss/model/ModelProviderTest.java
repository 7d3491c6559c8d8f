package org.usarsim.wss.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.model.distance.DistanceOnlyPropagationModel;
import org.usarsim.wss.model.noop.NoopPropagationModel;

/** What the catalog hands a run: a new instance of the model each time, never the one it asks. */
class ModelProviderTest {

    private static final ClassLoader APPLICATION = ModelProviderTest.class.getClassLoader();

    @TempDir
    Path dir;

    @Test
    void aBuiltInModelGivesANewInstanceForEachRun() throws Exception {
        ModelProvider provider = ModelCatalog.load(APPLICATION).provider("DistanceOnlyPropagationModel");
        PropagationModel first = provider.instanceForRun();
        PropagationModel second = provider.instanceForRun();
        assertInstanceOf(DistanceOnlyPropagationModel.class, first);
        assertInstanceOf(DistanceOnlyPropagationModel.class, second);
        assertNotSame(first, second);
        assertNotSame(provider.model(), first, "the instance the catalog asks is not run");
        assertNotSame(provider.model(), second);
    }

    @Test
    void aPluginsRunsAreNewInstancesOfItsOwnClassAndOneRunsValuesStayInIt() throws Exception {
        Path classes = PluginJars.compile(dir.resolve("build"));
        PluginJars.tunedJar(dir.resolve("plugins").resolve("tuned.jar"), classes);
        ModelProvider tuned = ModelCatalog.load(APPLICATION, List.of(dir.resolve("plugins"))).provider("Tuned");
        PropagationModel first = tuned.instanceForRun();
        first.configure(new ModelSettings(Map.of("tuned.level", "5", "tuned.gain", "0.25")));
        PropagationModel second = tuned.instanceForRun();
        assertSame(tuned.model().getClass(), second.getClass(), "the plugin's class, from its jar's loader");
        assertEquals(-50.25, first.getSignalStrengthForPair("A", "B"), 0);
        assertEquals(-32.5, second.getSignalStrengthForPair("A", "B"), 0, "the defaults: nothing of the first run");
        assertEquals(-32.5, tuned.model().getSignalStrengthForPair("A", "B"), 0);
    }

    /** A model that brings a dialog of its own, which keeps what the user entered in the instance. */
    private static final class OwnDialog extends StubModel {
        @Override
        public boolean isConfigurable() {
            return true;
        }
    }

    @Test
    void aModelWithADialogOfItsOwnRunsTheInstanceItsDialogConfigured() throws Exception {
        AtomicInteger made = new AtomicInteger();
        ModelProvider provider = ModelProvider.of(() -> {
            made.incrementAndGet();
            return new OwnDialog();
        });
        assertSame(provider.model(), provider.instanceForRun());
        assertSame(provider.model(), provider.instanceForRun());
        assertEquals(1, made.get());
    }

    @Test
    void anInstanceThatCannotBeMadeIsAStartFailureThatSaysWhy() {
        AtomicInteger made = new AtomicInteger();
        ModelProvider provider = ModelProvider.of(() -> {
            if (made.incrementAndGet() > 1) {
                throw new IllegalStateException("out of licences");
            }
            return new NoopPropagationModel();
        });
        assertEquals("NoopPropagationModel", provider.name());
        ModelStartException e = assertThrows(ModelStartException.class, provider::instanceForRun);
        assertTrue(e.getMessage().startsWith("cannot make a new instance: java.lang.IllegalStateException: out of licences"),
                e.getMessage());
    }
}
