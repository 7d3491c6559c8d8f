package org.usarsim.wss.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.usarsim.wss.ros.JsonException;
import org.usarsim.wss.ros.JsonLimits;
import org.usarsim.wss.ros.OccupancyGrid;
import org.usarsim.wss.ros.RosFrame;

/**
 * The walls of an occupancy grid between every pair of robots, timed (issue 23: a 2000 x 2000
 * grid and 100 robots, all 4,950 pairs within one poll interval of 200 ms). The grid is a
 * 100 x 100 m building at 5 cm a cell: rooms of 10 m with walls 2 cells thick and a 1 m door in
 * each, 1 % of the cells unknown at random. The peer, in the same run: the same walls as
 * segments (each wall of a room between its doors), counted as the world server and a
 * {@code obstacle.walls} file count them, segment by segment. The grid's rounds are also given in
 * CPU time of the benchmark's thread, which a loaded machine does not inflate as it does the
 * wall-clock time.
 *
 * <pre>
 * java -cp target/classes:target/test-classes org.usarsim.wss.bench.GridCrossingsBenchmark --rounds 30 --robots 100
 * </pre>
 */
public final class GridCrossingsBenchmark {

    private static final int CELLS = 2000;
    private static final double RESOLUTION = 0.05;
    private static final int ROOM_CELLS = 200;
    private static final int DOOR_CELLS = 20;

    private GridCrossingsBenchmark() {
    }

