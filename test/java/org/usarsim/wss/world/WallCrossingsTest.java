package org.usarsim.wss.world;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** The grid of walls answers what testing every wall answers. */
class WallCrossingsTest {

    @Test
    void theGridCountsWhatEveryWallTestedCountsByMaterial() {
        Random random = new Random(35);
        List<Wall> segments = new ArrayList<>();
        List<BoxWall> boxes = new ArrayList<>();
        String[] materials = {"", "concrete", "glass"};
        for (int i = 0; i < 300; i++) {
            double x = random.nextDouble() * 50;
            double y = random.nextDouble() * 30;
            double length = random.nextDouble() * 8;
            double angle = random.nextDouble() * Math.PI;
            String material = materials[random.nextInt(3)];
            if (random.nextBoolean()) {
                segments.add(new Wall(x, y, x + length * Math.cos(angle), y + length * Math.sin(angle), material));
            } else {
                double w = random.nextDouble() * 0.5;
                double c = Math.cos(angle);
                double s = Math.sin(angle);
                boxes.add(BoxWall.around("b" + i, material, List.of(new double[] {x, y}, new double[] {x + length * c, y + length * s},
                        new double[] {x + length * c - w * s, y + length * s + w * c}, new double[] {x - w * s, y + w * c})));
            }
        }
        // Lines on grid lines, vertical, horizontal, points, and some beyond the walls' extent.
        segments.add(new Wall(10, 0, 10, 30, "glass"));
        WallCrossings grid = new WallCrossings(segments, boxes);
        for (int i = 0; i < 3000; i++) {
            double ax = random.nextDouble() * 70 - 10;
            double ay = random.nextDouble() * 50 - 10;
            double bx = i % 7 == 0 ? ax : random.nextDouble() * 70 - 10;
            double by = i % 11 == 0 ? ay : random.nextDouble() * 50 - 10;
            if (i % 13 == 0) {
                ax = 10;
                bx = 10;
            }
            int[] counted = new int[grid.materials().size()];
            grid.count(ax, ay, bx, by, counted);
            int[] expected = new int[grid.materials().size()];
            Point a = new Point(ax, ay, 0);
            Point b = new Point(bx, by, 0);
            for (Wall wall : segments) {
                expected[grid.materials().indexOf(wall.material())] += wall.blocks(a, b) ? 1 : 0;
            }
            for (BoxWall box : boxes) {
                expected[grid.materials().indexOf(box.material())] += box.blocks(ax, ay, bx, by) ? 1 : 0;
            }
            assertArrayEquals(expected, counted, ax + "," + ay + " to " + bx + "," + by);
        }
    }

    @Test
    void noWallsCountNothing() {
        WallCrossings none = new WallCrossings(List.of(), List.of());
        assertEquals(List.of(), none.materials());
        none.count(0, 0, 10, 10, new int[0]);
    }

    @Test
    void oneWallAPointOnItAndALineAlongIt() {
        WallCrossings one = new WallCrossings(List.of(new Wall(0, 0, 10, 0)), List.of());
        int[] counted = new int[1];
        one.count(5, 0, 5, 0, counted);
        one.count(-5, 0, 20, 0, counted);
        one.count(5, 1, 5, 2, counted);
        assertArrayEquals(new int[] {2}, counted);
    }
}
