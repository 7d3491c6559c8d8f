package org.usarsim.wss.world;

import java.io.ByteArrayInputStream;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;

/**
 * The walls of a Gazebo world (an SDF document, docs/world.md "Walls from a Gazebo world"): every
 * {@code <collision>} whose geometry is a {@code <box>}, of every {@code <model>} (nested models
 * too), placed by its model's, link's and collision's poses composed, becomes a {@link BoxWall}
 * when its vertical extent meets the robots' height band. Every other geometry and every
 * {@code <include>} of a model by URI is skipped, counted by kind and named in one note each, as
 * are the boxes outside the band and the poses whose {@code relative_to} (or SDF 1.5
 * {@code frame}) is not followed.
 */
final class SdfWalls {

    /** The boxes kept and the notes on what was not (one line per kind), in document order. */
    record Result(List<BoxWall> boxes, List<String> notes) {
    }

    private static final Pattern SPACES = Pattern.compile("\\s+");
    /** How many names a note gives before it only counts. */
    private static final int NAMED = 5;

    private final String source;
    private final MaterialRules rules;
    private final double low;
    private final double high;
    private final List<BoxWall> boxes = new ArrayList<>();
    /** What was skipped, by kind: the names of each. */
    private final Map<String, List<String>> skipped = new LinkedHashMap<>();

    private SdfWalls(String source, MaterialRules rules, double low, double high) {
        this.source = source;
        this.rules = rules;
        this.low = low;
        this.high = high;
    }

    /** The walls of this SDF document; {@code source} names it in messages. */
    static Result parse(byte[] document, String source, MaterialRules rules, double low, double high) throws WorldFileException {
        SdfElements.Element root = SdfElements.read(new ByteArrayInputStream(document), source);
        if (!root.tag.equals("sdf")) {
            throw new WorldFileException(source + ": not an SDF document: its root is <" + root.tag + ">, not <sdf>");
        }
        SdfWalls walls = new SdfWalls(source, rules, low, high);
        for (SdfElements.Element child : root.children) {
            switch (child.tag) {
                case "world" -> walls.world(child);
                case "model" -> walls.model(child, Pose.IDENTITY, List.of());
                default -> { }
            }
        }
        return new Result(List.copyOf(walls.boxes), walls.notes());
    }

    private void world(SdfElements.Element world) throws WorldFileException {
        for (SdfElements.Element child : world.children) {
            if (child.tag.equals("model")) {
                model(child, Pose.IDENTITY, List.of());
            } else if (child.tag.equals("include")) {
                include(child);
            }
        }
    }

    private void model(SdfElements.Element model, Pose parent, List<String> outer) throws WorldFileException {
        List<String> names = new ArrayList<>(outer);
        names.add(model.attribute("name"));
        Pose pose = parent.then(pose(model, String.join("::", names)));
        for (SdfElements.Element child : model.children) {
            switch (child.tag) {
                case "link" -> link(child, pose, names);
                case "model" -> model(child, pose, names);
                case "include" -> include(child);
                default -> { }
            }
        }
    }

    private void include(SdfElements.Element include) {
        SdfElements.Element uri = include.child("uri");
        skip("include", uri == null ? "(no uri)" : uri.text());
    }

    private void link(SdfElements.Element link, Pose model, List<String> models) throws WorldFileException {
        String linkName = String.join("::", models) + "::" + link.attribute("name");
        Pose pose = model.then(pose(link, linkName));
        for (SdfElements.Element collision : link.children) {
            if (!collision.tag.equals("collision")) {
                continue;
            }
            String name = linkName + "::" + collision.attribute("name");
            SdfElements.Element geometry = collision.child("geometry");
            if (geometry == null || geometry.children.isEmpty()) {
                continue;
            }
            SdfElements.Element box = geometry.child("box");
            if (box == null) {
                skip(geometry.children.get(0).tag, name);
                continue;
            }
            List<String> matched = new ArrayList<>(models);
            matched.add(link.attribute("name"));
            matched.add(collision.attribute("name"));
            box(pose.then(pose(collision, name)), size(box, name), name, rules.materialOf(matched));
        }
    }

