package org.usarsim.wss.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
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

    /** Clock ticks per second of /proc/PID/stat's times (USER_HZ: 100 on Linux for every architecture in use). */
    private static final long TICKS_PER_SECOND = 100;

    /** CPU time the process has used, user and system, in nanoseconds: utime + stime of /proc/PID/stat. */
    static long cpuNanos(long pid) throws IOException {
        String stat = Files.readString(Path.of("/proc", Long.toString(pid), "stat"));
        // The name (field 2) is in parentheses and may hold spaces: count the fields after it.
        String[] fields = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
        long ticks = Long.parseLong(fields[11]) + Long.parseLong(fields[12]); // fields 14 and 15: utime, stime
        return ticks * (1_000_000_000L / TICKS_PER_SECOND);
    }

    /** Fields of /proc/PID/task/TID/schedstat: time on a CPU (ns), time waiting for one while runnable (ns), times run. */
    static final int RUN_NANOS = 0;
    static final int WAIT_NANOS = 1;
    static final int TIMES_RUN = 2;

    /** How long each of the server's link threads has waited for a CPU while runnable, in nanoseconds, by thread id. */
    static Map<String, Long> linkThreadsWaitNanos(long pid) throws IOException {
        return linkThreads(pid, WAIT_NANOS);
    }

    /** One field of each of the server's link threads' schedstat ({@link #RUN_NANOS}, ...), by thread id. */
    static Map<String, Long> linkThreads(long pid, int field) throws IOException {
        Map<String, Long> waits = new HashMap<>();
        try (Stream<Path> tasks = Files.list(Path.of("/proc", Long.toString(pid), "task"))) {
            for (Path task : tasks.toList()) {
                if (comm(task).startsWith("link ")) {
                    try {
                        String[] fields = Files.readString(task.resolve("schedstat")).strip().split(" ");
                        waits.put(task.getFileName().toString(), Long.parseLong(fields[field]));
                    } catch (IOException | RuntimeException e) {
                        // the thread ended while we looked, or the kernel keeps no schedstat
                    }
                }
            }
        }
        return waits;
    }

    /** What a field of {@link #linkThreads} grew by between two readings, added up over the threads in both. */
    static long waitedBetween(Map<String, Long> before, Map<String, Long> after) {
        long total = 0;
        for (var entry : after.entrySet()) {
            Long then = before.get(entry.getKey());
            if (then != null) {
                total += entry.getValue() - then;
            }
        }
        return total;
    }

    /** The kinds of thread {@link #cpuByKind} adds up apart, by the start of their names; the rest are "other". */
    private static final List<String> KINDS = List.of("control ", "wss-port-accept", "wss-port-handov", "C2 CompilerThre",
            "C1 CompilerThre", "GC Thread", "G1 ");

    /** Time on a CPU (schedstat, ns) of the process's threads alive now, added up by kind ({@link #KINDS}, and "other"). */
    static Map<String, Long> cpuByKind(long pid) throws IOException {
        Map<String, Long> byKind = new java.util.TreeMap<>();
        try (Stream<Path> tasks = Files.list(Path.of("/proc", Long.toString(pid), "task"))) {
            for (Path task : tasks.toList()) {
                String name = comm(task);
                String kind = KINDS.stream().filter(name::startsWith).findFirst().orElse("other").strip();
                try {
                    String[] fields = Files.readString(task.resolve("schedstat")).strip().split(" ");
                    byKind.merge(kind, Long.parseLong(fields[RUN_NANOS]), Long::sum);
                } catch (IOException | RuntimeException e) {
                    // the thread ended while we looked, or the kernel keeps no schedstat
                }
            }
        }
        return byKind;
    }

    /** What each kind of {@link #cpuByKind} grew by between two readings, in seconds, as "kind 1.23 s, ...". */
    static String cpuBetween(Map<String, Long> before, Map<String, Long> after) {
        StringBuilder text = new StringBuilder();
        after.forEach((kind, nanos) -> text.append(text.length() == 0 ? "" : ", ").append(kind).append(' ')
                .append(String.format(java.util.Locale.ROOT, "%.2f s", (nanos - before.getOrDefault(kind, 0L)) / 1e9)));
        return text.toString();
    }

    /** Time on a CPU (schedstat, ns) of the process's threads alive now whose name starts with {@code name}. */
    static long threadCpuNanos(long pid, String name) throws IOException {
        long nanos = 0;
        try (Stream<Path> tasks = Files.list(Path.of("/proc", Long.toString(pid), "task"))) {
            for (Path task : tasks.toList()) {
                if (comm(task).startsWith(name)) {
                    try {
                        nanos += Long.parseLong(Files.readString(task.resolve("schedstat")).strip().split(" ")[RUN_NANOS]);
                    } catch (IOException | RuntimeException e) {
                        // the thread ended while we looked, or the kernel keeps no schedstat
                    }
                }
            }
        }
        return nanos;
    }

    /** The process's CPU time so far (user and system), in seconds. */
    static double cpuSeconds(long pid) throws IOException {
        return cpuNanos(pid) / 1e9;
    }

    private static String comm(Path task) {
        try {
            return Files.readAllLines(task.resolve("comm")).get(0);
        } catch (IOException | IndexOutOfBoundsException e) {
            return ""; // the thread ended while we looked
        }
    }
}
