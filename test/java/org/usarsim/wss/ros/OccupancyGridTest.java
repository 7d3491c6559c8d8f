package org.usarsim.wss.ros;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.Random;
import org.junit.jupiter.api.Test;

/** The walls an occupancy grid puts between two points: runs of occupied cells, resolution, origin and threshold honoured. */
class OccupancyGridTest {

    /** A grid of 0 (free) cells, then {@code set}'s columns filled with a value from row 0 to the top. */
    private static byte[] free(int width, int height) {
        return new byte[width * height];
    }

    private static void column(byte[] cells, int width, int column, int value) {
        for (int row = 0; row < cells.length / width; row++) {
            cells[row * width + column] = (byte) value;
        }
    }

    @Test
    void aWallAcrossTheLineIsOneCrossingAndAThickWallToo() {
        byte[] cells = free(40, 10);
        column(cells, 40, 10, 100);
        column(cells, 40, 20, 100);
        column(cells, 40, 21, 100);
        column(cells, 40, 22, 100);
        OccupancyGrid grid = new OccupancyGrid(40, 10, 0.1, 0, 0, 0, "map", cells);
        assertEquals(0, grid.crossings(0.05, 0.55, 0.95, 0.55), "stops short of the wall");
        assertEquals(1, grid.crossings(0.05, 0.55, 1.55, 0.55), "the wall at x = 1.0 to 1.1");
        assertEquals(2, grid.crossings(0.05, 0.55, 3.95, 0.25), "the thin wall and the thick one");
        assertEquals(2, grid.crossings(3.95, 0.25, 0.05, 0.55), "either way");
        assertEquals(1, grid.crossings(1.05, 0.55, 1.95, 0.55), "a point in a wall is in its run");
        assertEquals(0, grid.crossings(0.05, 0.05, 0.05, 0.95), "along a free column");
    }

    @Test
    void theThresholdDecidesAndUnknownIsNeverAWall() {
        byte[] cells = free(10, 1);
        cells[3] = 64;
        cells[5] = 65;
        cells[7] = (byte) OccupancyGrid.UNKNOWN;
        OccupancyGrid grid = new OccupancyGrid(10, 1, 1, 0, 0, 0, "map", cells);
        assertEquals(1, grid.crossings(0.5, 0.5, 9.5, 0.5));
        assertEquals(2, grid.crossings(0.5, 0.5, 9.5, 0.5, 50));
        assertEquals(0, grid.crossings(0.5, 0.5, 9.5, 0.5, 100));
        assertEquals(2, grid.crossings(0.5, 0.5, 9.5, 0.5, 0), "-1 is not a wall even at threshold 0: it parts the cells into two runs");
    }

    @Test
    void theOriginAndItsTurnPlaceTheGrid() {
        byte[] cells = free(20, 20);
        column(cells, 20, 10, 100);
        // Turned 90 degrees about its origin (-5, 0): columns run along +y, rows along -x.
        OccupancyGrid grid = new OccupancyGrid(20, 20, 1, -5, 0, Math.PI / 2, "map", cells);
        assertEquals(1, grid.crossings(-10, 5, -10, 15));
        assertEquals(0, grid.crossings(-10, 5, -10, 9.9));
        assertEquals(0, grid.crossings(10, 5, 10, 15), "beside the grid");
        OccupancyGrid shifted = new OccupancyGrid(20, 20, 0.5, 100, 200, 0, "map", cells);
        assertEquals(1, shifted.crossings(104, 201, 106, 201));
        assertEquals(0, shifted.crossings(4, 1, 6, 1));
    }

    @Test
    void aDiagonalWallHasNoGapAtItsCorners() {
        byte[] cells = free(2, 2);
        cells[1] = 100; // column 1, row 0
        cells[2] = 100; // column 0, row 1
        OccupancyGrid grid = new OccupancyGrid(2, 2, 1, 0, 0, 0, "map", cells);
        assertEquals(1, grid.crossings(0.5, 0.5, 1.5, 1.5), "through the corner the two wall cells share");
    }

