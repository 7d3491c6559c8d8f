package org.usarsim.wss.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The world server with its rosbridge side, as users run it: a process of its own
 * ({@code --world FILE --bind 127.0.0.1 --port 0 --rosbridge 0 --ros-rate HZ}) from the compiled classes, known
 * only by its command line and the WebSocket address its log names.
 */
final class WorldProcess implements AutoCloseable {

    private static final Pattern ROSBRIDGE = Pattern.compile("(ws://127\\.0\\.0\\.1:\\d+)");

    private final Process process;
    private final String url;

    private WorldProcess(Process process, String url) {
        this.process = process;
        this.url = url;
    }

    /** The rosbridge side's address, {@code ws://127.0.0.1:PORT}. */
    String url() {
        return url;
    }

    /** Starts the world server on a world file of these lines (a temporary file). */
    static WorldProcess start(List<String> worldLines, int hz) throws IOException, InterruptedException {
        Path world = Files.createTempFile("wss-bench", ".world");
        world.toFile().deleteOnExit();
        Files.write(world, worldLines);
        Process process = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp",
                WssProcess.classes(), "org.usarsim.wss.app.Main", "--world", world.toString(), "--bind", "127.0.0.1", "--port", "0",
                "--rosbridge", "0", "--ros-rate", Integer.toString(hz)).redirectErrorStream(true).start();
        BlockingQueue<String> out = new LinkedBlockingQueue<>();
        OutputLines.follow(process.getInputStream(), line -> {
            out.add(line);
            if (line.contains(" WARNING ") || line.contains(" SEVERE ")) {
                System.err.println("  [world] " + line);
            }
        }, "world-output");
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (System.nanoTime() < deadline && process.isAlive()) {
            String line = out.poll(100, TimeUnit.MILLISECONDS);
            Matcher matcher = line == null ? null : ROSBRIDGE.matcher(line);
            if (matcher != null && matcher.find()) {
                return new WorldProcess(process, matcher.group(1));
            }
        }
        process.destroyForcibly();
        throw new IOException("the world server did not start its rosbridge side: " + out);
    }

    @Override
    public void close() throws InterruptedException {
        process.destroy();
        if (!process.waitFor(10, TimeUnit.SECONDS)) {
            process.destroyForcibly();
        }
    }
}
