package org.usarsim.wss.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.geom.Point2D;
import java.awt.geom.Rectangle2D;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Issue 26, item 2: the map's pair labels never lie on each other or on a robot's name. */
class LabelPlacerTest {

    private static final double W = 110;
    private static final double H = 13;
    private static final Rectangle2D CANVAS = new Rectangle2D.Double(0, 0, 800, 600);

    @Test
    void twoLabelsOnOneLineAndARobotsNameGetBoxesThatOverlapNone() {
        LabelPlacer placer = new LabelPlacer(CANVAS);
        Point2D a = new Point2D.Double(100, 300);
        Point2D b = new Point2D.Double(500, 300);
        // A robot's name where the first label would go: above the middle, right of it.
        placer.take(new Rectangle2D.Double(310, 280, 60, 15));
        Rectangle2D first = placer.place(LabelPlacer.alongLine(a, b, W, H), W, H, "label", null);
        Rectangle2D second = placer.place(LabelPlacer.alongLine(a, b, W, H), W, H, "label", null); // the same pair's other way, or a pair on the same line
        assertNotNull(first);
        assertNotNull(second);
        List<Rectangle2D> boxes = placer.taken();
        for (int i = 0; i < boxes.size(); i++) {
            for (int j = i + 1; j < boxes.size(); j++) {
                assertFalse(boxes.get(i).intersects(boxes.get(j)), boxes.get(i) + " and " + boxes.get(j));
            }
        }
        assertEquals(3, boxes.size());
    }

    @Test
    void aLabelWithNoFreePlaceIsLeftOut() {
        LabelPlacer placer = new LabelPlacer(CANVAS);
        placer.take(new Rectangle2D.Double(-1000, -1000, 3000, 3000));
        assertNull(placer.place(LabelPlacer.alongLine(new Point2D.Double(0, 0), new Point2D.Double(100, 0), W, H), W, H, "label", null));
        assertEquals(1, placer.taken().size());
    }

    @Test
    void aPlaceCutByTheCanvassEdgeIsPassedOverForTheNextOne() {
        LabelPlacer placer = new LabelPlacer(CANVAS);
        // A line along the left edge: every place left of it lies partly off the canvas.
        Point2D a = new Point2D.Double(10, 100);
        Point2D b = new Point2D.Double(10, 400);
        Rectangle2D box = placer.place(List.of(new Point2D.Double(10 - 4 - W, 200), new Point2D.Double(14, 200)), W, H, "label", null);
        assertEquals(new Rectangle2D.Double(14, 200, W, H), box, "the second place: the first is cut by the edge");
        Rectangle2D beside = placer.place(LabelPlacer.alongLine(a, b, W, H), W, H, "label", null);
        assertNotNull(beside, "right of the line there is room");
        assertTrue(CANVAS.contains(beside), beside + " inside the canvas");
        assertNull(placer.place(List.of(new Point2D.Double(-5, 300), new Point2D.Double(750, 300)), W, H, "label", null), "no place inside: left out");
        assertEquals(1, placer.leftOut());
    }
}
