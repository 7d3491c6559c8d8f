package org.usarsim.wss.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The walls of a Gazebo world: boxes placed by their poses, the rest skipped and named, the parser hardened. */
class SdfWallsTest {

    private static final MaterialRules WCS = MaterialRules.parse(
            "Hard_wall*=concrete, Medium_wall*=brick, Soft_wall*=drywall, *glass*=glass, *=concrete");

    private static SdfWalls.Result parse(String xml) throws WorldFileException {
        return SdfWalls.parse(xml.getBytes(StandardCharsets.UTF_8), "test.sdf", WCS, 0.1, 2.0);
    }

    private static String world(String models) {
        return "<?xml version=\"1.0\"?>\n<sdf version=\"1.6\"><world name=\"w\">" + models + "</world></sdf>";
    }

    private static String boxModel(String name, String modelPose, String linkPose, String collisionPose, String size) {
        return "<model name=\"" + name + "\"><static>true</static><pose>" + modelPose + "</pose>"
                + "<link name=\"link\"><pose>" + linkPose + "</pose>"
                + "<visual name=\"v\"><geometry><box><size>99 99 99</size></box></geometry></visual>"
                + "<collision name=\"c\"><pose>" + collisionPose + "</pose><geometry><box><size>" + size
                + "</size></box></geometry></collision></link></model>";
    }

    private static void assertCorners(BoxWall box, double[][] expected) {
        List<Wall> edges = box.edges();
        assertEquals(expected.length, edges.size(), box.toString());
        for (double[] corner : expected) {
            assertTrue(edges.stream().anyMatch(e -> Math.abs(e.x1() - corner[0]) < 1e-9 && Math.abs(e.y1() - corner[1]) < 1e-9),
                    "a corner at " + corner[0] + "," + corner[1] + " in " + box);
        }
    }

    @Test
    void aBoxIsARectangleAtItsModelLinkAndCollisionPosesComposed() throws Exception {
        // Model at (10, 0) turned 90 degrees; link 2 m along the model's x (so +y in the world); collision 1 m up.
        SdfWalls.Result r = parse(world(boxModel("Hard_wall_1", "10 0 0 0 0 1.5707963267948966", "2 0 0 0 0 0", "0 0 1 0 0 0",
                "4 0.2 2")));
        assertEquals(1, r.boxes().size());
        BoxWall box = r.boxes().get(0);
        assertEquals("Hard_wall_1::link::c", box.name());
        assertEquals("concrete", box.material());
        // Its 4 m length along the model's x is the world's y, centred at (10, 2).
        assertCorners(box, new double[][] {{9.9, 0}, {10.1, 0}, {10.1, 4}, {9.9, 4}});
        assertEquals(List.of(), r.notes());
    }

    @Test
    void aLineCrossingABoxCountsOneWallNotTwoEdges() throws Exception {
        WorldWalls walls = WorldWalls.of(List.of(), parse(world(boxModel("Medium_wall", "5 0 0 0 0 0", "0 0 0 0 0 0",
                "0 0 1 0 0 0", "0.3 10 2"))).boxes());
        assertEquals(1, walls.crossings(0, 0, 10, 0), "through both long sides");
        assertEquals(1, walls.crossings(0, 0, 5, 0), "ending inside it");
        assertEquals(1, walls.crossings(4.9, 0, 5.1, 1), "wholly inside it");
        assertEquals(0, walls.crossings(0, 6, 10, 6), "past its end");
        assertEquals(List.of("brick"), walls.materials());
        assertEquals(4, walls.walls().size(), "the map draws its four edges");
        assertEquals("brick", walls.walls().get(0).material());
    }

    @Test
    void nestedModelsComposeTheirPosesAndTheRulesMatchAnyLevelsName() throws Exception {
        String inner = boxModel("pane", "0 3 0 0 0 0", "0 0 0 0 0 0", "0 0 1 0 0 0", "2 0.1 2");
        SdfWalls.Result r = parse(world("<model name=\"window_glass\"><pose>1 1 0 0 0 0</pose>" + inner + "</model>"));
        BoxWall box = r.boxes().get(0);
        assertEquals("window_glass::pane::link::c", box.name());
        assertEquals("glass", box.material());
        assertCorners(box, new double[][] {{0, 3.95}, {2, 3.95}, {2, 4.05}, {0, 4.05}});
    }

