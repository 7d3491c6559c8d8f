package org.usarsim.wss.app;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;

/**
 * {@link Main#run} in the test JVM, for what ends before anything runs (a bad command line or
 * settings, --help): the exit code and what it wrote. What needs a real process (signals, the JVM
 * exiting, {@code java -jar}, no display) goes through {@link ServerProcess}.
 */
public final class MainRun {

    private final int exitCode;
    private final String stdout;
    private final String stderr;

    private MainRun(int exitCode, String stdout, String stderr) {
        this.exitCode = exitCode;
        this.stdout = stdout;
        this.stderr = stderr;
    }

    /** {@code Main.run(out, err, ARGS)}, with both streams captured. */
    public static MainRun of(String... args) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code;
        try (PrintStream outStream = new PrintStream(out, true, StandardCharsets.UTF_8);
                PrintStream errStream = new PrintStream(err, true, StandardCharsets.UTF_8)) {
            code = Main.run(outStream, errStream, args);
        }
        return new MainRun(code, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
    }

    /** What {@code run} returned: the process's exit code. */
    public int exitCode() {
        return exitCode;
    }

    /** The lines written to {@code out}. */
    public List<String> stdoutLines() {
        return stdout.lines().toList();
    }

    public String stderr() {
        return stderr;
    }
}
