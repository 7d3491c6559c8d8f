package org.usarsim.wss.bench;

import java.io.BufferedWriter;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import java.util.zip.GZIPOutputStream;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.model.Wall;
import org.usarsim.wss.recording.Entry;
import org.usarsim.wss.recording.EntryLines;
import org.usarsim.wss.recording.Header;
import org.usarsim.wss.recording.Recording;
import org.usarsim.wss.recording.RecordingReader;

/**
 * Recording and replay, measured (issue 17, docs/performance.md, "Recording and replay"). Sections
 * ({@code --only}):
 * <ul>
 * <li>{@code size}: a run of {@code --robots} robots polled {@code --hz} times a second for
 * {@code --minutes}, written as the recorder writes it (every poll: each robot's position, each
 * pair's strength, obstacles and state; the robots drive about a 60 by 40 m building, so pairs
 * break and resume): bytes per robot per poll, the file's size plain and gzip, and the seconds to
 * read it back ({@code RecordingReader}) and find its last poll, the first time (a cold JVM) and
 * the best of {@code --reads} more.</li>
 * </ul>
 *
 * <pre>
 * java -cp target/classes:target/test-classes org.usarsim.wss.bench.ReplayBenchmark --only size --robots 12 --hz 5 --minutes 30
 * </pre>
 */
public final class ReplayBenchmark {

