package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The real server as a child process, as a user runs it: {@code java -cp <classes>
 * org.usarsim.wss.app.Main ARGS} ({@link #start}) or any other {@code java} command line
 * ({@link #startJava}, e.g. {@code -jar wss.jar}). Its standard output is read line by line and
 * its standard error collected.
 */
public final class ServerProcess {

    /** How long to wait for anything the server should do at once (JVM start included). */
    public static final Duration WAIT = Duration.ofSeconds(10);

    /** The headless server's "listening" line: group 1 the control port, group 2 the propagation model. */
    private static final Pattern LISTENING = Pattern.compile("WSS listening for robots on 127\\.0\\.0\\.1:(\\d+) with (\\S+)");

    /** Put on the queue when standard output ends. */
    private static final String END = new String("<end of standard output>");

    public final Process process;
    private final BlockingQueue<String> lines = new LinkedBlockingQueue<>();
    private final List<String> stdout = new CopyOnWriteArrayList<>();
    private final ByteArrayOutputStream stderr = new ByteArrayOutputStream();
    private final Thread outReader;
    private final Thread errReader;

    /** A properties file in {@code dir} binding 127.0.0.1 on a port of the OS's choosing, with these overrides. */
    static Path config(Path dir, Map<String, String> overrides) throws IOException {
        Map<String, String> values = new LinkedHashMap<>();
        values.put("wss.bindAddress", "127.0.0.1");
        values.put("wss.port", "0");
        values.putAll(overrides);
        StringBuilder text = new StringBuilder("# written by a test\n");
        values.forEach((key, value) -> text.append(key).append('=').append(value).append('\n'));
        Path file = Files.createTempFile(dir, "wss", ".properties");
        Files.writeString(file, text, StandardCharsets.UTF_8);
        return file;
    }

    /** {@code java -cp <the server's classes> org.usarsim.wss.app.Main ARGS}. */
    public static ServerProcess start(String... args) throws Exception {
        Path classes = Path.of(Main.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        List<String> arguments = new ArrayList<>(List.of("-cp", classes.toString(), Main.class.getName()));
        arguments.addAll(List.of(args));
        return startJava(arguments);
    }

    /**
     * {@code java -Djava.util.prefs.userRoot=PREFS -cp <the server's classes> org.usarsim.wss.app.Main ARGS}
     * with the environment changed: a key mapped to null is removed (DISPLAY, to run without a display).
     */
    public static ServerProcess start(Path preferences, Map<String, String> environment, String... args) throws Exception {
        Path classes = Path.of(Main.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Djava.util.prefs.userRoot=" + preferences, "-cp", classes.toString(), Main.class.getName()));
        command.addAll(List.of(args));
        ProcessBuilder builder = new ProcessBuilder(command);
        environment.forEach((key, value) -> {
            if (value == null) {
                builder.environment().remove(key);
            } else {
                builder.environment().put(key, value);
            }
        });
        return new ServerProcess(builder.start());
    }

    /**
     * {@code java -cp <the server's classes> org.usarsim.wss.app.Main ARGS} under a lower limit
     * of open descriptors: {@code bash -c 'ulimit -n LIMIT; exec java ...'}.
     */
    public static ServerProcess startWithDescriptorLimit(int limit, String... args) throws Exception {
        Path classes = Path.of(Main.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        List<String> command = new ArrayList<>(List.of("bash", "-c", "ulimit -n " + limit + " && exec \"$@\"", "bash",
                Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp", classes.toString(),
                Main.class.getName()));
        command.addAll(List.of(args));
        return new ServerProcess(new ProcessBuilder(command).start());
    }

    /** {@code java ARGUMENTS}, with the java of the JVM running the tests. */
    public static ServerProcess startJava(List<String> arguments) throws IOException {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        command.addAll(arguments);
        return new ServerProcess(new ProcessBuilder(command).start());
    }

    private ServerProcess(Process process) {
        this.process = process;
        try {
            process.getOutputStream().close();
        } catch (IOException e) {
            // the child reads nothing from standard input anyway
        }
        outReader = new Thread(this::readStdout, "stdout of " + process.pid());
        errReader = new Thread(this::readStderr, "stderr of " + process.pid());
        outReader.setDaemon(true);
        errReader.setDaemon(true);
        outReader.start();
        errReader.start();
    }

    private void readStdout() {
        try (var reader = process.inputReader(StandardCharsets.UTF_8)) {
            String line;
            while ((line = reader.readLine()) != null) {
                stdout.add(line);
                lines.add(line);
            }
        } catch (IOException e) {
            // the process ended
        } finally {
            lines.add(END);
        }
    }

    private void readStderr() {
        try (InputStream in = process.getErrorStream()) {
            byte[] buffer = new byte[4096];
            int read;
            while ((read = in.read(buffer)) != -1) {
                synchronized (stderr) {
                    stderr.write(buffer, 0, read);
                }
            }
        } catch (IOException e) {
            // the process ended
        }
    }

    public List<String> stdoutSoFar() {
        return List.copyOf(stdout);
    }

    public String stderr() {
        synchronized (stderr) {
            return stderr.toString(StandardCharsets.UTF_8);
        }
    }

    /** The next line of standard output that matches, waiting at most {@link #WAIT}. */
    public String awaitLine(Predicate<String> wanted) throws InterruptedException {
        long deadline = System.nanoTime() + WAIT.toNanos();
        while (true) {
            long left = deadline - System.nanoTime();
            String line = left > 0 ? lines.poll(left, TimeUnit.NANOSECONDS) : null;
            if (line == null) {
                fail("timed out waiting for a line on standard output; stdout: " + stdoutSoFar() + "; stderr: " + stderr());
            }
            if (line == END) {
                lines.add(END);
                fail("standard output ended (the server exited?) before the line came; stdout: " + stdoutSoFar()
                        + "; stderr: " + stderr());
            }
            if (wanted.test(line)) {
                return line;
            }
        }
    }

    /**
     * The headless server's "WSS listening for robots on 127.0.0.1:PORT with MODEL" line, waiting
     * at most {@link #WAIT}: group 1 is the control port, group 2 the propagation model.
     */
    public Matcher awaitListening() throws InterruptedException {
        Matcher matcher = LISTENING.matcher(awaitLine(line -> LISTENING.matcher(line).find()));
        assertTrue(matcher.find());
        return matcher;
    }

    /** The exit code, waiting at most {@link #WAIT}; then all output has been read. */
    public int awaitExit() throws InterruptedException {
        if (!process.waitFor(WAIT.toMillis(), TimeUnit.MILLISECONDS)) {
            fail("the server did not exit; stdout: " + stdoutSoFar() + "; stderr: " + stderr());
        }
        outReader.join(WAIT.toMillis());
        errReader.join(WAIT.toMillis());
        return process.exitValue();
    }

    /**
     * Sends SIGTERM. Not with {@link Process#destroy()}: that also closes our ends of the
     * child's standard output and error, losing whatever it logs while it stops.
     */
    public void sigterm() {
        assertTrue(process.toHandle().destroy(), "SIGTERM sent");
    }

    public void kill() throws InterruptedException {
        if (process.isAlive()) {
            process.destroyForcibly();
            process.waitFor(WAIT.toMillis(), TimeUnit.MILLISECONDS);
        }
    }
}
