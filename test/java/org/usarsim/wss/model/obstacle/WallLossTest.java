package org.usarsim.wss.model.obstacle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.model.ModelInputException;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.model.simulator.PathLoss;
import org.usarsim.wss.model.simulator.ReportedRobot;
import org.usarsim.wss.protocol.Replies;
import org.usarsim.wss.world.WorldWalls;

/**
 * The Obstacle model's wall-loss term on the walls of obstacle.walls, without a simulator: its
 * strengths through {@code obstacleCounts} and {@code strength}, as a poll computes them.
 */
class WallLossTest {

    /** The declared defaults' path loss: the model's before its first run's configuration. */
    private static final PathLoss DEFAULT = new PathLoss(-49.67, 1, 2, -93);
    private static final double ATTENUATION = 6.325;
    /** The robots' spacing: some stand on walls. */
    private static final double STEP = 3.1;

    private static ObstaclePropagationModel started(Map<String, String> given) throws ModelStartException {
        ObstaclePropagationModel model = new ObstaclePropagationModel();
        model.started(new ModelSettings(Setting.checked(model.settings(), given)));
        return model;
    }

    /** Robots on a grid over the world, every STEP metres (so some stand on walls), and every pair's strength as a poll gives it. */
    private static Map<RobotPair, Double> strengths(ObstaclePropagationModel model, double x0, double y0, double x1, double y1)
            throws Exception {
        Map<String, ReportedRobot> listed = new HashMap<>();
        for (double x = x0; x <= x1; x += STEP) {
            for (double y = y0; y <= y1; y += STEP) {
                String name = "R" + listed.size();
                listed.put(name, new ReportedRobot(name, x, y, 0.45, false));
            }
        }
        List<RobotPair> pairs = new ArrayList<>();
        List<String> names = new ArrayList<>(listed.keySet());
        for (int i = 0; i < names.size(); i++) {
            for (int j = i + 1; j < names.size(); j++) {
                pairs.add(RobotPair.of(names.get(i), names.get(j)));
            }
        }
        Map<RobotPair, Double> counts = model.obstacleCounts(listed, pairs, null);
        Map<RobotPair, Double> strengths = new HashMap<>();
        for (RobotPair pair : pairs) {
            strengths.put(pair, model.strength(listed.get(pair.first()), listed.get(pair.second()), counts.get(pair)));
        }
        return strengths;
    }

    /** Today's answer: the DistanceOnly strength less the count of walls times the attenuation. */
    private static double today(WorldWalls walls, ReportedRobot a, ReportedRobot b) {
        return DEFAULT.strength(a.distanceTo(b)) - walls.crossings(a.x(), a.y(), b.x(), b.y()) * ATTENUATION;
    }

    private static void assertAsToday(Path world, Map<String, String> settings, double x1, double y1) throws Exception {
        ObstaclePropagationModel model = started(settings);
        WorldWalls walls = WorldWalls.read(world);
        Map<RobotPair, Double> strengths = strengths(model, -3, -3, x1, y1);
        int behindWalls = 0;
        // Recompute the positions as strengths() laid them out and compare every pair, bit for bit and as GETSS writes it.
        List<ReportedRobot> robots = new ArrayList<>();
        for (double x = -3; x <= x1; x += STEP) {
            for (double y = -3; y <= y1; y += STEP) {
                robots.add(new ReportedRobot("R" + robots.size(), x, y, 0.45, false));
            }
        }
        for (int i = 0; i < robots.size(); i++) {
            for (int j = i + 1; j < robots.size(); j++) {
                ReportedRobot a = robots.get(i);
                ReportedRobot b = robots.get(j);
                double expected = today(walls, a, b);
                double actual = strengths.get(RobotPair.of(a.name(), b.name()));
                assertEquals(Double.doubleToLongBits(expected), Double.doubleToLongBits(actual), a + " " + b);
                if ((i + j) % 5 == 0) {
                    assertEquals(Replies.signal(b.name(), expected), Replies.signal(b.name(), actual));
                }
                behindWalls += walls.crossings(a.x(), a.y(), b.x(), b.y()) > 0 ? 1 : 0;
            }
        }
        assertEquals(true, behindWalls > 50, behindWalls + " pairs behind walls");
    }

    @Test
    void theExampleWorldsAnswerExactlyAsTodayWithTheDefaultSettings() throws Exception {
        Path building = Path.of("docs/examples/building.world");
        assertAsToday(building, Map.of("obstacle.walls", building.toString()), 32, 16);
        Path corridor = Path.of("docs/examples/corridor.world");
        assertAsToday(corridor, Map.of("obstacle.walls", corridor.toString()), 30, 3);
    }

    @Test
    void oneMaterialLosingTheAttenuationAnswersExactlyAsToday(@TempDir Path dir) throws Exception {
        Path building = Path.of("docs/examples/building.world");
        List<String> lines = Files.readAllLines(building).stream()
                .map(line -> line.startsWith("wall ") ? line.replaceAll("\\s*(#.*)?$", "") + " concrete" : line).toList();
        Path concrete = Files.write(dir.resolve("concrete.world"), lines);
        assertEquals(List.of("concrete"), WorldWalls.read(concrete).materials());
        assertAsToday(building, Map.of("obstacle.walls", concrete.toString(), "obstacle.loss", "concrete:6.325"), 32, 16);
    }

