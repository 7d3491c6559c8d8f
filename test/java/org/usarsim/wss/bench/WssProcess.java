package org.usarsim.wss.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The WSS as users run it: a separate JVM, headless, on 127.0.0.1 with an OS-chosen control port.
 * {@code -Dwss.bench.jvmOptions="..."} gives its JVM options (a flight recording, say), and
 * {@code -Dwss.bench.properties="key=value ..."} settings over the benchmark's own.
 */
final class WssProcess implements AutoCloseable {

    private static final Pattern LISTENING = Pattern.compile("listening for robots on [^:]+:(\\d+)");

    final Process process;
    final int controlPort;
    /** Every line the server wrote so far. */
    private final List<String> lines;
    /** When each of {@link #lines} was read (System.nanoTime), in the same order. */
    private final List<Long> times;

    private WssProcess(Process process, int controlPort, List<String> lines, List<Long> times) {
        this.process = process;
        this.controlPort = controlPort;
        this.lines = lines;
        this.times = times;
    }

    /** When the first line after the first {@code from} lines that contains the text was read; -1 when none yet. */
    long lineTime(String text, int from) {
        synchronized (lines) {
            for (int i = from; i < lines.size(); i++) {
                if (lines.get(i).contains(text)) {
                    return times.get(i);
                }
            }
            return -1;
        }
    }

    /** How many lines the server wrote so far. */
    int lineCount() {
        synchronized (lines) {
            return lines.size();
        }
    }

    /** The last line the server wrote so far that contains the text; null when none does. */
    String lastLineContaining(String text) {
        synchronized (lines) {
            for (int i = lines.size() - 1; i >= 0; i--) {
                if (lines.get(i).contains(text)) {
                    return lines.get(i);
                }
            }
            return null;
        }
    }

    /** How many lines the server wrote so far that contain the text. */
    long linesContaining(String text) {
        synchronized (lines) {
            return lines.stream().filter(line -> line.contains(text)).count();
        }
    }

    /** Starts the server from the compiled classes with these extra properties. */
    static WssProcess start(String... properties) throws IOException, InterruptedException {
        return startFrom(classes(), properties);
    }

    /** Where the compiled classes are (target/classes), for a process of their own. */
    static String classes() {
        return Path.of(org.usarsim.wss.app.Main.class.getProtectionDomain().getCodeSource().getLocation().getPath()).toString();
    }

    /** Starts the server from another build (a wss.jar, or a classes folder) with these extra properties. */
    static WssProcess startFrom(String classpath, String... properties) throws IOException, InterruptedException {
        return start(classpath, 0, properties);
    }

    /** Starts the server from the compiled classes under {@code ulimit -n descriptors}, with these extra properties. */
    static WssProcess startWithDescriptorLimit(int descriptors, String... properties) throws IOException, InterruptedException {
        return start(classes(), descriptors, properties);
    }

    /** @param descriptors the process's limit of open descriptors; 0 keeps the shell's */
    static WssProcess start(String classpath, int descriptors, String... properties) throws IOException, InterruptedException {
        Path config = Files.createTempFile("wss-bench", ".properties");
        config.toFile().deleteOnExit(); // the server reads it at its start; the benchmark outlives it
        List<String> lines = new ArrayList<>(List.of("wss.bindAddress=127.0.0.1", "wss.port=0", "wss.logLevel=INFO"));
        lines.addAll(List.of(properties));
        String more = System.getProperty("wss.bench.properties", "").trim();
        if (!more.isEmpty()) {
            lines.addAll(List.of(more.split("\\s+"))); // after the others: the last of a key counts
        }
        Files.write(config, lines);
        List<String> command = new ArrayList<>();
        if (descriptors > 0) {
            command.addAll(List.of("bash", "-c", "ulimit -n " + descriptors + " && exec \"$@\"", "bash"));
        }
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        String jvmOptions = System.getProperty("wss.bench.jvmOptions", "").trim();
        if (!jvmOptions.isEmpty()) {
            command.addAll(List.of(jvmOptions.split("\\s+"))); // a JFR recording of the server, say
        }
        command.addAll(List.of("-cp", classpath, "org.usarsim.wss.app.Main", "--headless", "--config", config.toString()));
        Process process = new ProcessBuilder(command).redirectErrorStream(true).start();
        BlockingQueue<String> out = new LinkedBlockingQueue<>();
        List<String> all = Collections.synchronizedList(new ArrayList<>());
        List<Long> times = new ArrayList<>();
        OutputLines.follow(process.getInputStream(), line -> {
            out.add(line);
            synchronized (all) {
                times.add(System.nanoTime());
                all.add(line);
            }
            if (line.contains(" WARNING ") || line.contains(" SEVERE ")) {
                System.err.println("  [wss] " + line);
            }
        }, "wss-output");
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (System.nanoTime() < deadline) {
            String line = out.poll(100, TimeUnit.MILLISECONDS);
            if (line != null) {
                Matcher matcher = LISTENING.matcher(line);
                if (matcher.find()) {
                    return new WssProcess(process, Integer.parseInt(matcher.group(1)), all, times);
                }
            }
            if (!process.isAlive()) {
                break;
            }
        }
        process.destroyForcibly();
        throw new IOException("the WSS did not start");
    }

    long pid() {
        return process.pid();
    }

    @Override
    public void close() throws InterruptedException {
        process.destroy();
        if (!process.waitFor(10, TimeUnit.SECONDS)) {
            process.destroyForcibly();
        }
    }
}
