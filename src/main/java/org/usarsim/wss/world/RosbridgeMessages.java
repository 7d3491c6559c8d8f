package org.usarsim.wss.world;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.usarsim.wss.ros.Json;

/**
 * The ROS messages of the world, as rosbridge v2 publish frames, one per publication of its
 * {@link RosGraph}: {@code /gazebo/model_states} ({@code gazebo_msgs/ModelStates}: every robot, in
 * file order), {@code /tf} ({@code tf2_msgs/TFMessage}: one robot's {@code world -> NAME/base_link},
 * from that robot's publisher), {@code /tf_static} ({@code map -> world}, the identity), each
 * robot's {@code /NAME/odom} ({@code nav_msgs/Odometry}, frame {@code world}, child
 * {@code NAME/base_link}) and {@code /map} ({@code nav_msgs/OccupancyGrid} of the walls, in
 * {@code world}). Positions as the world has them at the publication's instant, turned by nothing
 * (the world has no headings: every rotation is the identity); stamps that instant, the world's
 * time since the server started, as Gazebo's simulation time; {@code seq} the publisher's count.
 * The only place the world server writes a ROS message.
 */
final class RosbridgeMessages {

    /** The map's cell size unless the walls span too much for {@link #MAX_CELLS} cells. */
    static final double RESOLUTION = 0.1;
    /** The most cells of the map (2000 x 2000): coarser cells beyond. */
    static final int MAX_CELLS = 4_000_000;
    /** Free space around the walls in the map, in metres. */
    static final double MARGIN = 1.0;
    private static final List<Double> ZEROS_36 = Collections.nCopies(36, 0.0);

    private RosbridgeMessages() {
    }

    /** The publish frame of a publication of the world's graph, but {@code /map}'s ({@link #map}). */
    static String publish(RosGraph.Publication publication, World world) {
        RosGraph.Publisher publisher = publication.publisher();
        String topic = publisher.topic();
        double seconds = publication.nanos() / 1e9;
        Object msg;
        if (topic.equals(RosGraph.MODEL_STATES)) {
            msg = modelStates(world.at(seconds));
        } else if (topic.equals(RosGraph.TF_STATIC)) {
            msg = object("transforms", List.of(transform(header(seconds, publication.seq(), "map"), "world", new Point(0, 0, 0))));
        } else if (topic.equals(RosGraph.TF)) {
            RobotAt robot = world.robotAt(publisher.robot(), seconds);
            msg = object("transforms", List.of(transform(header(seconds, publication.seq(), "world"), robot.name() + "/base_link",
                    robot.position())));
        } else {
            msg = odometry(world.robotAt(publisher.robot(), seconds), seconds, publication.seq());
        }
        return frame(topic, msg);
    }

    static String frame(String topic, Object msg) {
        Map<String, Object> frame = new LinkedHashMap<>();
        frame.put("op", "publish");
        frame.put("topic", topic);
        frame.put("msg", msg);
        return Json.write(frame);
    }

    private static Map<String, Object> modelStates(Snapshot world) {
        List<Object> names = new ArrayList<>();
        List<Object> poses = new ArrayList<>();
        List<Object> twists = new ArrayList<>();
        for (RobotAt robot : world.robots()) {
            names.add(robot.name());
            poses.add(pose(robot.position()));
            twists.add(object("linear", vector(0, 0, 0), "angular", vector(0, 0, 0)));
        }
        return object("name", names, "pose", poses, "twist", twists);
    }

    private static Map<String, Object> transform(Map<String, Object> header, String child, Point p) {
        return object("header", header, "child_frame_id", child, "transform",
                object("translation", vector(p.x(), p.y(), p.z()), "rotation", identity()));
    }

    private static Map<String, Object> odometry(RobotAt robot, double seconds, long seq) {
        return object("header", header(seconds, seq, "world"), "child_frame_id", robot.name() + "/base_link",
                "pose", object("pose", pose(robot.position()), "covariance", ZEROS_36),
                "twist", object("twist", object("linear", vector(0, 0, 0), "angular", vector(0, 0, 0)), "covariance", ZEROS_36));
    }

