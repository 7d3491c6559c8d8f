package org.usarsim.wss.world;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.List;

/**
 * The walls a model counts between two places itself (the Obstacle model's {@code obstacle.walls}):
 * the {@code wall} lines of a world file (its robots are not read further), or the boxes of a
 * Gazebo world (an SDF document: a file whose first character is {@code <}), and how many of them
 * the straight line on the floor between two places crosses or touches, by material: the count
 * the world server answers to {@code GETOBS}. A box is one wall however many of its edges the line
 * meets. Immutable.
 */
public final class WorldWalls {

    /** The largest file read: an SDF world of 64 MiB is far beyond any real one. */
    public static final long MAX_BYTES = 64L << 20;

    private final List<String> notes;
    private final WallCrossings crossings;

    private WorldWalls(List<Wall> segments, List<BoxWall> boxes, List<String> notes) {
        this.notes = List.copyOf(notes);
        this.crossings = new WallCrossings(segments, boxes);
    }

    /** These walls: for tests and benchmarks. */
    static WorldWalls of(List<Wall> segments, List<BoxWall> boxes) {
        return new WorldWalls(segments, boxes, List.of());
    }

    /** The walls of the world file; its first mistake refuses it, as the world server does. */
    public static WorldWalls read(Path file) throws WorldFileException {
        return new WorldWalls(WorldFile.read(file).walls(), List.of(), List.of());
    }

    /**
     * The walls of a world file or of an SDF world, the boxes of which are kept when their
     * vertical extent meets {@code low..high} metres and get their material from {@code rules}.
     */
    public static WorldWalls read(Path file, MaterialRules rules, double low, double high) throws WorldFileException {
        byte[] bytes;
        try {
            if (Files.size(file) > MAX_BYTES) {
                throw new WorldFileException(file + ": larger than " + (MAX_BYTES >> 20) + " MiB");
            }
            bytes = Files.readAllBytes(file);
        } catch (NoSuchFileException e) {
            throw new WorldFileException(file + ": no such file");
        } catch (IOException e) {
            throw new WorldFileException(file + ": cannot read it: " + e);
        }
        int start = xmlStart(bytes);
        if (start < 0) {
            return read(file);
        }
        SdfWalls.Result sdf = SdfWalls.parse(java.util.Arrays.copyOfRange(bytes, start, bytes.length), file.toString(), rules, low, high);
        return new WorldWalls(List.of(), sdf.boxes(), sdf.notes());
    }

    /** Where the document starts when its first character, after a byte order mark and white space, is {@code <}; else -1. */
    private static int xmlStart(byte[] bytes) {
        int i = bytes.length >= 3 && (bytes[0] & 0xFF) == 0xEF && (bytes[1] & 0xFF) == 0xBB && (bytes[2] & 0xFF) == 0xBF ? 3 : 0;
        while (i < bytes.length && Character.isWhitespace(bytes[i])) {
            i++;
        }
        return i < bytes.length && bytes[i] == '<' ? i : -1;
    }

    /** Every wall as segments for the map: a world file's walls, then each box's outline, with their materials. */
    public List<Wall> walls() {
        return crossings.segments();
    }

    /** How many walls (a box once) the source holds. */
    public int count() {
        return crossings.size();
    }

    /** What an SDF world's reading left out, one line per kind; empty for a world file. */
    public List<String> notes() {
        return notes;
    }

    /** The walls' materials, each once, in the order first met; empty for a wall of none. */
    public List<String> materials() {
        return crossings.materials();
    }

    /** How many walls the line on the floor from (ax, ay) to (bx, by) crosses or touches. */
    public int crossings(double ax, double ay, double bx, double by) {
        int[] counts = new int[materials().size()];
        crossed(ax, ay, bx, by, counts);
        int total = 0;
        for (int count : counts) {
            total += count;
        }
        return total;
    }

    /**
     * Adds to {@code byMaterial} (indexed as {@link #materials()}) the walls of each material the
     * line on the floor from (ax, ay) to (bx, by) crosses or touches.
     */
    public void crossed(double ax, double ay, double bx, double by, int[] byMaterial) {
        crossings.count(ax, ay, bx, by, byMaterial);
    }

    /** The boxes of an SDF world: for tests. */
    List<BoxWall> boxes() {
        return crossings.boxes();
    }
}
