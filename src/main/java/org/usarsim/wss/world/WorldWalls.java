package org.usarsim.wss.world;

import java.nio.file.Path;
import java.util.List;

/**
 * The walls of a world file (its {@code wall} lines; its robots are not read further), and how
 * many of them the straight line on the floor between two places crosses or touches: the count
 * the world server answers to {@code GETOBS}, for a model that counts obstacles itself (the
 * Obstacle model's {@code obstacle.walls}).
 */
public final class WorldWalls {

    private final List<Wall> walls;

    private WorldWalls(List<Wall> walls) {
        this.walls = List.copyOf(walls);
    }

    /** The walls of the world file; its first mistake refuses it, as the world server does. */
    public static WorldWalls read(Path file) throws WorldFileException {
        return new WorldWalls(WorldFile.read(file).walls());
    }

    public List<Wall> walls() {
        return walls;
    }

    /** How many walls the line on the floor from (ax, ay) to (bx, by) crosses or touches. */
    public int crossings(double ax, double ay, double bx, double by) {
        Point a = new Point(ax, ay, 0);
        Point b = new Point(bx, by, 0);
        int count = 0;
        for (Wall wall : walls) {
            if (wall.blocks(a, b)) {
                count++;
            }
        }
        return count;
    }
}