    @Test
    void rollAndPitchTiltTheBoxItsOutlineIsItsShadowAndItsHeightDecides() throws Exception {
        // A 2 x 2 x 0.1 plate lying on the floor is below the band; stood up by a roll of 90 degrees it is a wall.
        SdfWalls.Result lying = parse(world(boxModel("Soft_wall", "0 0 0.04 0 0 0", "0 0 0 0 0 0", "0 0 0 0 0 0", "2 2 0.1")));
        assertEquals(0, lying.boxes().size());
        assertEquals(List.of("skipped 1 box(es) outside the height band 0.1..2.0 m: Soft_wall::link::c"), lying.notes());
        SdfWalls.Result standing = parse(world(boxModel("Soft_wall", "0 0 1 1.5707963267948966 0 0", "0 0 0 0 0 0",
                "0 0 0 0 0 0", "2 2 0.1")));
        assertEquals("drywall", standing.boxes().get(0).material());
        assertCorners(standing.boxes().get(0), new double[][] {{-1, -0.05}, {1, -0.05}, {1, 0.05}, {-1, 0.05}});
        SdfWalls.Result degrees = parse(world(boxModel("Soft_wall", "0 0 1 90 0 0\" degrees=\"true", "0 0 0 0 0 0",
                "0 0 0 0 0 0", "2 2 0.1").replace("<pose>0 0 1 90 0 0\" degrees=\"true</pose>",
                "<pose degrees=\"true\">0 0 1 90 0 0</pose>")));
        assertCorners(degrees.boxes().get(0), new double[][] {{-1, -0.05}, {1, -0.05}, {1, 0.05}, {-1, 0.05}});
    }

    @Test
    void otherShapesAndIncludesAreSkippedOneLineEachKindNamed() throws Exception {
        String shapes = "<model name=\"stuff\"><link name=\"l\">"
                + "<collision name=\"m1\"><geometry><mesh><uri>model://x/a.dae</uri></mesh></geometry></collision>"
                + "<collision name=\"m2\"><geometry><mesh><uri>model://x/b.dae</uri></mesh></geometry></collision>"
                + "<collision name=\"cyl\"><geometry><cylinder><radius>1</radius><length>2</length></cylinder></geometry></collision>"
                + "<collision name=\"ball\"><geometry><sphere><radius>1</radius></sphere></geometry></collision>"
                + "<collision name=\"floor\"><geometry><plane><normal>0 0 1</normal></plane></geometry></collision>"
                + "</link></model><include><uri>model://ground_plane</uri></include>";
        SdfWalls.Result r = parse(world(shapes));
        assertEquals(List.of(), r.boxes());
        assertEquals(List.of(
                "skipped 2 mesh collision(s) (only boxes are walls): stuff::l::m1, stuff::l::m2",
                "skipped 1 cylinder collision(s) (only boxes are walls): stuff::l::cyl",
                "skipped 1 sphere collision(s) (only boxes are walls): stuff::l::ball",
                "skipped 1 plane collision(s) (only boxes are walls): stuff::l::floor",
                "skipped 1 <include> of a model by URI (not followed): model://ground_plane"), r.notes());
    }

    @Test
    void relativeToIsNotFollowedAndSaysSo() throws Exception {
        SdfWalls.Result r = parse(world(boxModel("w", "1 0 0 0 0 0", "0 0 0 0 0 0", "0 0 1 0 0 0", "1 1 1")
                .replace("<pose>1 0 0", "<pose relative_to=\"other\">1 0 0")));
        assertEquals(1, r.boxes().size());
        assertEquals(List.of("1 pose(s) with relative_to (taken relative to the parent instead), not supported: w relative_to other"),
                r.notes());
    }

    @Test
    void aBadPoseOrSizeNamesTheCollision() {
        WorldFileException e = assertThrows(WorldFileException.class,
                () -> parse(world(boxModel("w", "1 0 0", "0 0 0 0 0 0", "0 0 0 0 0 0", "1 1 1"))));
        assertTrue(e.getMessage().startsWith("test.sdf: w: a pose is 'x y z roll pitch yaw'"), e.getMessage());
        e = assertThrows(WorldFileException.class,
                () -> parse(world(boxModel("w", "0 0 0 0 0 0", "0 0 0 0 0 0", "0 0 0 0 0 0", "1 -1 1"))));
        assertEquals("test.sdf: w::link::c: a box's size is three numbers of 0 or more, not '1 -1 1'", e.getMessage());
    }

