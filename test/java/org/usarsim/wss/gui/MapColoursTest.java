package org.usarsim.wss.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.model.Wall;

/** Walls by material: one colour each, the plain wall colour for none, and the legend says which is which. */
class MapColoursTest {

    @Test
    void eachMaterialHasItsColourAndAWallOfNoneKeepsThePlainOne() {
        assertEquals(MapPainter.WALL, MapColours.wall(""));
        Set<Color> defaults = Stream.of("concrete", "brick", "drywall", "wood", "glass", "metal").map(MapColours::wall)
                .collect(Collectors.toSet());
        assertEquals(6, defaults.size(), "the six default materials differ");
        assertFalse(defaults.contains(MapPainter.WALL), "and differ from a wall of no material");
        assertEquals(MapColours.wall("adamantium"), MapColours.wall("adamantium"), "another material: always the same");
    }

    /** Paints a map of walls off screen: the legend has a sample of each material's colour only when a wall has one. */
    @Test
    void theLegendShowsTheMaterialsOfTheWalls() {
        List<Wall> walls = List.of(new Wall(0, 0, 10, 0, "glass"), new Wall(0, 5, 10, 5, "brick"), new Wall(0, 8, 10, 8));
        BufferedImage withMaterials = paint(walls);
        BufferedImage plain = paint(List.of(new Wall(0, 0, 10, 0), new Wall(0, 5, 10, 5)));
        for (String material : List.of("glass", "brick")) {
            Color colour = MapColours.wall(material);
            assertTrue(bottomRowsHave(withMaterials, colour), material + "'s sample in the legend");
            assertNotEquals(true, bottomRowsHave(plain, colour), "no " + material + " wall: no sample");
        }
    }

    private static BufferedImage paint(List<Wall> walls) {
        BufferedImage image = new BufferedImage(800, 500, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, 800, 500);
        MapData data = new MapData(List.of(), List.of(), walls, -93);
        // The walls high up the canvas, the legend at its bottom.
        new MapPainter(800, 500, new Font(Font.SANS_SERIF, Font.PLAIN, 12), Color.WHITE, null, null)
                .paint(g, new MapTransform(20, 100, 200), data);
        g.dispose();
        return image;
    }

    /** Whether the legend's rows (the bottom 60 pixels) have a pixel of this colour. */
    private static boolean bottomRowsHave(BufferedImage image, Color colour) {
        for (int y = image.getHeight() - 60; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                if (image.getRGB(x, y) == colour.getRGB()) {
                    return true;
                }
            }
        }
        return false;
    }
}
