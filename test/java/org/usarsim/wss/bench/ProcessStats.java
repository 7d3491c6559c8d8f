package org.usarsim.wss.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

/**
 * Threads, open descriptors and resident memory of a process, from /proc. The server's own
 * threads (links, WSS ports, control connections) are counted apart from the JVM's, which grow
 * by themselves (G1 starts more GC workers under load and keeps them).
 */
record ProcessStats(int threads, int serverThreads, int descriptors, long residentKiB) {

    /** How the server names its threads (a thread's name in /proc is cut at 15 characters). */
    private static final List<String> SERVER_THREADS = List.of("link ", "wss-port", "control ", "wss-control");

    static ProcessStats of(long pid) throws IOException {
        Path process = Path.of("/proc", Long.toString(pid));
        long rss = 0;
        for (String line : Files.readAllLines(process.resolve("status"))) {
            if (line.startsWith("VmRSS:")) {
                rss = Long.parseLong(line.substring(6).replace("kB", "").strip());
            }
        }
        int threads = 0;
        int server = 0;
        try (Stream<Path> tasks = Files.list(process.resolve("task"))) {
            for (Path task : tasks.toList()) {
                threads++;
                String name = comm(task);
                if (SERVER_THREADS.stream().anyMatch(name::startsWith)) {
                    server++;
                }
            }
        }
        try (Stream<Path> fds = Files.list(process.resolve("fd"))) {
            return new ProcessStats(threads, server, (int) fds.count(), rss);
        }
    }

    /** The process's CPU time so far (user and system), in seconds. */
    static double cpuSeconds(long pid) throws IOException {
        String stat = Files.readString(Path.of("/proc", Long.toString(pid), "stat"));
        String[] fields = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
        return (Long.parseLong(fields[11]) + Long.parseLong(fields[12])) / 100.0; // utime, stime in clock ticks (USER_HZ 100)
    }

    private static String comm(Path task) {
        try {
            return Files.readAllLines(task.resolve("comm")).get(0);
        } catch (IOException | IndexOutOfBoundsException e) {
            return ""; // the thread ended while we looked
        }
    }
}
