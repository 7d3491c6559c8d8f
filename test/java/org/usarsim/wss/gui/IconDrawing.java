package org.usarsim.wss.gui;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.GradientPaint;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Arc2D;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.awt.geom.RoundRectangle2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;

/**
 * Draws the WSS's icon, a radio mast between two robots, as {@code wss-48.png} and
 * {@code wss-256.png} (the committed ones in src/main/resources/org/usarsim/wss/gui were made so):
 *
 * <pre>
 * mvn -B -q test-compile
 * java -Djava.awt.headless=true -cp target/classes:target/test-classes org.usarsim.wss.gui.IconDrawing \
 *     src/main/resources/org/usarsim/wss/gui
 * </pre>
 *
 * Drawn on a 256-unit square and scaled, so both sizes are the same picture.
 */
public final class IconDrawing {

    private static final Color BACKGROUND_TOP = new Color(38, 70, 120);
    private static final Color BACKGROUND_BOTTOM = new Color(20, 36, 66);
    private static final Color MAST = new Color(230, 232, 236);
    private static final Color WAVES = new Color(120, 220, 120);
    private static final Color ROBOT = new Color(245, 170, 40);
    private static final Color ROBOT_DARK = new Color(60, 60, 66);

    private IconDrawing() {
    }

    public static void main(String[] args) throws IOException {
        Path folder = Path.of(args.length > 0 ? args[0] : ".");
        Files.createDirectories(folder);
        for (int size : Icons.SIZES) {
            Path file = folder.resolve("wss-" + size + ".png");
            ImageIO.write(draw(size), "png", file.toFile());
            System.out.println(file);
        }
    }

    /** The icon, {@code size} pixels square, with a transparent margin around its rounded square. */
    static BufferedImage draw(int size) {
        BufferedImage image = new BufferedImage(size, size, BufferedImage.TYPE_INT_ARGB);
        Graphics2D g = image.createGraphics();
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE);
            g.setRenderingHint(RenderingHints.KEY_RENDERING, RenderingHints.VALUE_RENDER_QUALITY);
            g.scale(size / 256.0, size / 256.0);
            background(g);
            waves(g);
            mast(g);
            robot(g, 52, false);
            robot(g, 204, true);
        } finally {
            g.dispose();
        }
        return image;
    }

    private static void background(Graphics2D g) {
        g.setPaint(new GradientPaint(0, 8, BACKGROUND_TOP, 0, 248, BACKGROUND_BOTTOM));
        g.fill(new RoundRectangle2D.Double(8, 8, 240, 240, 48, 48));
        g.setPaint(new Color(90, 140, 90));
        g.fill(new RoundRectangle2D.Double(8, 206, 240, 42, 48, 48));
        g.fillRect(8, 206, 240, 14);
    }

    /** Two arcs each side of the mast's top. */
    private static void waves(Graphics2D g) {
        g.setColor(WAVES);
        g.setStroke(new BasicStroke(9, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        for (int r : new int[] {30, 54}) {
            g.draw(new Arc2D.Double(128 - r, 52 - r, 2 * r, 2 * r, -40, 80, Arc2D.OPEN));
            g.draw(new Arc2D.Double(128 - r, 52 - r, 2 * r, 2 * r, 140, 80, Arc2D.OPEN));
        }
    }

    /** A lattice mast from the ground to its antenna ball. */
    private static void mast(Graphics2D g) {
        g.setColor(MAST);
        g.setStroke(new BasicStroke(7, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        double top = 62;
        double bottom = 212;
        g.draw(new Line2D.Double(128, top, 104, bottom));
        g.draw(new Line2D.Double(128, top, 152, bottom));
        g.setStroke(new BasicStroke(4.5f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        double[] levels = {100, 140, 180, 212};
        double previousLeft = 128;
        double previousRight = 128;
        double previousY = top;
        for (double y : levels) {
            double half = 24 * (y - top) / (bottom - top);
            g.draw(new Line2D.Double(128 - half, y, 128 + half, y));
            g.draw(new Line2D.Double(previousLeft, previousY, 128 + half, y));
            g.draw(new Line2D.Double(previousRight, previousY, 128 - half, y));
            previousLeft = 128 - half;
            previousRight = 128 + half;
            previousY = y;
        }
        g.fill(new Ellipse2D.Double(128 - 11, 52 - 11, 22, 22));
    }

    /** A tracked robot centred on {@code x}, its head and antenna turned to the mast. */
    private static void robot(Graphics2D g, double x, boolean facingLeft) {
        double toMast = facingLeft ? -1 : 1;
        // tracks
        g.setColor(ROBOT_DARK);
        g.fill(new RoundRectangle2D.Double(x - 34, 190, 68, 24, 24, 24));
        g.setColor(new Color(150, 150, 156));
        for (int i = -1; i <= 1; i++) {
            g.fill(new Ellipse2D.Double(x + i * 20 - 6, 196, 12, 12));
        }
        // body
        g.setColor(ROBOT);
        g.fill(new RoundRectangle2D.Double(x - 28, 150, 56, 44, 12, 12));
        // neck and head
        g.setColor(ROBOT_DARK);
        g.fill(new RoundRectangle2D.Double(x - 4, 134, 8, 20, 4, 4));
        g.setColor(ROBOT);
        g.fill(new RoundRectangle2D.Double(x - 22, 112, 44, 28, 10, 10));
        // eye (a camera) towards the mast
        g.setColor(ROBOT_DARK);
        g.fill(new Ellipse2D.Double(x + toMast * 8 - 7, 119, 14, 14));
        g.setColor(new Color(140, 210, 255));
        g.fill(new Ellipse2D.Double(x + toMast * 8 - 3.5, 122.5, 7, 7));
        // antenna
        g.setColor(MAST);
        g.setStroke(new BasicStroke(4, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        Path2D antenna = new Path2D.Double();
        antenna.moveTo(x - toMast * 14, 112);
        antenna.lineTo(x - toMast * 14, 90);
        g.draw(antenna);
        g.fill(new Ellipse2D.Double(x - toMast * 14 - 5, 84, 10, 10));
    }
}
