package org.usarsim.wss.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import java.util.Random;
import org.usarsim.wss.world.MaterialRules;
import org.usarsim.wss.world.WorldWalls;

/**
 * The walls of a Gazebo world between every pair of robots, by material, timed (issue 35: a
 * 5,000-wall SDF world and 100 robots, all 4,950 pairs' losses within one poll interval of
 * 200 ms). The world is a 100 x 100 m building of 10 m rooms whose walls are boxes of the 2019
 * WCS's kinds (Hard_wall, Medium_wall, Soft_wall, a glass one in each room) with a 1 m door in
 * each, and boxes scattered in the rooms (turned at random) up to 5,000 walls, written as an SDF
 * file and read as {@code obstacle.walls} reads it ({@code WorldWalls.read}, the default rules
 * and height band). A round is what a poll's wall part costs when every pair is stale: the walls
 * crossed by material and their losses summed, for all pairs. Also given in CPU time of the
 * benchmark's thread, which a loaded machine does not inflate as it does the wall-clock time.
 *
 * <pre>
 * java -cp target/classes:target/test-classes org.usarsim.wss.bench.SdfWallsBenchmark --rounds 30 --robots 100 --walls 5000
 * </pre>
 */
public final class SdfWallsBenchmark {

    private static final double SIDE = 100;
    private static final double ROOM = 10;
    private static final double[] LOSSES = {15, 10, 4, 2, 15};

