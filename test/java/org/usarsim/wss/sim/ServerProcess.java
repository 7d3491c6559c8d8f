package org.usarsim.wss.sim;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import org.usarsim.wss.app.Main;

/**
 * The real server as a child process, {@code java -cp <classes> org.usarsim.wss.app.Main ARGS},
 * its standard output read line by line and its standard error collected.
 */
final class ServerProcess {

    /** How long to wait for anything the server should do at once (JVM start included). */
    static final Duration WAIT = Duration.ofSeconds(10);

    /** Put on the queue when standard output ends. */
    private static final String END = new String("<end of standard output>");

    final Process process;
    private final BlockingQueue<String> lines = new LinkedBlockingQueue<>();
    private final List<String> stdout = new CopyOnWriteArrayList<>();
    private final ByteArrayOutputStream stderr = new ByteArrayOutputStream();
    private final Thread outReader;
    private final Thread errReader;

    static ServerProcess start(String... args) throws Exception {
        Path classes = Path.of(Main.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        List<String> command = new ArrayList<>(List.of(
                Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", classes.toString(), Main.class.getName()));
        command.addAll(List.of(args));
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

    List<String> stdoutSoFar() {
        return List.copyOf(stdout);
    }

    String stderr() {
        synchronized (stderr) {
            return stderr.toString(StandardCharsets.UTF_8);
        }
    }

    /** The next line of standard output that matches, waiting at most {@link #WAIT}. */
    String awaitLine(Predicate<String> wanted) throws InterruptedException {
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

    /** The exit code, waiting at most {@link #WAIT}; then all output has been read. */
    int awaitExit() throws InterruptedException {
        if (!process.waitFor(WAIT.toMillis(), TimeUnit.MILLISECONDS)) {
            fail("the server did not exit; stdout: " + stdoutSoFar() + "; stderr: " + stderr());
        }
        outReader.join(WAIT.toMillis());
        errReader.join(WAIT.toMillis());
        return process.exitValue();
    }

    /** SIGTERM, leaving our ends of the child's output open (unlike {@link Process#destroy()}). */
    void sigterm() {
        assertTrue(process.toHandle().destroy(), "SIGTERM sent");
    }

    void kill() throws InterruptedException {
        if (process.isAlive()) {
            process.destroyForcibly();
            process.waitFor(WAIT.toMillis(), TimeUnit.MILLISECONDS);
        }
    }
}