    /** The walls as an occupancy grid: every cell a wall passes through 100, the others 0, a margin of free cells around. */
    static String map(List<Wall> walls, double seconds) {
        double minX = 0;
        double minY = 0;
        double maxX = 0;
        double maxY = 0;
        if (!walls.isEmpty()) {
            minX = Double.POSITIVE_INFINITY;
            minY = Double.POSITIVE_INFINITY;
            maxX = Double.NEGATIVE_INFINITY;
            maxY = Double.NEGATIVE_INFINITY;
            for (Wall wall : walls) {
                minX = Math.min(minX, Math.min(wall.x1(), wall.x2()));
                minY = Math.min(minY, Math.min(wall.y1(), wall.y2()));
                maxX = Math.max(maxX, Math.max(wall.x1(), wall.x2()));
                maxY = Math.max(maxY, Math.max(wall.y1(), wall.y2()));
            }
        }
        minX -= MARGIN;
        minY -= MARGIN;
        double resolution = RESOLUTION;
        int width;
        int height;
        while (true) {
            width = (int) Math.ceil((maxX + MARGIN - minX) / resolution);
            height = (int) Math.ceil((maxY + MARGIN - minY) / resolution);
            if ((long) width * height <= MAX_CELLS) {
                break;
            }
            resolution *= 2;
        }
        byte[] cells = new byte[width * height];
        for (Wall wall : walls) {
            draw(cells, width, height, (wall.x1() - minX) / resolution, (wall.y1() - minY) / resolution,
                    (wall.x2() - minX) / resolution, (wall.y2() - minY) / resolution);
        }
        Integer[] data = new Integer[cells.length];
        for (int i = 0; i < cells.length; i++) {
            data[i] = (int) cells[i];
        }
        Map<String, Object> info = object("map_load_time", stamp(seconds), "resolution", resolution, "width", width,
                "height", height, "origin", object("position", vector(minX, minY, 0), "orientation", identity()));
        return frame(RosGraph.MAP, object("header", header(seconds, 0, "world"), "info", info, "data", Arrays.asList(data)));
    }

    /** Marks every cell a segment (in cell units) passes through, sampled at a quarter of a cell. */
    private static void draw(byte[] cells, int width, int height, double u1, double v1, double u2, double v2) {
        int samples = (int) Math.ceil(Math.hypot(u2 - u1, v2 - v1) * 4) + 1;
        for (int i = 0; i <= samples; i++) {
            double f = (double) i / samples;
            int column = (int) Math.floor(u1 + (u2 - u1) * f);
            int row = (int) Math.floor(v1 + (v2 - v1) * f);
            if (column >= 0 && column < width && row >= 0 && row < height) {
                cells[row * width + column] = 100;
            }
        }
    }

    private static Map<String, Object> pose(Point p) {
        return object("position", vector(p.x(), p.y(), p.z()), "orientation", identity());
    }

    private static Map<String, Object> header(double seconds, long seq, String frame) {
        return object("seq", seq, "stamp", stamp(seconds), "frame_id", frame);
    }

    private static Map<String, Object> stamp(double seconds) {
        long nanos = Math.round(seconds * 1e9);
        return object("secs", nanos / 1_000_000_000L, "nsecs", nanos % 1_000_000_000L);
    }

    private static Map<String, Object> vector(double x, double y, double z) {
        return object("x", x, "y", y, "z", z);
    }

    private static Map<String, Object> identity() {
        return object("x", 0.0, "y", 0.0, "z", 0.0, "w", 1.0);
    }

    /** A JSON object of key, value pairs in order. */
    private static Map<String, Object> object(Object... keysAndValues) {
        Map<String, Object> object = new LinkedHashMap<>();
        for (int i = 0; i < keysAndValues.length; i += 2) {
            object.put((String) keysAndValues[i], keysAndValues[i + 1]);
        }
        return object;
    }
}