    private SdfWallsBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        java.util.Map<String, Long> given = new java.util.HashMap<>(java.util.Map.of("--rounds", 30L, "--robots", 100L,
                "--walls", 5000L, "--seed", 35L));
        for (int i = 0; i + 1 < args.length; i += 2) {
            if (given.replace(args[i], Long.parseLong(args[i + 1])) == null) {
                throw new IllegalArgumentException("unknown argument " + args[i]);
            }
        }
        int rounds = given.get("--rounds").intValue();
        int robots = given.get("--robots").intValue();
        int walls = given.get("--walls").intValue();
        long seed = given.get("--seed");
        Random random = new Random(seed);
        Path file = Files.createTempFile("walls", ".sdf");
        try {
            Files.writeString(file, world(walls, random));
            MaterialRules rules = MaterialRules.parse(
                    "Hard_wall*=concrete, Medium_wall*=brick, Soft_wall*=drywall, *glass*=glass, *=concrete");
            ThreadMXBean threads = ManagementFactory.getThreadMXBean();
            long readCpu = threads.getCurrentThreadCpuTime();
            long start = System.nanoTime();
            WorldWalls read = WorldWalls.read(file, rules, 0.1, 2.0);
            long readNanos = System.nanoTime() - start;
            readCpu = threads.getCurrentThreadCpuTime() - readCpu;
            double[] loss = read.materials().stream().mapToDouble(m -> switch (m) {
                case "concrete" -> 15;
                case "brick" -> 10;
                case "drywall" -> 4;
                case "glass" -> 2;
                default -> 6.325;
            }).toArray();
            double[][] at = new double[robots][];
            for (int i = 0; i < robots; i++) {
                at[i] = new double[] {random.nextDouble() * SIDE, random.nextDouble() * SIDE};
            }
            long[] nanos = new long[rounds];
            long[] cpuNanos = new long[rounds];
            double total = 0;
            for (int warm = 0; warm < 3; warm++) {
                total = allPairs(read, loss, at);
            }
            for (int round = 0; round < rounds; round++) {
                long cpu = threads.getCurrentThreadCpuTime();
                start = System.nanoTime();
                total = allPairs(read, loss, at);
                nanos[round] = System.nanoTime() - start;
                cpuNanos[round] = threads.getCurrentThreadCpuTime() - cpu;
            }
            int pairs = robots * (robots - 1) / 2;
            System.out.printf(Locale.ROOT, "%s: %d walls (%s) read in %.0f ms (CPU %.0f ms), %.1f MB; %d robots, %d pairs, %d rounds (seed %d)%n",
                    file.getFileName(), read.count(), String.join(", ", read.materials()), readNanos / 1e6, readCpu / 1e6, Files.size(file) / 1e6,
                    robots, pairs, rounds, seed);
            System.out.printf(Locale.ROOT, "all pairs' wall losses: median %.1f ms, max %.1f ms per round, median CPU %.1f ms"
                    + " (%.0f dB in all)%n", GridCrossingsBenchmark.median(nanos) / 1e6, GridCrossingsBenchmark.max(nanos) / 1e6, GridCrossingsBenchmark.median(cpuNanos) / 1e6, total);
            System.out.printf(Locale.ROOT, "against the 200 ms poll interval: %.3f (wall clock), %.3f (CPU)%n",
                    GridCrossingsBenchmark.median(nanos) / 200e6, GridCrossingsBenchmark.median(cpuNanos) / 200e6);
        } finally {
            Files.deleteIfExists(file);
        }
    }

    /** The losses of all pairs summed: the walls each pair crosses, by material, times their losses. */
    private static double allPairs(WorldWalls walls, double[] loss, double[][] at) {
        double total = 0;
        int[] counts = new int[loss.length];
        for (int i = 0; i < at.length; i++) {
            for (int j = i + 1; j < at.length; j++) {
                Arrays.fill(counts, 0);
                walls.crossed(at[i][0], at[i][1], at[j][0], at[j][1], counts);
                for (int m = 0; m < counts.length; m++) {
                    total += counts[m] * loss[m];
                }
            }
        }
        return total;
    }

    /** The building's walls between its doors and the boxes scattered in its rooms, {@code walls} in all. */
    static String world(int walls, Random random) {
        StringBuilder sdf = new StringBuilder("<?xml version=\"1.0\"?>\n<sdf version=\"1.6\">\n<world name=\"building\">\n");
        sdf.append("<include><uri>model://sun</uri></include>\n<include><uri>model://ground_plane</uri></include>\n");
        int count = 0;
        String[] kinds = {"Hard_wall", "Medium_wall", "Soft_wall", "window_glass"};
        int rooms = (int) (SIDE / ROOM);
        for (int line = 0; line <= rooms && count < walls; line++) {
            for (int room = 0; room < rooms && count < walls; room++) {
                // Along x at y = line * ROOM, and along y at x = line * ROOM: two boxes each side of a 1 m door.
                for (int half = 0; half < 2; half++) {
                    String kind = kinds[random.nextInt(kinds.length)];
                    double from = room * ROOM + (half == 0 ? 0 : 5.5);
                    double length = 4.5;
                    count += box(sdf, kind + "_" + count, from + length / 2, line * ROOM, 0, length, 0.2);
                    count += box(sdf, kind + "_" + count, line * ROOM, from + length / 2, Math.PI / 2, length, 0.2);
                }
            }
        }
        while (count < walls) {
            double x = random.nextDouble() * SIDE;
            double y = random.nextDouble() * SIDE;
            count += box(sdf, "crate_" + count, x, y, random.nextDouble() * Math.PI, 0.3 + random.nextDouble(), 0.3 + random.nextDouble());
        }
        return sdf.append("</world>\n</sdf>\n").toString();
    }

    private static int box(StringBuilder sdf, String name, double x, double y, double yaw, double length, double width) {
        sdf.append(String.format(Locale.ROOT, "<model name=\"%s\"><static>true</static><pose>%.3f %.3f 0 0 0 %.4f</pose>"
                + "<link name=\"link\"><collision name=\"collision\"><pose>0 0 1 0 0 0</pose><geometry><box><size>%.3f %.3f 2</size>"
                + "</box></geometry></collision><visual name=\"visual\"><geometry><box><size>%.3f %.3f 2</size></box></geometry>"
                + "</visual></link></model>%n", name, x, y, yaw, length, width, length, width));
        return 1;
    }
}
