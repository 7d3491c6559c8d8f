package org.usarsim.wss.model.simulator;

import java.util.ArrayList;
import java.util.List;
import org.usarsim.wss.model.Wall;
import org.usarsim.wss.ros.OccupancyGrid;

/**
 * An occupancy grid's walls as the map draws them and a recording keeps them: each run of occupied
 * cells along a row, one segment through the middle of the row from the first cell's edge to the
 * last's, turned and moved by the grid's origin. A grid with more runs than {@link #MAX_WALLS} is
 * drawn in blocks of 2 x 2 cells (4 x 4, ...), a block occupied when any of its cells is, so that
 * the map and the recording stay small; the counting ({@link OccupancyGrid#crossings}) is always
 * cell by cell.
 */
final class GridWalls {

    /** The most segments drawn for one grid. */
    static final int MAX_WALLS = 20_000;

    private GridWalls() {
    }

    static List<Wall> of(OccupancyGrid grid) {
        for (int block = 1;; block *= 2) {
            List<Wall> walls = runs(grid, block);
            if (walls != null) {
                return List.copyOf(walls);
            }
        }
    }

    /** The runs with cells taken {@code block} x {@code block} together; null when there are more than {@link #MAX_WALLS}. */
    private static List<Wall> runs(OccupancyGrid grid, int block) {
        List<Wall> walls = new ArrayList<>();
        int rows = (grid.height() + block - 1) / block;
        int columns = (grid.width() + block - 1) / block;
        for (int row = 0; row < rows; row++) {
            int start = -1;
            for (int column = 0; column <= columns; column++) {
                boolean occupied = column < columns && occupied(grid, column, row, block);
                if (occupied && start < 0) {
                    start = column;
                } else if (!occupied && start >= 0) {
                    double v = (row + 0.5) * block;
                    walls.add(wall(grid, start * block, v, Math.min(column * block, grid.width()), v));
                    if (walls.size() > MAX_WALLS) {
                        return null;
                    }
                    start = -1;
                }
            }
        }
        return walls;
    }

    private static boolean occupied(OccupancyGrid grid, int column, int row, int block) {
        for (int r = row * block; r < Math.min((row + 1) * block, grid.height()); r++) {
            for (int c = column * block; c < Math.min((column + 1) * block, grid.width()); c++) {
                if (OccupancyGrid.occupied(grid.value(c, r), OccupancyGrid.DEFAULT_THRESHOLD)) {
                    return true;
                }
            }
        }
        return false;
    }

    /** The segment from cell coordinates (u1, v1) to (u2, v2), in metres in the grid's frame. */
    private static Wall wall(OccupancyGrid grid, double u1, double v1, double u2, double v2) {
        double cos = Math.cos(grid.yaw());
        double sin = Math.sin(grid.yaw());
        double r = grid.resolution();
        return new Wall(grid.originX() + (u1 * cos - v1 * sin) * r, grid.originY() + (u1 * sin + v1 * cos) * r,
                grid.originX() + (u2 * cos - v2 * sin) * r, grid.originY() + (u2 * sin + v2 * cos) * r);
    }
}
