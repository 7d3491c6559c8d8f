package org.usarsim.wss.model.obstacle;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.Reader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.model.simulator.PathLoss;
import org.usarsim.wss.model.simulator.ReportedRobot;
import org.usarsim.wss.world.WorldWalls;

/** docs/examples/rooms.sdf with rooms.properties does what their comments say. */
class RoomsExampleTest {

    private static Map<String, String> settings() throws Exception {
        Properties properties = new Properties();
        try (Reader in = Files.newBufferedReader(Path.of("docs/examples/rooms.properties"))) {
            properties.load(in);
        }
        Map<String, String> values = new HashMap<>();
        properties.stringPropertyNames().stream().filter(key -> !key.startsWith("wss.")).forEach(key -> values.put(key,
                properties.getProperty(key)));
        return values;
    }

    @Test
    void theRoomsAreNineWallsOfConcreteAndGlassAndTheRestIsSkippedWithALineEach() throws Exception {
        ObstaclePropagationModel model = new ObstaclePropagationModel();
        ModelSettings settings = new ModelSettings(Setting.checked(model.settings(), settings()));
        WorldWalls walls = WallSettings.of(settings).walls(Path.of(settings.getString("obstacle.walls", "")));
        assertEquals(9, walls.count(), "5 concrete walls, 4 boxes of glass");
        assertEquals(List.of("concrete", "glass"), walls.materials());
        assertEquals(36, walls.walls().size(), "the map draws each box's 4 edges");
        assertEquals(List.of(
                "skipped 2 <include> of a model by URI (not followed): model://ground_plane, model://sun",
                "skipped 1 box(es) outside the height band 0.1..2.0 m: floor_slab::link::collision",
                "skipped 1 mesh collision(s) (only boxes are walls): desk::link::collision"), walls.notes());
    }

    @Test
    void explorerAtRoomBsFarCornerLosesGlassAndConcreteToOperatorAndConcreteToMapper() throws Exception {
        ObstaclePropagationModel model = new ObstaclePropagationModel();
        model.started(new ModelSettings(Setting.checked(model.settings(), settings())));
        ReportedRobot operator = new ReportedRobot("Operator", 2, 2.5, 0.45, false);
        ReportedRobot mapper = new ReportedRobot("Mapper", 5, 8, 0.45, false);
        ReportedRobot explorer = new ReportedRobot("Explorer", 18, 8.5, 0.45, false);
        List<RobotPair> pairs = List.of(RobotPair.of("Operator", "Mapper"), RobotPair.of("Operator", "Explorer"),
                RobotPair.of("Mapper", "Explorer"));
        Map<RobotPair, Double> counts = model.obstacleCounts(Map.of("Operator", operator, "Mapper", mapper, "Explorer", explorer),
                pairs, null);
        assertEquals(Map.of(pairs.get(0), 1.0, pairs.get(1), 2.0, pairs.get(2), 1.0), counts);
        // The path loss before a run's configuration (the declared defaults; started() does not set it): the walls' loss is apart.
        PathLoss open = new PathLoss(-49.67, 1, 2, -93);
        assertEquals(2, open.strength(operator.distanceTo(mapper)) - model.strength(operator, mapper, 1), 1e-9, "a glass front");
        assertEquals(17, open.strength(operator.distanceTo(explorer)) - model.strength(operator, explorer, 2), 1e-9,
                "a glass front and the concrete wall between the rooms");
        assertEquals(15, open.strength(mapper.distanceTo(explorer)) - model.strength(mapper, explorer, 1), 1e-9,
                "the concrete wall between the rooms");
    }
}