    @Test
    void aLineOutOfTheGridCountsOnlyWhatIsInside() {
        byte[] cells = free(10, 10);
        column(cells, 10, 5, 100);
        OccupancyGrid grid = new OccupancyGrid(10, 10, 1, 0, 0, 0, "map", cells);
        assertEquals(1, grid.crossings(-50, 5.5, 50, 5.5));
        assertEquals(0, grid.crossings(-50, 50, 50, 50));
        assertEquals(1, grid.crossings(5.5, 5.5, 5.5, 5.5), "a point in a wall");
        assertEquals(0, new OccupancyGrid(0, 0, 1, 0, 0, 0, "map", new byte[0]).crossings(0, 0, 1, 1));
        assertEquals(0, grid.crossings(Double.MAX_VALUE, 0, -Double.MAX_VALUE, 0), "beyond any cell: nothing");
    }

    @Test
    void randomLinesCountTheSameBothWays() {
        Random random = new Random(23);
        byte[] cells = free(50, 40);
        for (int i = 0; i < cells.length; i++) {
            cells[i] = (byte) (random.nextInt(10) == 0 ? 100 : random.nextInt(3) == 0 ? -1 : 0);
        }
        OccupancyGrid grid = new OccupancyGrid(50, 40, 0.25, -2, 3, 0.4, "map", cells);
        for (int i = 0; i < 10_000; i++) {
            double x1 = random.nextDouble() * 20 - 6;
            double y1 = random.nextDouble() * 20;
            double x2 = random.nextDouble() * 20 - 6;
            double y2 = random.nextDouble() * 20;
            assertEquals(grid.crossings(x1, y1, x2, y2), grid.crossings(x2, y2, x1, y1));
        }
    }

    private static String map(String info, String data) {
        return "{\"op\":\"publish\",\"topic\":\"\\/map\",\"msg\":{\"header\":{\"frame_id\":\"\\/map\"},\"info\":" + info
                + ",\"data\":" + data + "}}";
    }

    private static final String INFO = "{\"map_load_time\":{\"secs\":0,\"nsecs\":0},\"resolution\":0.5,\"width\":3,\"height\":2,"
            + "\"origin\":{\"position\":{\"x\":1.0,\"y\":2.0,\"z\":0.0},\"orientation\":{\"x\":0.0,\"y\":0.0,\"z\":0.0,\"w\":1.0}}}";

    private static OccupancyGrid parse(String frame) throws JsonException {
        return OccupancyGrid.of(RosFrame.parse(frame, JsonLimits.DEFAULT).msg());
    }

    @Test
    void aMessageGivesItsGrid() throws JsonException {
        OccupancyGrid grid = parse(map(INFO, "[0,100,-1,0,0,100]"));
        assertEquals(3, grid.width());
        assertEquals(2, grid.height());
        assertEquals(0.5, grid.resolution());
        assertEquals(1.0, grid.originX());
        assertEquals(2.0, grid.originY());
        assertEquals("map", grid.frameId());
        assertEquals(100, grid.value(1, 0));
        assertEquals(-1, grid.value(2, 0));
        assertEquals(100, grid.value(2, 1));
        assertEquals(1, grid.crossings(1.1, 2.2, 2.4, 2.2));
    }

    @Test
    void aBadGridIsAClearError() {
        assertEquals("msg.data: 5 cells for 3 x 2", assertThrows(JsonException.class,
                () -> parse(map(INFO, "[0,100,-1,0,0]"))).getMessage());
        assertEquals("msg.data[3]: expected -1 or a whole number from 0 to 100, found 101.0", assertThrows(JsonException.class,
                () -> parse(map(INFO, "[0,100,-1,101,0,0]"))).getMessage());
        assertEquals("msg.data[1]: expected -1 or a whole number from 0 to 100, found null", assertThrows(JsonException.class,
                () -> parse(map(INFO, "[0,null,-1,1,0,0]"))).getMessage());
        assertEquals("msg.info: expected an object, found null", assertThrows(JsonException.class,
                () -> parse(map("null", "[]"))).getMessage());
        assertEquals("msg.info.resolution: a cell's size in metres, above 0, not 0.0", assertThrows(JsonException.class,
                () -> parse(map(INFO.replace("0.5", "0"), "[0,0,0,0,0,0]"))).getMessage());
    }
}