    /** The box of this size about the origin of {@code pose}: kept when its extent in z meets the band. */
    private void box(Pose pose, double[] size, String name, String material) {
        List<double[]> floor = new ArrayList<>(8);
        double zMin = Double.POSITIVE_INFINITY;
        double zMax = Double.NEGATIVE_INFINITY;
        for (int corner = 0; corner < 8; corner++) {
            double[] p = pose.apply(((corner & 1) == 0 ? -0.5 : 0.5) * size[0], ((corner & 2) == 0 ? -0.5 : 0.5) * size[1],
                    ((corner & 4) == 0 ? -0.5 : 0.5) * size[2]);
            floor.add(new double[] {p[0], p[1]});
            zMin = Math.min(zMin, p[2]);
            zMax = Math.max(zMax, p[2]);
        }
        if (zMax < low || zMin > high) {
            skip("outside the height band", name);
            return;
        }
        boxes.add(BoxWall.around(name, material, floor));
    }

    private double[] size(SdfElements.Element box, String name) throws WorldFileException {
        SdfElements.Element size = box.child("size");
        double[] values = numbers(size == null ? "1 1 1" : size.text(), name + "'s box size");
        if (values.length != 3 || values[0] < 0 || values[1] < 0 || values[2] < 0) {
            throw new WorldFileException(source + ": " + name + ": a box's size is three numbers of 0 or more, not '"
                    + size.text() + "'");
        }
        return values;
    }

    /** The element's own pose, relative to its parent's frame; identity when it has none. */
    private Pose pose(SdfElements.Element owner, String name) throws WorldFileException {
        SdfElements.Element pose = owner.child("pose");
        if (pose == null || pose.text().isEmpty()) {
            return Pose.IDENTITY;
        }
        String frame = !pose.attribute("relative_to").isEmpty() ? pose.attribute("relative_to") : pose.attribute("frame");
        if (!frame.isEmpty()) {
            skip("relative_to (taken relative to the parent instead)", name + " relative_to " + frame);
        }
        double[] v = numbers(pose.text(), name + "'s pose");
        boolean quaternion = pose.attribute("rotation_format").equals("quat_xyzw");
        if (quaternion && v.length == 7) {
            Pose turned = Pose.quaternion(v[0], v[1], v[2], v[3], v[4], v[5], v[6]);
            if (turned != null) {
                return turned;
            }
        } else if (!quaternion && v.length == 6) {
            double k = pose.attribute("degrees").equals("true") ? Math.PI / 180 : 1;
            return Pose.euler(v[0], v[1], v[2], v[3] * k, v[4] * k, v[5] * k);
        }
        throw new WorldFileException(source + ": " + name + ": a pose is 'x y z roll pitch yaw'"
                + " (or 'x y z qx qy qz qw' with rotation_format quat_xyzw), not '" + pose.text() + "'");
    }

    private double[] numbers(String text, String what) throws WorldFileException {
        String[] words = text.isEmpty() ? new String[0] : SPACES.split(text);
        double[] values = new double[words.length];
        for (int i = 0; i < words.length; i++) {
            try {
                values[i] = Double.parseDouble(words[i]);
            } catch (NumberFormatException e) {
                values[i] = Double.NaN;
            }
            if (!Double.isFinite(values[i])) {
                throw new WorldFileException(source + ": '" + words[i] + "' is not a number, in " + what);
            }
        }
        return values;
    }

    private void skip(String kind, String name) {
        skipped.computeIfAbsent(kind, k -> new ArrayList<>()).add(name);
    }

    /** One line per kind skipped: how many and the first few names. */
    private List<String> notes() {
        List<String> notes = new ArrayList<>();
        skipped.forEach((kind, names) -> {
            String what = switch (kind) {
                case "include" -> names.size() + " <include> of a model by URI (not followed)";
                case "outside the height band" -> names.size() + " box(es) outside the height band " + band();
                default -> kind.startsWith("relative_to") ? names.size() + " pose(s) with " + kind + ", not supported"
                        : names.size() + " " + kind + " collision(s) (only boxes are walls)";
            };
            notes.add((kind.startsWith("relative_to") ? "" : "skipped ") + what + ": " + String.join(", ", names.subList(0, Math.min(NAMED, names.size())))
                    + (names.size() > NAMED ? ", ..." : ""));
        });
        return notes;
    }

    private String band() {
        return low + ".." + high + " m";
    }
}