    @Test
    void anExternalEntityIsRefusedBeforeAnythingIsRead(@TempDir Path dir) throws Exception {
        Path secret = Files.writeString(dir.resolve("secret.txt"), "Hard_wall_secret");
        String xxe = "<?xml version=\"1.0\"?>\n<!DOCTYPE sdf [<!ENTITY x SYSTEM \"" + secret.toUri() + "\">]>\n"
                + world("<model name=\"&x;\"/>").substring(world("").indexOf("<sdf"));
        WorldFileException e = assertThrows(WorldFileException.class, () -> parse(xxe));
        assertEquals("test.sdf: a DOCTYPE is refused (SDF needs none; entities and DTDs are never read): line 2", e.getMessage());
    }

    @Test
    void aBillionLaughsIsRefusedAtOnce() {
        StringBuilder laughs = new StringBuilder("<?xml version=\"1.0\"?>\n<!DOCTYPE lolz [<!ENTITY lol \"lol\">");
        for (int i = 1; i <= 9; i++) {
            laughs.append("<!ENTITY lol").append(i).append(" \"").append(("&lol" + (i == 1 ? "" : i - 1) + ";").repeat(10)).append("\">");
        }
        laughs.append("]>\n<sdf><world><model name=\"&lol9;\"/></world></sdf>");
        WorldFileException e = assertThrows(WorldFileException.class, () -> parse(laughs.toString()));
        assertTrue(e.getMessage().startsWith("test.sdf: a DOCTYPE is refused"), e.getMessage());
    }

    @Test
    void thePredefinedEntitiesStillWork() throws Exception {
        SdfWalls.Result r = parse(world(boxModel("Hard_wall &amp; glass", "0 0 0 0 0 0", "0 0 0 0 0 0", "0 0 1 0 0 0", "1 1 1")));
        assertEquals("Hard_wall & glass::link::c", r.boxes().get(0).name());
    }

    @Test
    void notXmlNotSdfAndTooLargeAreRefused(@TempDir Path dir) throws Exception {
        WorldFileException e = assertThrows(WorldFileException.class, () -> parse("<sdf><world></sdf>"));
        assertTrue(e.getMessage().startsWith("test.sdf:1: not well-formed XML: "), e.getMessage());
        e = assertThrows(WorldFileException.class, () -> parse("<html/>"));
        assertEquals("test.sdf: not an SDF document: its root is <html>, not <sdf>", e.getMessage());
        Path huge = dir.resolve("huge.sdf");
        try (var file = new java.io.RandomAccessFile(huge.toFile(), "rw")) {
            file.setLength(WorldWalls.MAX_BYTES + 1); // sparse: nothing written
        }
        e = assertThrows(WorldFileException.class, () -> WorldWalls.read(huge, WCS, 0.1, 2));
        assertEquals(huge + ": larger than 64 MiB", e.getMessage());
    }

    @Test
    void aFileIsReadAsSdfWhenItStartsWithAnAngleBracketElseAsAWorldFile(@TempDir Path dir) throws Exception {
        Path sdf = Files.writeString(dir.resolve("gazebo.world"), "\n  " + world(boxModel("Hard_wall", "0 0 0 0 0 0",
                "0 0 0 0 0 0", "0 0 1 0 0 0", "1 1 1")));
        assertEquals(List.of("concrete"), WorldWalls.read(sdf, WCS, 0.1, 2).materials());
        Path plain = Files.writeString(dir.resolve("plain.world"), "wall 0,0 1,0\nwall 0,1 1,1 glass\n");
        WorldWalls walls = WorldWalls.read(plain, WCS, 0.1, 2);
        assertEquals(List.of(new Wall(0, 0, 1, 0, ""), new Wall(0, 1, 1, 1, "glass")), walls.walls());
        assertEquals(List.of("", "glass"), walls.materials());
    }
}