    @Test
    void theLossesOfTheWallsCrossedAreSummedByMaterial(@TempDir Path dir) throws Exception {
        Path world = Files.writeString(dir.resolve("w.world"),
                "wall 2,-5 2,5 concrete\nwall 4,-5 4,5 glass\nwall 6,-5 6,5 glass\nwall 8,-5 8,5\nwall 9,-5 9,5 Metal\n");
        ObstaclePropagationModel model = started(Map.of("obstacle.walls", world.toString()));
        ReportedRobot a = new ReportedRobot("A", 0, 0, 0, false);
        ReportedRobot b = new ReportedRobot("B", 10, 0, 0, false);
        ReportedRobot c = new ReportedRobot("C", 5, 0, 0, false);
        List<RobotPair> pairs = List.of(RobotPair.of("A", "B"), RobotPair.of("A", "C"), RobotPair.of("B", "C"));
        Map<RobotPair, Double> counts = model.obstacleCounts(Map.of("A", a, "B", b, "C", c), pairs, null);
        assertEquals(Map.of(pairs.get(0), 5.0, pairs.get(1), 2.0, pairs.get(2), 3.0), counts, "the counts stay counts");
        assertEquals(DEFAULT.strength(10) - (15 + 2 * 2 + ATTENUATION + 30), model.strength(a, b, 5), 1e-9,
                "concrete 15, glass 2 twice, a wall of no material the attenuation, metal 30");
        assertEquals(DEFAULT.strength(5) - 17, model.strength(a, c, 2), 1e-9);
        assertEquals(DEFAULT.strength(5) - 2 - ATTENUATION - 30, model.strength(b, c, 3), 1e-9);
        ObstaclePropagationModel cheap = started(Map.of("obstacle.walls", world.toString(),
                "obstacle.loss", "concrete:1, glass:0.5, metal:3", "obstacle.attenuation", "2"));
        cheap.obstacleCounts(Map.of("A", a, "B", b, "C", c), pairs, null);
        assertEquals(DEFAULT.strength(10) - 7, cheap.strength(a, b, 5), 1e-9);
    }

    /** The walls the map draws and a recording keeps (the model's own) carry their materials. */
    @Test
    void theModelsWallsCarryTheirMaterials(@TempDir Path dir) throws Exception {
        Path world = Files.writeString(dir.resolve("w.world"), "wall 2,-5 2,5 concrete\nwall 4,-5 4,5\n");
        ObstaclePropagationModel model = started(Map.of("obstacle.walls", world.toString()));
        assertEquals(List.of(new org.usarsim.wss.model.Wall(2, -5, 2, 5, "concrete"), new org.usarsim.wss.model.Wall(4, -5, 4, 5)),
                model.ownWalls());
    }

    @Test
    void aMaterialWithNoLossAndBadSettingsRefuseTheStart(@TempDir Path dir) throws Exception {
        Path world = Files.writeString(dir.resolve("w.world"), "wall 2,-5 2,5 adamantium\n");
        ModelInputException e = assertThrows(ModelInputException.class, () -> started(Map.of("obstacle.walls", world.toString())));
        assertEquals("obstacle.walls: " + world + " has walls of adamantium, which has no loss in obstacle.loss", e.getMessage());
        Path plain = Files.writeString(dir.resolve("p.world"), "wall 2,-5 2,5\n");
        Map<String, String> bad = Map.of(
                "obstacle.loss", "obstacle.loss: 'concrete=15' is not MATERIAL:DB (a material is letters, digits, _ and -;"
                        + " the loss a number of 0 dB or more)",
                "obstacle.materials", "obstacle.materials: 'Hard_wall*' is not GLOB=MATERIAL (a material is letters, digits, _ and -)",
                "obstacle.heightBand", "obstacle.heightBand: '2..1' is not LOW..HIGH in metres, LOW at most HIGH");
        Map<String, String> values = Map.of("obstacle.loss", "concrete=15", "obstacle.materials", "Hard_wall*",
                "obstacle.heightBand", "2..1");
        for (String key : bad.keySet()) {
            e = assertThrows(ModelInputException.class,
                    () -> started(Map.of("obstacle.walls", plain.toString(), key, values.get(key))), key);
            assertEquals(bad.get(key), e.getMessage());
        }
    }

    @Test
    void theSourcesCountsStillLoseTheAttenuationEach() throws Exception {
        ObstaclePropagationModel model = started(Map.of());
        ReportedRobot a = new ReportedRobot("A", 0, 0, 0, false);
        ReportedRobot b = new ReportedRobot("B", 30, 40, 0, false);
        assertEquals(DEFAULT.strength(50) - 3 * ATTENUATION, model.strength(a, b, 3));
        assertEquals(Double.NaN, model.strength(a, b, Double.NaN));
    }
}
