package org.usarsim.wss.bench;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * A ROS publisher the benchmark runs ({@code test/ros/latency_publisher.py}, or any command that
 * speaks as it does): started as {@code bash -c "COMMAND ARGUMENTS"}, told {@code place NAME X Y} on
 * its standard input, and saying {@code published NAME EPOCH_NANOS} on its standard output at the
 * first publish of each place; {@code sent ...} at its end, when its standard input is closed.
 */
final class PublisherProcess implements AutoCloseable {

    private final Process process;
    private final OutputStream in;
    private final BlockingQueue<String> out = new LinkedBlockingQueue<>();
    private final Thread outReader;

    private PublisherProcess(Process process) {
        this.process = process;
        this.in = process.getOutputStream();
        outReader = OutputLines.follow(process.getInputStream(), out::add, "publisher-output");
        OutputLines.follow(process.getErrorStream(), line -> System.err.println("  [publisher] " + line), "publisher-errors");
    }

    /** Starts {@code bash -c "COMMAND ARGUMENTS"}: the command (a shell command line) with the script's arguments after it. */
    static PublisherProcess start(String command, String arguments) throws IOException {
        return new PublisherProcess(new ProcessBuilder("bash", "-c", command + " " + arguments).start());
    }

    /**
     * Places a model and waits for its publish; when that was, on this JVM's System.nanoTime (the
     * script's realtime clock, {@code time.time_ns()}, is this machine's, as {@link Instant#now()}).
     */
    long place(String name, double x, double y) throws IOException, InterruptedException {
        in.write(String.format(Locale.ROOT, "place %s %s %s%n", name, x, y).getBytes(StandardCharsets.UTF_8));
        in.flush();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        String said = "published " + name + " ";
        for (String line = next(deadline); line != null; line = next(deadline)) {
            if (line.startsWith(said)) {
                long published = Long.parseLong(line.substring(said.length()).strip());
                Instant now = Instant.now();
                long nanoNow = System.nanoTime();
                return published - (now.getEpochSecond() * 1_000_000_000L + now.getNano()) + nanoNow;
            }
        }
        throw new IOException("the publisher did not say it published " + name + (process.isAlive() ? "" : " (it ended)"));
    }

    private String next(long deadline) throws InterruptedException {
        return out.poll(Math.max(0, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
    }

    /** Ends the publisher (its standard input closed) and gives what it said it sent; the whole tree is ended after 15 s. */
    String stop() throws InterruptedException {
        try {
            in.close();
        } catch (IOException e) {
            // it ended already
        }
        List<String> said = new ArrayList<>();
        if (!process.waitFor(15, TimeUnit.SECONDS)) {
            process.descendants().forEach(ProcessHandle::destroy);
            process.destroy();
            process.waitFor(5, TimeUnit.SECONDS);
        }
        outReader.join(2_000);
        out.drainTo(said);
        return said.stream().filter(line -> line.startsWith("sent ")).findFirst().orElse("(said nothing sent)");
    }

    @Override
    public void close() throws InterruptedException {
        if (process.isAlive()) {
            stop();
        }
        process.descendants().forEach(ProcessHandle::destroyForcibly);
        process.destroyForcibly();
    }
}
