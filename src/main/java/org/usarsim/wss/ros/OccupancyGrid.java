package org.usarsim.wss.ros;

import java.util.List;

/**
 * A {@code nav_msgs/OccupancyGrid}: {@code width} x {@code height} cells of {@code resolution}
 * metres, row by row from the origin (cell (0, 0)'s corner, {@code info.origin}: a position and a
 * turn about z), each -1 (unknown) or 0 to 100 (the chance, in percent, that it is occupied), and
 * the walls it makes between two points: {@link #crossings}. Immutable.
 */
public final class OccupancyGrid {

    /** The ROS type of a grid. */
    public static final String TYPE = "nav_msgs/OccupancyGrid";
    /**
     * A cell is a wall from this value on: ROS's {@code map_server} writes a map's occupied cells
     * as 100 and its free ones as 0, and reads an image's pixels as occupied from 0.65
     * ({@code occupied_thresh}); 65 counts the cells it would, and a costmap's inscribed (99) and
     * lethal (100) cells, not its inflation below.
     */
    public static final int DEFAULT_THRESHOLD = 65;
    /** The value of a cell nobody has seen; never a wall. */
    public static final int UNKNOWN = -1;

    private final int width;
    private final int height;
    private final double resolution;
    private final double originX;
    private final double originY;
    private final double yaw;
    private final double cos;
    private final double sin;
    private final String frameId;
    private final byte[] cells;

    /**
     * @param cells row by row ({@code cells[row * width + column]}), each -1 or 0 to 100
     * @throws IllegalArgumentException sizes that do not fit, a resolution that is not above 0, a
     *     cell out of range
     */
    public OccupancyGrid(int width, int height, double resolution, double originX, double originY, double yaw,
            String frameId, byte[] cells) {
        if (width < 0 || height < 0 || (long) width * height != cells.length) {
            throw new IllegalArgumentException(width + " x " + height + " cells, not " + cells.length);
        }
        if (!(resolution > 0) || !Double.isFinite(resolution) || !Double.isFinite(originX) || !Double.isFinite(originY)
                || !Double.isFinite(yaw)) {
            throw new IllegalArgumentException("a resolution above 0 and a finite origin: " + resolution + ", "
                    + originX + ", " + originY + ", " + yaw);
        }
        for (byte cell : cells) {
            if (cell < UNKNOWN || cell > 100) {
                throw new IllegalArgumentException("a cell is -1 or 0 to 100, not " + cell);
            }
        }
        this.width = width;
        this.height = height;
        this.resolution = resolution;
        this.originX = originX;
        this.originY = originY;
        this.yaw = yaw;
        this.cos = Math.cos(yaw);
        this.sin = Math.sin(yaw);
        this.frameId = frameId;
        this.cells = cells.clone();
    }

