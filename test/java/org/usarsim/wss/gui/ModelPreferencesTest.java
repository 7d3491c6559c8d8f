package org.usarsim.wss.gui;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.prefs.Preferences;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.LogCapture;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.model.distance.DistanceOnlyPropagationModel;
import org.usarsim.wss.model.obstacle.ObstaclePropagationModel;

class ModelPreferencesTest {

    private static final String DISTANCE = "DistanceOnlyPropagationModel";
    private static final String OBSTACLE = "ObstaclePropagationModel";
    private static final PropagationModel DISTANCE_MODEL = new DistanceOnlyPropagationModel();
    private static final PropagationModel OBSTACLE_MODEL = new ObstaclePropagationModel();

    /** A throw-away node, never the user's real preferences; removed after each test. */
    private Preferences root;
    private ModelPreferences preferences;

    private LogCapture log;
    private List<LogRecord> logged;

    @BeforeEach
    void setUp() {
        root = TestPreferences.create();
        preferences = new ModelPreferences(root);
        log = LogCapture.of(ModelPreferences.class.getName(), null);
        logged = log.records;
    }

    @AfterEach
    void tearDown() throws Exception {
        log.close();
        TestPreferences.remove(root);
    }

    @Test
    void nothingStoredGivesTheDefaults() {
        assertEquals(Setting.defaults(DISTANCE_MODEL.settings()), preferences.load(DISTANCE_MODEL));
        assertEquals(Setting.defaults(OBSTACLE_MODEL.settings()), preferences.settingValues(OBSTACLE_MODEL).asMap());
        assertEquals(28, preferences.load(OBSTACLE_MODEL).size(),
                "positions.*, usarsim.*, rosbridge.*, distance.*, obstacle.* and shadowing.* (the seed is the run's, wss.seed)");
        assertTrue(logged.isEmpty(), "no warning for missing values: " + logged);
    }

    @Test
    void storedValuesComeBack() throws Exception {
        Map<String, String> values = new LinkedHashMap<>();
        values.put("usarsim.host", "10.0.0.7");
        values.put("usarsim.port", "7000");
        values.put("positions.interval", "250");
        values.put("distance.n", "3.0007");
        values.put("distance.holdTime", "1.5");
        preferences.store(DISTANCE_MODEL, values);

        // a new instance over the same node, as at the next start
        Map<String, String> loaded = new ModelPreferences(root).load(DISTANCE_MODEL);
        Map<String, String> expected = new LinkedHashMap<>(Setting.defaults(DISTANCE_MODEL.settings()));
        expected.putAll(values);
        assertEquals(expected, loaded);
        assertEquals(3.0007, preferences.settingValues(DISTANCE_MODEL).getDouble("distance.n", -1), 0);
        assertEquals(250, preferences.settingValues(DISTANCE_MODEL).getInt("positions.interval", -1));
    }

    @Test
    void aValueStoredUnderTheOldNameOfItsKeyComesBackUnderTheNewOne() throws Exception {
        root.node(DISTANCE).put("usarsim.interval", "400"); // as a WSS before positions.interval stored it
        assertEquals("400", preferences.load(DISTANCE_MODEL).get("positions.interval"));
        assertEquals(null, preferences.load(DISTANCE_MODEL).get("usarsim.interval"));
        preferences.store(DISTANCE_MODEL, Map.of("usarsim.interval", "500"));
        assertEquals("500", root.node(DISTANCE).get("positions.interval", null), "stored under the new name");
        assertEquals("500", preferences.load(DISTANCE_MODEL).get("positions.interval"), "which wins over the old");
    }

    @Test
    void storedInTheModelsOwnNodeAndWrittenOut() throws Exception {
        preferences.store(DISTANCE_MODEL, Map.of("usarsim.port", "7001"));
        Preferences node = root.node(DISTANCE);
        assertEquals(root.absolutePath() + "/" + DISTANCE, node.absolutePath());
        assertArrayEquals(new String[] {"usarsim.port"}, node.keys());
        assertEquals("7001", node.get("usarsim.port", null));
    }

    @Test
    void eachModelHasItsOwnNode() throws Exception {
        preferences.store(DISTANCE_MODEL, Map.of("distance.cutoff", "-80"));
        preferences.store(OBSTACLE_MODEL, Map.of("distance.cutoff", "-70", "obstacle.attenuation", "3"));
        assertEquals("-80", preferences.load(DISTANCE_MODEL).get("distance.cutoff"));
        assertEquals(null, preferences.load(DISTANCE_MODEL).get("obstacle.attenuation"), "not a setting of DistanceOnly");
        assertEquals("-70", preferences.load(OBSTACLE_MODEL).get("distance.cutoff"));
        assertEquals("3", preferences.load(OBSTACLE_MODEL).get("obstacle.attenuation"));
        assertEquals(Setting.defaults(DISTANCE_MODEL.settings()), preferences.load(new MySimulatorModel("SomeOtherModel")), "another simulator model: the same settings, its own node");
    }

    @Test
    void valuesAreStoredStripped() throws Exception {
        preferences.store(DISTANCE_MODEL, Map.of("usarsim.host", "  sim.local "));
        assertEquals("sim.local", root.node(DISTANCE).get("usarsim.host", null));
    }

    @Test
    void aHandEditedBadValueGivesTheDefaultAndAWarning() {
        Preferences node = root.node(DISTANCE);
        node.put("distance.n", "zero");
        node.put("usarsim.port", "3000");
        node.put("usarsim.interval", "5");
        Map<String, String> loaded = preferences.load(DISTANCE_MODEL);
        assertEquals("1", loaded.get("distance.n"));
        assertEquals("3000", loaded.get("usarsim.port"), "a good value next to bad ones is kept");
        assertEquals("1000", loaded.get("positions.interval"), "stored under its old name, refused all the same");

        List<String> warnings = logged.stream().filter(r -> r.getLevel() == Level.WARNING).map(LogRecord::getMessage).toList();
        assertEquals(2, warnings.size(), warnings.toString());
        String n = warnings.stream().filter(m -> m.contains("distance.n")).findFirst().orElseThrow();
        assertTrue(n.contains("'zero'") && n.contains("a number above 0") && n.contains("default 1")
                && n.contains(node.absolutePath()), n);
    }

    @Test
    void unknownStoredKeysAreIgnored() {
        root.node(DISTANCE).put("distance.colour", "blue");
        assertEquals(Setting.defaults(DISTANCE_MODEL.settings()), preferences.load(DISTANCE_MODEL));
    }

    @Test
    void storeRefusesABadValueAndStoresNothing() throws Exception {
        Map<String, String> values = new LinkedHashMap<>();
        values.put("usarsim.port", "7001");
        values.put("distance.d0", "0");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> preferences.store(DISTANCE_MODEL, values));
        assertTrue(e.getMessage().contains("distance.d0") && e.getMessage().contains("above 0"), e.getMessage());
        assertEquals(0, root.node(DISTANCE).keys().length);
    }

    @Test
    void storeRefusesAKeyThatIsNotAModelSetting() throws Exception {
        assertThrows(IllegalArgumentException.class, () -> preferences.store(DISTANCE_MODEL, Map.of("wss.port", "1")));
        assertThrows(IllegalArgumentException.class, () -> preferences.store(DISTANCE_MODEL, Map.of("distance.colour", "1")));
        assertEquals(0, root.node(DISTANCE).keys().length);
    }
}
