package org.usarsim.wss.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.geom.Point2D;
import java.awt.geom.Rectangle2D;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.hub.core.PairState;

/** The map's transform (fit, zoom, pan) and its colouring rule: pure functions, no window. */
class MapTransformTest {

    private static void assertPoint(double x, double y, Point2D actual) {
        assertEquals(x, actual.getX(), 1e-9, "x of " + actual);
        assertEquals(y, actual.getY(), 1e-9, "y of " + actual);
    }

    @Test
    void fittingCentresTheWorldWithOneScaleAndYUp() {
        // 80 m x 20 m in 840 x 440 px less 20 px a side: 800 / 80 = 10 px/m (400 / 20 = 20 would not fit the width).
        MapTransform t = MapTransform.fit(new Rectangle2D.Double(-10, 0, 80, 20), 840, 440, 20);
        assertEquals(10, t.scale(), 1e-9);
        assertPoint(20, 120, t.toScreen(-10, 20)); // top left
        assertPoint(820, 320, t.toScreen(70, 0)); // bottom right
        assertPoint(420, 220, t.toScreen(30, 10)); // the centre at the centre
        assertPoint(30, 10, t.toWorld(420, 220));
    }

    @Test
    void aSinglePointIsShownWithTheLeastSpanAroundIt() {
        MapTransform t = MapTransform.fit(new Rectangle2D.Double(5, 5, 0, 0), 100, 100, 0);
        assertEquals(100 / MapTransform.LEAST_SPAN, t.scale(), 1e-9);
        assertPoint(50, 50, t.toScreen(5, 5));
    }

    @Test
    void zoomKeepsThePointUnderTheMouseAndPanMovesByThePixelsDragged() {
        MapTransform t = new MapTransform(10, 100, 200);
        Point2D under = t.toWorld(150, 80);
        MapTransform zoomed = t.zoom(2.5, 150, 80);
        assertEquals(25, zoomed.scale(), 1e-9);
        assertPoint(150, 80, zoomed.toScreen(under.getX(), under.getY()));
        MapTransform panned = zoomed.pan(30, -12);
        assertPoint(180, 68, panned.toScreen(under.getX(), under.getY()));
        assertEquals(MapTransform.MAX_SCALE, t.zoom(1e9, 0, 0).scale(), "the wheel stops at the largest scale");
        assertEquals(MapTransform.MIN_SCALE, t.zoom(1e-9, 0, 0).scale(), "and at the smallest");
    }

    @Test
    void theGridStepIsARoundNumberOfMetres() {
        assertEquals(10, MapPainter.gridStep(10), 1e-9); // 60 px / 10 px a metre = 6 m: 10 m
        assertEquals(2, MapPainter.gridStep(40), 1e-9); // 1.5 m: 2 m
        assertEquals(0.5, MapPainter.gridStep(200), 1e-9); // 0.3 m: 0.5 m
    }

    @Test
    void greenWhenStrongAmberNearTheCutoffGreyWhenBrokenOrForcedDown() {
        double cutoff = -93;
        assertEquals(MapColours.STRONG, MapColours.of(line(PairState.UP, -70), cutoff));
        assertEquals(MapColours.STRONG, MapColours.of(line(PairState.UP, -90), cutoff), "exactly NEAR_DB above: strong");
        assertEquals(MapColours.NEAR, MapColours.of(line(PairState.UP, -90.5), cutoff));
        assertEquals(MapColours.NEAR, MapColours.of(line(PairState.FORCED_UP, -100), cutoff), "forced up below the cutoff");
        assertEquals(MapColours.BROKEN, MapColours.of(line(PairState.BROKEN, -70), cutoff));
        assertEquals(MapColours.BROKEN, MapColours.of(line(PairState.FORCED_DOWN, -50), cutoff));
        assertEquals(MapColours.STRONG, MapColours.of(line(PairState.UP, Double.NaN), cutoff), "no strength: up is all we know");
        assertEquals(MapColours.STRONG, MapColours.of(line(PairState.UP, -92), Double.NaN), "no cutoff to compare");
        assertEquals(List.of(false, true, true), List.of(line(PairState.BROKEN, 0).forced(), line(PairState.FORCED_UP, 0).forced(),
                line(PairState.FORCED_DOWN, 0).forced()), "dashed when forced");
    }

    private static MapData.Line line(PairState state, double strength) {
        return new MapData.Line("A", "B", state, strength, 0);
    }
}
