package org.usarsim.wss.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.awt.geom.Point2D;
import java.awt.geom.Rectangle2D;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Issue 26, item 2: the map's pair labels never lie on each other or on a robot's name. */
class LabelPlacerTest {

    private static final double W = 110;
    private static final double H = 13;

    @Test
    void twoLabelsOnOneLineAndARobotsNameGetBoxesThatOverlapNone() {
        LabelPlacer placer = new LabelPlacer();
        Point2D a = new Point2D.Double(100, 300);
        Point2D b = new Point2D.Double(500, 300);
        // A robot's name where the first label would go: above the middle, right of it.
        placer.take(new Rectangle2D.Double(310, 280, 60, 15));
        Rectangle2D first = placer.place(LabelPlacer.alongLine(a, b, W, H), W, H);
        Rectangle2D second = placer.place(LabelPlacer.alongLine(a, b, W, H), W, H); // the same pair's other way, or a pair on the same line
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
        LabelPlacer placer = new LabelPlacer();
        placer.take(new Rectangle2D.Double(-1000, -1000, 3000, 3000));
        assertNull(placer.place(LabelPlacer.alongLine(new Point2D.Double(0, 0), new Point2D.Double(100, 0), W, H), W, H));
        assertEquals(1, placer.taken().size());
    }
}