    private ReplayBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        String only = "size";
        int robots = 12;
        int hz = 5;
        int minutes = 30;
        int reads = 3;
        Path dir = Path.of(System.getProperty("java.io.tmpdir"));
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--only" -> only = args[++i];
                case "--robots" -> robots = Integer.parseInt(args[++i]);
                case "--hz" -> hz = Integer.parseInt(args[++i]);
                case "--minutes" -> minutes = Integer.parseInt(args[++i]);
                case "--reads" -> reads = Integer.parseInt(args[++i]);
                case "--dir" -> dir = Path.of(args[++i]);
                default -> throw new IllegalArgumentException("unknown argument " + args[i]);
            }
        }
        System.out.printf("WSS replay benchmark: %d cores, %s, %s, %s%n", Runtime.getRuntime().availableProcessors(),
                System.getProperty("java.vm.name") + " " + System.getProperty("java.version"), only, java.time.LocalDateTime.now());
        switch (only) {
            case "size" -> size(dir, robots, hz, minutes, reads);
            default -> throw new IllegalArgumentException("unknown section " + only);
        }
        System.exit(0);
    }

    // ---- size ----

    private static void size(Path dir, int robots, int hz, int minutes, int reads) throws Exception {
        Path plain = dir.resolve("replay-benchmark-" + robots + "x" + hz + "x" + minutes + ".rec");
        Path gzip = dir.resolve(plain.getFileName() + ".gz");
        long polls = (long) hz * 60 * minutes;
        long pollBytes = writeRun(plain, gzip, robots, hz, polls);
        long size = Files.size(plain);
        System.out.printf(Locale.ROOT, "  %d robots, %d polls (%d a second for %d min): %,d bytes plain (%.1f MB; target under 50 MB),"
                + " %,d gzip (%.1f MB)%n", robots, polls, hz, minutes, size, size / 1e6, Files.size(gzip), Files.size(gzip) / 1e6);
        System.out.printf(Locale.ROOT, "  a poll: %.0f bytes, %.1f bytes per robot per poll (its robot line and its share of the"
                + " %d pairs' lines)%n", pollBytes / (double) polls, pollBytes / (double) polls / robots, robots * (robots - 1) / 2);
        for (Path file : List.of(plain, gzip)) {
            for (int i = 0; i <= reads; i++) {
                long start = System.nanoTime();
                Recording recording = RecordingReader.read(file);
                int last = recording.pollIndexAt(recording.durationMillis());
                int robotsThere = recording.polls().get(last).robots().size();
                double seconds = (System.nanoTime() - start) / 1e9;
                System.out.printf(Locale.ROOT, "  read %s and its last poll %s: %.3f s (%d polls, the last at %d ms with %d robots,"
                        + " cut short %s)%n", file.getFileName(), i == 0 ? "first" : "again", seconds, recording.polls().size(),
                        recording.durationMillis(), robotsThere, recording.cutShort());
            }
        }
        Files.deleteIfExists(plain);
        Files.deleteIfExists(gzip);
    }

    /** Writes the run to both files; returns the bytes of its polls' lines. */
    public static long writeRun(Path plain, Path gzip, int robots, int hz, long polls) throws Exception {
        Random random = new Random(17);
        double[][] at = new double[robots][2];
        double[][] heading = new double[robots][2];
        List<String> names = new ArrayList<>();
        for (int i = 0; i < robots; i++) {
            names.add("Robot" + (i + 1));
            at[i][0] = random.nextDouble() * 60;
            at[i][1] = random.nextDouble() * 40;
            double angle = random.nextDouble() * 2 * Math.PI;
            heading[i][0] = Math.cos(angle);
            heading[i][1] = Math.sin(angle);
        }
        long pollBytes = 0;
        try (Writer a = Files.newBufferedWriter(plain, StandardCharsets.UTF_8);
                Writer b = new BufferedWriter(new OutputStreamWriter(new GZIPOutputStream(Files.newOutputStream(gzip), 1 << 16),
                        StandardCharsets.UTF_8))) {
            StringBuilder text = new StringBuilder(1 << 16);
            EntryLines.header(text, new Header(EntryLines.VERSION, "benchmark", "2026-11-25T00:00:00Z", "ObstaclePropagationModel",
                    Map.of("usarsim.interval", String.valueOf(1000 / hz), "distance.cutoff", "-93")));
            for (String name : names) {
                EntryLines.write(text, new Entry.Registered(0, name, "127.0.0.1"));
            }
            EntryLines.write(text, new Entry.Walls(0, List.of(new Wall(0, 0, 60, 0), new Wall(60, 0, 60, 40), new Wall(20, 0, 20, 30))));
            flush(text, a, b);
            for (long p = 0; p < polls; p++) {
                long millis = p * 1000 / hz;
                List<ModelPoll.Robot> listed = new ArrayList<>();
                for (int i = 0; i < robots; i++) {
                    for (int axis = 0; axis < 2; axis++) {
                        at[i][axis] += heading[i][axis] * 0.5 / hz; // 0.5 m/s
                        double bound = axis == 0 ? 60 : 40;
                        if (at[i][axis] < 0 || at[i][axis] > bound) {
                            heading[i][axis] = -heading[i][axis];
                        }
                    }
                    listed.add(new ModelPoll.Robot(names.get(i), new Position(at[i][0], at[i][1], 0.45), false));
                }
                List<ModelPoll.Pair> pairs = new ArrayList<>();
                for (int i = 0; i < robots; i++) {
                    for (int j = i + 1; j < robots; j++) {
                        double metres = Math.max(0.01, Math.hypot(at[i][0] - at[j][0], at[i][1] - at[j][1]));
                        int walls = (int) (metres / 15);
                        double strength = -49.67 - 10 * 2 * Math.log10(metres / 2) - 6 * walls;
                        pairs.add(new ModelPoll.Pair(names.get(i), names.get(j), strength, walls, strength >= -93));
                    }
                }
                int before = text.length();
                EntryLines.write(text, new Entry.Poll(millis, listed, pairs));
                pollBytes += text.length() - before;
                if (text.length() > 1 << 15) {
                    flush(text, a, b);
                }
            }
            EntryLines.write(text, new Entry.End(polls * 1000 / hz));
            flush(text, a, b);
        }
        return pollBytes;
    }

    private static void flush(StringBuilder text, Writer a, Writer b) throws java.io.IOException {
        a.append(text);
        b.append(text);
        text.setLength(0);
    }
}