    /**
     * The grid of a {@code nav_msgs/OccupancyGrid} message ({@code info.resolution},
     * {@code info.width}, {@code info.height}, {@code info.origin.position},
     * {@code info.origin.orientation}, {@code data[]}; {@code header.frame_id} where present).
     */
    public static OccupancyGrid of(JsonNode msg) throws JsonException {
        JsonNode info = msg.get("info");
        JsonNode resolutionNode = info.get("resolution");
        double resolution = resolutionNode.number();
        if (!(resolution > 0)) {
            throw resolutionNode.problem("a cell's size in metres, above 0, not " + resolution);
        }
        int width = (int) info.get("width").integer(0, Integer.MAX_VALUE);
        int height = (int) info.get("height").integer(0, Integer.MAX_VALUE);
        JsonNode origin = info.get("origin");
        JsonNode position = origin.get("position");
        Transform turn = Transform.of(position, origin.get("orientation"));
        JsonNode data = msg.get("data");
        List<?> values = data.list();
        if ((long) width * height != values.size()) {
            throw data.problem(values.size() + " cells for " + width + " x " + height);
        }
        byte[] cells = new byte[values.size()];
        for (int i = 0; i < cells.length; i++) {
            Object value = values.get(i);
            if (!(value instanceof Double d) || d != Math.rint(d) || d < UNKNOWN || d > 100) {
                throw JsonException.in(data.path() + "[" + i + "]", "expected -1 or a whole number from 0 to 100, found "
                        + (value instanceof Double ? value : JsonNode.kind(value)));
            }
            cells[i] = (byte) d.intValue();
        }
        JsonNode header = msg.optional("header");
        JsonNode frame = header == null ? null : header.optional("frame_id");
        return new OccupancyGrid(width, height, resolution, turn.x(), turn.y(), turn.yaw(),
                frame == null ? "" : TfTree.plain(frame.string()), cells);
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    /** A cell's side, in metres. */
    public double resolution() {
        return resolution;
    }

    /** Where cell (0, 0)'s outer corner is, in metres. */
    public double originX() {
        return originX;
    }

    public double originY() {
        return originY;
    }

    /** How the grid's rows are turned from the x axis, in radians. */
    public double yaw() {
        return yaw;
    }

    /** The frame the grid is in ({@code map}), without a leading {@code /}; empty when the message said none. */
    public String frameId() {
        return frameId;
    }

    /** A cell's value: -1 (unknown) or 0 to 100. */
    public int value(int column, int row) {
        return cells[row * width + column];
    }

    /** Whether a value is a wall at this threshold (-1 never is). */
    public static boolean occupied(int value, int threshold) {
        return value >= Math.max(threshold, 0);
    }

    /** {@link #crossings(double, double, double, double, int)} at {@link #DEFAULT_THRESHOLD}. */
    public int crossings(double x1, double y1, double x2, double y2) {
        return crossings(x1, y1, x2, y2, DEFAULT_THRESHOLD);
    }

    /**
     * The walls between two points on the floor (metres, in the grid's frame): the runs of occupied
     * cells ({@link #occupied}) that the straight line from one to the other passes through, every
     * cell it touches counted (Amanatides and Woo's traversal; through a corner, both cells beside
     * it). Outside the grid is unknown, never a wall. A point inside a wall is in that wall's run.
     */
    public int crossings(double x1, double y1, double x2, double y2, int threshold) {
        double u1 = column(x1, y1);
        double v1 = row(x1, y1);
        double u2 = column(x2, y2);
        double v2 = row(x2, y2);
        if (cells.length == 0 || !Double.isFinite(u1) || !Double.isFinite(v1) || !Double.isFinite(u2) || !Double.isFinite(v2)) {
            return 0;
        }
        double du = u2 - u1;
        double dv = v2 - v1;
        // Clipped to the grid (Liang and Barsky): t from enter to leave is inside.
        double[] range = {0, 1};
        if (!clip(-du, u1, range) || !clip(du, width - u1, range) || !clip(-dv, v1, range) || !clip(dv, height - v1, range)) {
            return 0;
        }
        double startU = u1 + du * range[0];
        double startV = v1 + dv * range[0];
        int column = clamp((int) Math.floor(startU), width);
        int row = clamp((int) Math.floor(startV), height);
        int endColumn = clamp((int) Math.floor(u1 + du * range[1]), width);
        int endRow = clamp((int) Math.floor(v1 + dv * range[1]), height);
        int stepU = du > 0 ? 1 : -1;
        int stepV = dv > 0 ? 1 : -1;
        double deltaU = du == 0 ? Double.POSITIVE_INFINITY : Math.abs(1 / du);
        double deltaV = dv == 0 ? Double.POSITIVE_INFINITY : Math.abs(1 / dv);
        double nextU = du == 0 ? Double.POSITIVE_INFINITY : ((stepU > 0 ? column + 1 : column) - startU) / du;
        double nextV = dv == 0 ? Double.POSITIVE_INFINITY : ((stepV > 0 ? row + 1 : row) - startV) / dv;
        int steps = Math.abs(endColumn - column) + Math.abs(endRow - row);
        int wallFrom = Math.max(threshold, 0);
        int index = row * width + column;
        int rowStep = stepV * width;
        int runs = 0;
        boolean inWall = false;
        for (int i = 0; ; i++) {
            boolean wall = cells[index] >= wallFrom;
            if (wall && !inWall) {
                runs++;
            }
            inWall = wall;
            if (i == steps) {
                return runs;
            }
            // Across the nearer cell border; along the other axis once this one has reached its end.
            if (nextU < nextV ? column != endColumn : row == endRow) {
                column += stepU;
                index += stepU;
                nextU += deltaU;
            } else {
                row += stepV;
                index += rowStep;
                nextV += deltaV;
            }
        }
    }

    /** The grid's column coordinate (in cells, fractional) of a point. */
    private double column(double x, double y) {
        return (cos * (x - originX) + sin * (y - originY)) / resolution;
    }

    private double row(double x, double y) {
        return (-sin * (x - originX) + cos * (y - originY)) / resolution;
    }

    /** One side of Liang and Barsky's clip: p t <= q, narrowing [t0, t1]; false when nothing is left. */
    private static boolean clip(double p, double q, double[] range) {
        if (p == 0) {
            return q >= 0;
        }
        double t = q / p;
        if (p < 0) {
            if (t > range[1]) {
                return false;
            }
            range[0] = Math.max(range[0], t);
        } else {
            if (t < range[0]) {
                return false;
            }
            range[1] = Math.min(range[1], t);
        }
        return true;
    }

    private static int clamp(int cell, int size) {
        return Math.max(0, Math.min(size - 1, cell));
    }
}
