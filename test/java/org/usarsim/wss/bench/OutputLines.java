package org.usarsim.wss.bench;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.function.Consumer;

/** A process's output read line by line on a daemon thread of its own, until the process ends. */
final class OutputLines {

    private OutputLines() {
    }

    /** Gives each line of the stream to {@code each}; the thread, started. */
    static Thread follow(InputStream stream, Consumer<String> each, String name) {
        Thread reader = new Thread(() -> {
            try (BufferedReader lines = new BufferedReader(new InputStreamReader(stream, StandardCharsets.UTF_8))) {
                for (String line = lines.readLine(); line != null; line = lines.readLine()) {
                    each.accept(line);
                }
            } catch (IOException ignored) {
                // The process ended.
            }
        }, name);
        reader.setDaemon(true);
        reader.start();
        return reader;
    }
}
