package org.usarsim.wss.world;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The walls a line on the floor crosses, counted by material, fast: the walls (segments and
 * boxes) are kept in a uniform grid of cells, each wall in every cell its bounding box overlaps
 * (widened by {@link Segments#TOUCH}), and a line is tested only against the walls of the cells
 * it passes through; each wall once. About as many cells as walls: 5,000 walls and the 4,950
 * pairs of 100 robots in a few milliseconds (docs/performance.md). Immutable; safe to ask from any
 * thread.
 */
final class WallCrossings {

    private final List<Wall> segmentWalls;
    private final List<BoxWall> boxes;
    private final List<String> materials;
    /** Per wall (segments first, then boxes): its material's index. */
    private final int[] material;
    private final double originX;
    private final double originY;
    private final double cell;
    private final int columns;
    private final int rows;
    /** Per wall, its bounding box widened by {@link Segments#TOUCH}, in flat arrays: the first test, without touching the wall. */
    private final double[] minXs;
    private final double[] minYs;
    private final double[] maxXs;
    private final double[] maxYs;
    /** Per cell (row-major): the walls in it. */
    private final int[][] cells;
    /** Per thread: the query each wall was last tested in, so a wall in many cells is tested once. */
    private final ThreadLocal<int[]> seen;
    private final ThreadLocal<int[]> query = ThreadLocal.withInitial(() -> new int[1]);

    WallCrossings(List<Wall> segmentWalls, List<BoxWall> boxes) {
        this.segmentWalls = List.copyOf(segmentWalls);
        this.boxes = List.copyOf(boxes);
        int n = segmentWalls.size() + boxes.size();
        Map<String, Integer> indices = new LinkedHashMap<>();
        material = new int[n];
        double[][] bounds = new double[n][];
        for (int i = 0; i < n; i++) {
            String name = i < segmentWalls.size() ? segmentWalls.get(i).material() : boxes.get(i - segmentWalls.size()).material();
            material[i] = indices.computeIfAbsent(name, k -> indices.size());
            bounds[i] = bounds(i);
        }
        materials = List.copyOf(indices.keySet());
        minXs = new double[n];
        minYs = new double[n];
        maxXs = new double[n];
        maxYs = new double[n];
        for (int i = 0; i < n; i++) {
            minXs[i] = bounds[i][0];
            minYs[i] = bounds[i][1];
            maxXs[i] = bounds[i][2];
            maxYs[i] = bounds[i][3];
        }
        double minX = Double.POSITIVE_INFINITY;
        double minY = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY;
        double maxY = Double.NEGATIVE_INFINITY;
        for (double[] b : bounds) {
            minX = Math.min(minX, b[0]);
            minY = Math.min(minY, b[1]);
            maxX = Math.max(maxX, b[2]);
            maxY = Math.max(maxY, b[3]);
        }
        int side = Math.max(1, (int) Math.ceil(Math.sqrt(n)));
        double extent = n == 0 ? 1 : Math.max(maxX - minX, maxY - minY);
        cell = extent > 0 ? extent / side : 1;
        originX = n == 0 ? 0 : minX;
        originY = n == 0 ? 0 : minY;
        columns = n == 0 ? 1 : Math.max(1, Math.min(side, (int) Math.floor((maxX - minX) / cell) + 1));
        rows = n == 0 ? 1 : Math.max(1, Math.min(side, (int) Math.floor((maxY - minY) / cell) + 1));
        List<List<Integer>> filling = new ArrayList<>(columns * rows);
        for (int c = 0; c < columns * rows; c++) {
            filling.add(new ArrayList<>());
        }
        for (int i = 0; i < n; i++) {
            double[] b = bounds[i];
            for (int row = row(b[1]); row <= row(b[3]); row++) {
                for (int column = column(b[0]); column <= column(b[2]); column++) {
                    filling.get(row * columns + column).add(i);
                }
            }
        }
        cells = new int[columns * rows][];
        for (int c = 0; c < cells.length; c++) {
            cells[c] = filling.get(c).stream().mapToInt(Integer::intValue).toArray();
        }
        seen = ThreadLocal.withInitial(() -> new int[n]);
    }

    /** The wall's bounding box widened by {@link Segments#TOUCH}: {minX, minY, maxX, maxY}. */
    private double[] bounds(int i) {
        double t = Segments.TOUCH;
        if (i < segmentWalls.size()) {
            Wall w = segmentWalls.get(i);
            return new double[] {Math.min(w.x1(), w.x2()) - t, Math.min(w.y1(), w.y2()) - t,
                Math.max(w.x1(), w.x2()) + t, Math.max(w.y1(), w.y2()) + t};
        }
        BoxWall b = boxes.get(i - segmentWalls.size());
        return new double[] {b.minX() - t, b.minY() - t, b.maxX() + t, b.maxY() + t};
    }

    private int column(double x) {
        return clamp((int) Math.floor((x - originX) / cell), columns);
    }

    private int row(double y) {
        return clamp((int) Math.floor((y - originY) / cell), rows);
    }

    private static int clamp(int i, int size) {
        return Math.max(0, Math.min(size - 1, i));
    }

    List<Wall> segmentWalls() {
        return segmentWalls;
    }

    List<BoxWall> boxes() {
        return boxes;
    }

    int size() {
        return segmentWalls.size() + boxes.size();
    }

    List<String> materials() {
        return materials;
    }

    /** The segments first, then each box's outline: what the map draws. */
    List<Wall> segments() {
        List<Wall> all = new ArrayList<>(segmentWalls);
        for (BoxWall box : boxes) {
            all.addAll(box.edges());
        }
        return List.copyOf(all);
    }

    /** Adds to {@code byMaterial} the walls of each material the line from (ax, ay) to (bx, by) crosses or touches. */
    void count(double ax, double ay, double bx, double by, int[] byMaterial) {
        if (material.length == 0) {
            return;
        }
        int[] stamps = seen.get();
        int[] counter = query.get();
        if (++counter[0] == 0) {
            java.util.Arrays.fill(stamps, 0);
            counter[0] = 1;
        }
        int stamp = counter[0];
        double t = Segments.TOUCH;
        // Column by column of the cells under the line's x range: the rows its y spans within that column, widened.
        double x0 = Math.min(ax, bx);
        double x1 = Math.max(ax, bx);
        double lowX = x0;
        double highX = x1;
        double lowY = Math.min(ay, by);
        double highY = Math.max(ay, by);
        int first = column(x0 - t);
        int last = column(x1 + t);
        for (int column = first; column <= last; column++) {
            double from = Math.max(x0, originX + column * cell) - t;
            double to = Math.min(x1, originX + (column + 1) * cell) + t;
            double yFrom = yAt(ax, ay, bx, by, from);
            double yTo = yAt(ax, ay, bx, by, to);
            int lowRow = row(Math.min(yFrom, yTo) - t);
            int highRow = row(Math.max(yFrom, yTo) + t);
            for (int row = lowRow; row <= highRow; row++) {
                for (int wall : cells[row * columns + column]) {
                    if (stamps[wall] != stamp) {
                        stamps[wall] = stamp;
                        if (lowX <= maxXs[wall] && highX >= minXs[wall] && lowY <= maxYs[wall] && highY >= minYs[wall]
                                && blocks(wall, ax, ay, bx, by)) {
                            byMaterial[material[wall]]++;
                        }
                    }
                }
            }
        }
    }

    /** The line's y at x, clamped to its ends (its whole y range when it is vertical). */
    private static double yAt(double ax, double ay, double bx, double by, double x) {
        if (ax == bx) {
            return x <= ax ? Math.min(ay, by) : Math.max(ay, by);
        }
        double f = Math.max(0, Math.min(1, (x - ax) / (bx - ax)));
        return ay + f * (by - ay);
    }

    private boolean blocks(int wall, double ax, double ay, double bx, double by) {
        if (wall >= segmentWalls.size()) {
            return boxes.get(wall - segmentWalls.size()).blocks(ax, ay, bx, by);
        }
        Wall w = segmentWalls.get(wall);
        double t = Segments.TOUCH;
        if (Math.max(ax, bx) < Math.min(w.x1(), w.x2()) - t || Math.min(ax, bx) > Math.max(w.x1(), w.x2()) + t
                || Math.max(ay, by) < Math.min(w.y1(), w.y2()) - t || Math.min(ay, by) > Math.max(w.y1(), w.y2()) + t) {
            return false;
        }
        return Segments.meet(ax, ay, bx, by, w.x1(), w.y1(), w.x2(), w.y2());
    }
}