    public static void main(String[] args) {
        int rounds = 30;
        int robots = 100;
        long seed = 23;
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--rounds" -> rounds = Integer.parseInt(args[++i]);
                case "--robots" -> robots = Integer.parseInt(args[++i]);
                case "--seed" -> seed = Long.parseLong(args[++i]);
                default -> throw new IllegalArgumentException("unknown argument " + args[i]);
            }
        }
        Random random = new Random(seed);
        OccupancyGrid grid = building(random);
        List<double[]> segments = segments();
        double[][] at = new double[robots][];
        for (int i = 0; i < robots; i++) {
            at[i] = new double[] {random.nextDouble() * CELLS * RESOLUTION, random.nextDouble() * CELLS * RESOLUTION};
        }
        int pairs = robots * (robots - 1) / 2;
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        long[] gridNanos = new long[rounds];
        long[] gridCpuNanos = new long[rounds];
        long[] segmentNanos = new long[rounds];
        long gridWalls = 0;
        long segmentWalls = 0;
        for (int warm = 0; warm < 3; warm++) {
            gridWalls = allPairs(grid, at);
            segmentWalls = allPairs(segments, at);
        }
        for (int round = 0; round < rounds; round++) {
            long cpu = threads.getCurrentThreadCpuTime();
            long start = System.nanoTime();
            gridWalls = allPairs(grid, at);
            gridNanos[round] = System.nanoTime() - start;
            gridCpuNanos[round] = threads.getCurrentThreadCpuTime() - cpu;
            start = System.nanoTime();
            segmentWalls = allPairs(segments, at);
            segmentNanos[round] = System.nanoTime() - start;
        }
        System.out.printf(Locale.ROOT, "%d x %d grid at %.2f m, %d robots, %d pairs, %d rounds (seed %d)%n", CELLS, CELLS,
                RESOLUTION, robots, pairs, rounds, seed);
        System.out.printf(Locale.ROOT, "grid:     median %.1f ms, max %.1f ms per round of all pairs, median CPU %.1f ms"
                + " (%d walls counted)%n", median(gridNanos) / 1e6, max(gridNanos) / 1e6, median(gridCpuNanos) / 1e6, gridWalls);
        System.out.printf(Locale.ROOT, "segments: median %.1f ms, max %.1f ms (%d segments, %d walls counted)%n",
                median(segmentNanos) / 1e6, max(segmentNanos) / 1e6, segments.size(), segmentWalls);
        System.out.printf(Locale.ROOT, "grid / segments: %.2fx; grid / the 200 ms poll interval: %.3f%n",
                (double) median(gridNanos) / median(segmentNanos), median(gridNanos) / 200e6);
        readingTheMap(grid, Math.max(3, rounds / 10));
    }

    /**
     * The grid as rosbridge sends it ({@code /map}, one frame of JSON), read back: Json.parse and
     * OccupancyGrid.of, timed; the JDK's own reading of the same number of integers
     * ({@code Integer.parseInt} of each, split by hand) as the peer.
     */
    private static void readingTheMap(OccupancyGrid grid, int rounds) {
        StringBuilder text = new StringBuilder("{\"op\":\"publish\",\"topic\":\"\\/map\",\"msg\":{\"header\":{\"seq\":0,"
                + "\"stamp\":{\"secs\":0,\"nsecs\":0},\"frame_id\":\"map\"},\"info\":{\"resolution\":0.05,\"width\":" + CELLS
                + ",\"height\":" + CELLS + ",\"origin\":{\"position\":{\"x\":0.0,\"y\":0.0,\"z\":0.0},\"orientation\":"
                + "{\"x\":0.0,\"y\":0.0,\"z\":0.0,\"w\":1.0}}},\"data\":[");
        int dataAt = text.length();
        for (int row = 0; row < CELLS; row++) {
            for (int column = 0; column < CELLS; column++) {
                text.append(grid.value(column, row)).append(',');
            }
        }
        text.setLength(text.length() - 1);
        int dataEnd = text.length();
        text.append("]}}");
        String frame = text.toString();
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        long[] parse = new long[rounds];
        long[] parseCpu = new long[rounds];
        long[] peer = new long[rounds];
        long[] peerCpu = new long[rounds];
        long sum = 0;
        for (int round = 0; round < rounds; round++) {
            long cpu = threads.getCurrentThreadCpuTime();
            long start = System.nanoTime();
            try {
                sum += OccupancyGrid.of(RosFrame.parse(frame, JsonLimits.DEFAULT).msg()).width();
            } catch (JsonException e) {
                throw new IllegalStateException(e);
            }
            parse[round] = System.nanoTime() - start;
            parseCpu[round] = threads.getCurrentThreadCpuTime() - cpu;
            cpu = threads.getCurrentThreadCpuTime();
            start = System.nanoTime();
            int from = dataAt;
            byte[] cells = new byte[CELLS * CELLS];
            for (int i = 0; i < cells.length; i++) {
                int comma = frame.indexOf(',', from);
                int end = comma < 0 || comma > dataEnd ? dataEnd : comma;
                cells[i] = (byte) Integer.parseInt(frame, from, end, 10);
                from = end + 1;
            }
            sum += cells[cells.length - 1];
            peer[round] = System.nanoTime() - start;
            peerCpu[round] = threads.getCurrentThreadCpuTime() - cpu;
        }
        System.out.printf(Locale.ROOT, "the /map frame (%.1f MB of JSON): parsed and read in median %.0f ms (CPU %.0f ms);"
                + " the peer (Integer.parseInt of each cell) %.0f ms (CPU %.0f ms); %.2fx in CPU (%d)%n", frame.length() / 1e6,
                median(parse) / 1e6, median(parseCpu) / 1e6, median(peer) / 1e6, median(peerCpu) / 1e6,
                (double) median(parseCpu) / median(peerCpu), sum);
    }

    /** Every pair's walls, summed (so that nothing is optimised away). */
    private static long allPairs(OccupancyGrid grid, double[][] at) {
        long walls = 0;
        for (int i = 0; i < at.length; i++) {
            for (int j = i + 1; j < at.length; j++) {
                walls += grid.crossings(at[i][0], at[i][1], at[j][0], at[j][1]);
            }
        }
        return walls;
    }

    private static long allPairs(List<double[]> segments, double[][] at) {
        long walls = 0;
        for (int i = 0; i < at.length; i++) {
            for (int j = i + 1; j < at.length; j++) {
                for (double[] s : segments) {
                    if (meet(at[i][0], at[i][1], at[j][0], at[j][1], s[0], s[1], s[2], s[3])) {
                        walls++;
                    }
                }
            }
        }
        return walls;
    }

    /** Whether two segments cross or touch (the orientation test). */
    private static boolean meet(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy) {
        double d1 = cross(cx, cy, dx, dy, ax, ay);
        double d2 = cross(cx, cy, dx, dy, bx, by);
        double d3 = cross(ax, ay, bx, by, cx, cy);
        double d4 = cross(ax, ay, bx, by, dx, dy);
        return d1 * d2 <= 0 && d3 * d4 <= 0;
    }

    private static double cross(double ox, double oy, double ax, double ay, double bx, double by) {
        return (ax - ox) * (by - oy) - (ay - oy) * (bx - ox);
    }

    /** Rooms of ROOM_CELLS, walls 2 cells thick on each room line, a door in each wall's middle; 1 % unknown. */
    private static OccupancyGrid building(Random random) {
        byte[] cells = new byte[CELLS * CELLS];
        for (int row = 0; row < CELLS; row++) {
            for (int column = 0; column < CELLS; column++) {
                boolean wallRow = row % ROOM_CELLS < 2 && !door(column);
                boolean wallColumn = column % ROOM_CELLS < 2 && !door(row);
                cells[row * CELLS + column] = (byte) (wallRow || wallColumn ? 100 : random.nextInt(100) == 0 ? -1 : 0);
            }
        }
        return new OccupancyGrid(CELLS, CELLS, RESOLUTION, 0, 0, 0, "map", cells);
    }

    private static boolean door(int along) {
        int inRoom = along % ROOM_CELLS;
        return inRoom >= (ROOM_CELLS - DOOR_CELLS) / 2 && inRoom < (ROOM_CELLS + DOOR_CELLS) / 2;
    }

    /** The same walls as segments along their middle: each room line cut by its doors. */
    private static List<double[]> segments() {
        List<double[]> segments = new ArrayList<>();
        double room = ROOM_CELLS * RESOLUTION;
        double doorStart = (ROOM_CELLS - DOOR_CELLS) / 2 * RESOLUTION;
        double doorEnd = (ROOM_CELLS + DOOR_CELLS) / 2 * RESOLUTION;
        for (int line = 0; line < CELLS / ROOM_CELLS; line++) {
            double at = line * room + RESOLUTION;
            for (int piece = 0; piece < CELLS / ROOM_CELLS; piece++) {
                double base = piece * room;
                segments.add(new double[] {base, at, base + doorStart, at});
                segments.add(new double[] {base + doorEnd, at, base + room, at});
                segments.add(new double[] {at, base, at, base + doorStart});
                segments.add(new double[] {at, base + doorEnd, at, base + room});
            }
        }
        return segments;
    }

    static long median(long[] values) {
        long[] sorted = values.clone();
        Arrays.sort(sorted);
        return sorted[sorted.length / 2];
    }

    static long max(long[] values) {
        return Arrays.stream(values).max().orElse(0);
    }
}
