package org.usarsim.wss;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/** Which package may know which: app knows the others; the window never imports app nor a concrete model; the model SPI neither; world never the hub; ros (JSON and ROS messages) only the root. */
class PackagesTest {

    private static final Path SOURCES = Path.of("src/main/java/org/usarsim/wss");

    /** The sources of a package (and its sub-packages) that import one of these packages. */
    private static List<String> importing(String packageName, String... forbidden) throws IOException {
        try (Stream<Path> files = Files.walk(SOURCES.resolve(packageName))) {
            return files.filter(file -> file.toString().endsWith(".java")).filter(file -> {
                try {
                    String source = Files.readString(file, StandardCharsets.UTF_8);
                    return Stream.of(forbidden).anyMatch(name -> source.contains("import org.usarsim.wss." + name + "."));
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            }).map(Path::toString).toList();
        }
    }

    @Test
    void guiDoesNotImportApp() throws IOException {
        assertEquals(List.of(), importing("gui", "app"));
    }

    @Test
    void theWindowAsksAModelWhichDialogItNeedsAndKnowsNoConcreteModel() throws IOException {
        assertEquals(List.of(), importing("gui", "model.noop", "model.distance", "model.obstacle"));
    }

    @Test
    void theModelsDoNotImportGuiOrApp() throws IOException {
        assertEquals(List.of(), importing("model", "gui", "app"));
    }

    @Test
    void theWorldServerKnowsNothingOfTheHubAndTheAcceptLoopNothingOfTheRest() throws IOException {
        assertEquals(List.of(), importing("world", "hub", "gui", "app"));
        assertEquals(List.of(), importing("net", "hub", "world", "model", "protocol", "gui", "app"));
    }

    @Test
    void theRosWireKnowsNothingOfTheRestButTheRoot() throws IOException {
        assertEquals(List.of(), importing("ros", "hub", "world", "model", "protocol", "net", "recording", "replay", "shaping",
                "gui", "app"));
    }

    @Test
    void theMonitorKnowsNeitherTheWindowNorTheCommandLine() throws IOException {
        assertEquals(List.of(), importing("monitor", "gui", "app"));
    }
}
