package org.usarsim.wss.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Properties;
import org.junit.jupiter.api.Test;

/**
 * The examples in docs/examples do what their comments say, with the signal formula of the
 * models (S = pd0 - 10 n log10(d / d0) - walls * attenuation, in range while S >= cutoff) and
 * the values of their properties files.
 */
class ExampleWorldsTest {

    @Test
    void corridorScoutLeavesRangeAndComesBackWithinAMinute() throws Exception {
        World world = WorldFile.read(Path.of("docs/examples/corridor.world"));
        Properties config = properties("docs/examples/corridor.properties");
        assertEquals("DistanceOnlyPropagationModel", config.getProperty("wss.model"));
        assertEquals("7435", config.getProperty("usarsim.port"));
        assertEquals(55.6, range(config, 0), 0.05, "the range the comments state");

        Double left = null;
        Double back = null;
        for (double t = 0; t <= 80; t += 0.1) {
            boolean inRange = strength(world.at(t), "Base", "Scout", config, false) >= cutoff(config);
            if (left == null && !inRange) {
                left = t;
            } else if (left != null && back == null && inRange) {
                back = t;
            }
        }
        assertTrue(left != null && left > 20 && left < 30, "leaves range at about 27 s: " + left);
        assertTrue(back != null && back > 40 && back < 50, "back in range at about 46 s: " + back);
        assertEquals(0, world.at(36.5).obstacles("Base", "Scout"), "no wall between them");
        assertEquals(new Point(75, 0, 0.45), world.at(36.5).robot("Scout").orElseThrow().position(), "turns at 36.5 s");
        assertEquals(new Point(2, 0, 0.45), world.at(73).robot("Scout").orElseThrow().position(), "home at 73 s");
    }

    @Test
    void buildingWallsDecideWhoReachesTheOperator() throws Exception {
        World world = WorldFile.read(Path.of("docs/examples/building.world"));
        Properties config = properties("docs/examples/building.properties");
        assertEquals("ObstaclePropagationModel", config.getProperty("wss.model"));
        assertEquals(13.0, range(config, 3), 0.05, "the 3-wall range the comments state");

        Snapshot inCorridor = world.at(21.5);
        assertEquals(new Point(24.5, 2, 0.45), inCorridor.robot("Explorer").orElseThrow().position());
        assertEquals(0, inCorridor.obstacles("Operator", "Explorer"));
        assertTrue(strength(inCorridor, "Operator", "Explorer", config, true) >= cutoff(config), "in range in the corridor");

        Snapshot inRoomC = world.at(30.5);
        assertEquals(new Point(24.5, 11, 0.45), inRoomC.robot("Explorer").orElseThrow().position());
        assertEquals(3, inRoomC.obstacles("Operator", "Explorer"));
        assertTrue(strength(inRoomC, "Operator", "Explorer", config, true) < cutoff(config), "out of range in room C");
        assertEquals(new Point(3, 2, 0.45), world.at(61).robot("Explorer").orElseThrow().position(), "a lap of 61 s");

        assertEquals(new Point(14.5, 9, 0.45), world.at(48).robot("Mapper").orElseThrow().position(), "Mapper in room B at 48 s");
        assertEquals(new Point(14.5, 9, 0.45), world.at(500).robot("Mapper").orElseThrow().position(), "and stays there");

        assertFalse(world.at(59.9).robot("Scout").orElseThrow().batteryEmpty());
        assertTrue(world.at(60).robot("Scout").orElseThrow().batteryEmpty(), "Scout's battery is empty after a minute");
        for (double t = 0; t < 60; t += 0.5) {
            assertTrue(strength(world.at(t), "Operator", "Scout", config, true) >= cutoff(config), "Scout in range until then, t=" + t);
        }
    }

    private static Properties properties(String file) throws IOException {
        Properties properties = new Properties();
        try (Reader reader = Files.newBufferedReader(Path.of(file), StandardCharsets.UTF_8)) {
            properties.load(reader);
        }
        return properties;
    }

    private static double value(Properties config, String key) {
        return Double.parseDouble(config.getProperty(key));
    }

    private static double cutoff(Properties config) {
        return value(config, "distance.cutoff");
    }

    private static double range(Properties config, int walls) {
        double loss = walls == 0 ? 0 : walls * value(config, "obstacle.attenuation");
        return value(config, "distance.d0")
                * Math.pow(10, (value(config, "distance.pd0") - cutoff(config) - loss) / (10 * value(config, "distance.n")));
    }

    private static double strength(Snapshot world, String a, String b, Properties config, boolean walls) {
        double d = world.robot(a).orElseThrow().position().distanceTo(world.robot(b).orElseThrow().position());
        double s = value(config, "distance.pd0") - 10 * value(config, "distance.n") * Math.log10(d / value(config, "distance.d0"));
        return walls ? s - world.obstacles(a, b) * value(config, "obstacle.attenuation") : s;
    }
}
