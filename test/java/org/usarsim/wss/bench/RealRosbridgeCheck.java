package org.usarsim.wss.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import org.usarsim.wss.bench.RegisteredRobots.Held;
import org.usarsim.wss.bench.RegisteredRobots.Pair;

/**
 * Issue 31's ROS position source checked against a real rosbridge_suite (docs/ros.md, "Checked
 * against a real rosbridge"): not a JUnit test (CI has no ROS), a check run by hand. Each scenario
 * starts a headless WSS of its own ({@link WssProcess}: DistanceOnly, {@code distance.n = 3}, poll
 * 200 ms, {@code positions = rosbridge}, {@code rosbridge.grace = 5000}) on topics under
 * {@code /check/sN/} that nothing else publishes, real ROS nodes ({@code test/ros/latency_publisher.py},
 * {@link PublisherProcess}) and robots on control connections ({@link RegisteredRobots}), and says
 * PASS or FAIL per check with its figures, from GETSS and the WSS's log:
 * <ol>
 * <li>per-robot topics ({@code /check/s1/{robot}/odom}, 5 Hz): A, B, C, D registered 0.5 s apart,
 * each robot's publisher advertised 0.6 s after the one before (each late after its INIT): all
 * placed, kept 15 s, none kicked, never silent; E, with no publisher, kicked after the grace and
 * not before;</li>
 * <li>two publishers on one tf topic ({@code /check/s2/tf}), one TFMessage per robot: every robot
 * placed, none kicked in 10 s;</li>
 * <li>{@code /tf_static} composed with {@code /tf}, {@code rosbridge.frame = map}: a latched
 * {@code map -> world} (100, 0) turned 90 degrees, A and B in {@code world}, C in {@code map}: the
 * strengths of the composed places (A-B 10 m, B-C 10 m, A-C 20 m), which no other reading
 * gives (tf_static ignored: A and B never listed, kicked; its turn ignored: B-C 22.4 m; its
 * translation ignored: A-C 102 m), none kicked; the robots' tf publishers start 1.5 s after their
 * INITs, the static broadcaster before the WSS, and the source must not count as silent meanwhile
 * (the grace, not the stale limit, until a robot's first pose);</li>
 * <li>unreadable messages only: good Odometry for 6 s, then x = NaN (rosbridge 0.11 writes null):
 * "lost the simulator" said once, nobody kicked for 10 s and the last good strengths kept, the
 * message that cannot be read said once;</li>
 * <li>a rosbridge restart: the rosbridge process (its pid file under {@code --rosbridge-work})
 * killed with SIGKILL and started again by that folder's {@code start.sh} (which skips the pieces
 * still running): "answers again" logged, the poses live again (no new silence for 5 s), nobody
 * kicked (GETSS shows the last known places all along, so it tells nothing here).</li>
 * </ol>
 * Exit code 0 only if every check of the scenarios run passed. With the real rosbridge of
 * docs/ros.md's section (its {@code start.sh} started, ws://127.0.0.1:9090):
 *
 * <pre>
 * mvn -B -q test-compile
 * java -cp target/classes:target/test-classes org.usarsim.wss.bench.RealRosbridgeCheck \
 *     --url ws://127.0.0.1:9090 \
 *     --publisher ". /work/rb/env.sh; exec /usr/bin/python3 test/ros/latency_publisher.py" \
 *     --rosbridge-work /work/rb [--only 1,2,3,4,5]
 * </pre>
 */
public final class RealRosbridgeCheck {

    private static final int POLL_MS = 200;
    private static final int GRACE_MS = 5000;
    /** How long after a robot's INIT its first strength may take: its publisher's late start, ROS's connection, a poll. */
    private static final long PLACED_WITHIN_MS = 10_000;
    /** Slack on the grace for the kick of a robot never published: the first ask waits for a poll, the kick for another. */
    private static final long KICK_SLACK_MS = 2_500;
    /** Scenario 3: how long after the robots' INITs their tf publishers start (well within the grace). */
    private static final long TF_LATE_MS = 1_500;
    /** Scenarios 4 and 5: two robots 10 m apart, each asking GETSS of the other. */
    private static final List<String> TWO = List.of("A", "B");
    private static final List<Pair> BOTH_WAYS = List.of(new Pair("A", "B", 10), new Pair("B", "A", 10));

    private final String url;
    private final String publisher;
    /** The rosbridge's work folder (pids/rosbridge.pid, start.sh); null: scenario 5 cannot run. */
    private final Path rosbridgeWork;
    private final Verdicts verdicts = new Verdicts();

    private RealRosbridgeCheck(String url, String publisher, Path rosbridgeWork) {
        this.url = url;
        this.publisher = publisher;
        this.rosbridgeWork = rosbridgeWork;
    }

    public static void main(String[] args) throws Exception {
        Map<String, String> options = options(args);
        String work = options.getOrDefault("--rosbridge-work", System.getenv("RB_WORK"));
        RealRosbridgeCheck check = new RealRosbridgeCheck(options.getOrDefault("--url", "ws://127.0.0.1:9090"),
                options.getOrDefault("--publisher", "python3 test/ros/latency_publisher.py"), work == null ? null : Path.of(work));
        Set<String> only = new LinkedHashSet<>(List.of(options.getOrDefault("--only", "1,2,3,4,5").split(",")));
        System.out.printf(Locale.ROOT, "rosbridge %s, publisher \"%s\"; each WSS: DistanceOnly, distance.n=3, poll %d ms, grace %d ms%n",
                check.url, check.publisher, POLL_MS, GRACE_MS);
        check.run(only);
        System.out.println();
        System.out.println(check.verdicts.summary());
        System.exit(check.verdicts.allPassed() ? 0 : 1);
    }

    private static Map<String, String> options(String[] args) {
        Map<String, String> options = new LinkedHashMap<>();
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--url", "--publisher", "--rosbridge-work", "--only" -> {
                    if (i + 1 == args.length) {
                        throw new IllegalArgumentException(args[i] + " needs a value");
                    }
                    options.put(args[i], args[++i]);
                }
                default -> throw new IllegalArgumentException("unknown option " + args[i]);
            }
        }
        return options;
    }

    /** One scenario's checks; an exception breaks it off (a failure). */
    private interface Scenario {
        void run() throws Exception;
    }

    private void run(Set<String> only) {
        scenario(only, "1", "per-robot topics, publishers starting late", this::perRobotTopics);
        scenario(only, "2", "several publishers on one tf topic", this::severalTfPublishers);
        scenario(only, "3", "/tf_static composed with /tf", this::tfStatic);
        scenario(only, "4", "unreadable messages only", this::unreadable);
        scenario(only, "5", "a rosbridge restart", this::restart);
    }

    private void scenario(Set<String> only, String number, String title, Scenario scenario) {
        if (!only.contains(number)) {
            return;
        }
        System.out.println();
        System.out.println("== " + number + ". " + title);
        try {
            scenario.run();
        } catch (Exception e) {
            verdicts.broke(number + " " + title, e);
        }
    }

    // ---- the scenarios ----

    private void perRobotTopics() throws Exception {
        String topic = "/check/s1/{robot}/odom";
        List<String> four = List.of("A", "B", "C", "D");
        try (WssProcess wss = wss(topic);
                PublisherProcess odom = publish("--mode odom --names A,B,C,D --rate 5 --spacing 10 --delay-each 0.6 --topic " + topic);
                RegisteredRobots robots = new RegisteredRobots(wss)) {
            long start = System.nanoTime();
            for (int i = 0; i < four.size(); i++) {
                sleepUntil(start + TimeUnit.MILLISECONDS.toNanos(500L * i));
                robots.register(four.get(i));
            }
            sleepUntil(start + TimeUnit.MILLISECONDS.toNanos(2000));
            robots.register("E");
            placed("1a A, B, C, D placed, each robot's publisher starting after its INIT", robots,
                    List.of(new Pair("A", "B", 10), new Pair("A", "C", 20), new Pair("A", "D", 30)));
            kept("1b A, B, C, D kept for 15 s, none kicked", wss, robots, four, ring(four), 15_000);
            long kicked = awaitLine(wss, "kicking E:", 0, robots.init("E") + TimeUnit.SECONDS.toNanos(20));
            long after = kicked - robots.init("E");
            verdicts.say("1c E, never published, kicked after the grace (" + GRACE_MS + " ms) and not before",
                    kicked >= 0 && after >= TimeUnit.MILLISECONDS.toNanos(GRACE_MS)
                            && after <= TimeUnit.MILLISECONDS.toNanos(GRACE_MS + KICK_SLACK_MS),
                    kicked < 0 ? "not kicked within 20 s of its INIT"
                            : "kicked " + RegisteredRobots.seconds(after) + " after its INIT: " + wss.lastLineContaining("kicking E:"));
            noSilence("1d", wss);
            System.out.println("  publisher: " + odom.stop());
        }
    }

    private void severalTfPublishers() throws Exception {
        String topic = "/check/s2/tf";
        List<String> four = List.of("A", "B", "C", "D");
        try (WssProcess wss = wss(topic, "rosbridge.type=tf2_msgs/TFMessage");
                PublisherProcess tf = publish("--mode tf --publishers 2 --per-robot --names A,B,C,D --rate 5 --spacing 10 --topic "
                        + topic);
                RegisteredRobots robots = new RegisteredRobots(wss)) {
            robots.register(four);
            placed("2a A, B (one node) and C, D (another) placed, one TFMessage per robot", robots,
                    List.of(new Pair("A", "B", 10), new Pair("A", "C", 20), new Pair("A", "D", 30)));
            kept("2b none kicked in 10 s", wss, robots, four, ring(four), 10_000);
            noSilence("2c", wss);
            System.out.println("  publishers: " + tf.stop());
        }
    }

    private void tfStatic() throws Exception {
        String topic = "/check/s3/tf";
        List<String> three = List.of("A", "B", "C");
        try (PublisherProcess statics = publish("--mode tf_static --topic /check/s3/tf_static --frame map --child world --x 100 --y 0"
                + " --yaw 90");
                WssProcess wss = wss(topic, "rosbridge.type=tf2_msgs/TFMessage", "rosbridge.frame=map");
                RegisteredRobots robots = new RegisteredRobots(wss)) {
            robots.register(three);
            // The robots' tf starts after the WSS has connected (a robot launched later), the static broadcaster was up before.
            sleepUntil(robots.init("A") + TimeUnit.MILLISECONDS.toNanos(TF_LATE_MS));
            try (PublisherProcess inWorld = publish("--mode tf --publishers 1 --names A,B --frame world --rate 5 --spacing 10"
                    + " --topic " + topic);
                    PublisherProcess inMap = publish("--mode tf --publishers 1 --names C --frame map --rate 5 --spacing 10 --x 100"
                            + " --y 20 --topic " + topic)) {
                List<Pair> pairs = List.of(new Pair("A", "B", 10), new Pair("B", "C", 10), new Pair("A", "C", 20));
                System.out.println("  composed in map: A (100, 0), B (100, 10), C (100, 20); tf_static ignored: A, B never listed;"
                        + " its turn ignored: B-C 22.4 m; its translation ignored: A-C 102.0 m");
                placed("3a the composed places (A-B 10 m, B-C 10 m, A-C 20 m)", robots, pairs);
                kept("3b none kicked in 10 s", wss, robots, three, pairs, 10_000);
                noSilence("3c (the robots' tf starting " + TF_LATE_MS + " ms after their INITs, the latched tf_static at once)", wss);
                System.out.println("  publishers: " + statics.stop() + "; " + inWorld.stop() + "; " + inMap.stop());
            }
        }
    }

    private void unreadable() throws Exception {
        String topic = "/check/s4/{robot}/odom";
        String badLine = "sent a message that cannot be read";
        try (WssProcess wss = wss(topic);
                PublisherProcess bad = publish("--mode bad --names A,B --rate 10 --spacing 10 --good 6 --topic " + topic);
                RegisteredRobots robots = new RegisteredRobots(wss)) {
            robots.register(TWO);
            placed("4a A, B placed while the poses are good", robots, BOTH_WAYS);
            long firstBad = awaitLine(wss, badLine, 0, System.nanoTime() + TimeUnit.SECONDS.toNanos(15));
            if (firstBad < 0) {
                verdicts.say("4b the bad messages reach the WSS", false, "no \"" + badLine + "\" within 15 s");
                return;
            }
            Held held = robots.holds(BOTH_WAYS, TimeUnit.NANOSECONDS.toMillis(firstBad + TimeUnit.SECONDS.toNanos(10) - System.nanoTime()));
            Map<String, Long> kicks = robots.kicks(TWO);
            verdicts.say("4b nobody kicked for 10 s of unreadable messages only, the last good strengths kept",
                    held.well() && kicks.isEmpty(), held + "; kicked: " + (kicks.isEmpty() ? "nobody" : kicks));
            long lostCount = wss.linesContaining("lost the simulator");
            long lost = wss.lineTime("lost the simulator", 0);
            verdicts.say("4c \"lost the simulator\" said once", lostCount == 1, lostCount + " times"
                    + (lost < 0 ? "" : ", the first " + RegisteredRobots.seconds(lost - firstBad) + " after the first bad message: "
                            + wss.lastLineContaining("lost the simulator")));
            long badCount = wss.linesContaining(badLine);
            verdicts.say("4d the one kind of bad message (x null) said once", badCount == 1,
                    badCount + " lines: " + wss.lastLineContaining(badLine));
            System.out.println("  publisher: " + bad.stop());
        }
    }

    private void restart() throws Exception {
        if (rosbridgeWork == null) {
            throw new IOException("no --rosbridge-work (nor RB_WORK): the folder with pids/rosbridge.pid and start.sh");
        }
        String topic = "/check/s5/{robot}/odom";
        try (WssProcess wss = wss(topic);
                PublisherProcess odom = publish("--mode odom --names A,B --rate 5 --spacing 10 --topic " + topic);
                RegisteredRobots robots = new RegisteredRobots(wss)) {
            robots.register(TWO);
            if (!placed("5a A, B placed before the restart", robots, BOTH_WAYS)) {
                return;
            }
            int from = wss.lineCount();
            long killed = killRosbridge();
            long started = startRosbridge();
            System.out.println("  start.sh took " + RegisteredRobots.seconds(started - killed) + " from the kill to its end");
            long back = awaitLine(wss, "answers again", from, killed + TimeUnit.SECONDS.toNanos(60));
            long lost = wss.lineTime("lost the simulator", from);
            verdicts.say("5b \"answers again\" logged", back >= 0, (lost < 0 ? "no \"lost the simulator\""
                    : "lost " + RegisteredRobots.seconds(lost - killed) + " after the kill") + ", "
                    + (back < 0 ? "no \"answers again\" within 60 s of the kill"
                            : "answers again " + RegisteredRobots.seconds(back - killed) + " after the kill: "
                                    + wss.lastLineContaining("answers again")));
            if (back < 0) {
                return;
            }
            // GETSS shows the last known places all along: the new connection's poses are live when no silence follows.
            int afterBack = wss.lineCount();
            Held held = robots.holds(BOTH_WAYS, 5_000);
            Map<String, Long> kicks = robots.kicks(TWO);
            boolean silentAgain = wss.lineTime("lost the simulator", afterBack) >= 0;
            verdicts.say("5c the poses live again for 5 s after it answers again, nobody kicked since the registration",
                    held.well() && kicks.isEmpty() && !silentAgain, held + " in the 5 s; " + (silentAgain
                            ? "silent again: " + wss.lastLineContaining("lost the simulator") : "not silent again")
                            + "; kicked: " + (kicks.isEmpty() ? "nobody" : kicks));
            System.out.println("  publisher: " + odom.stop());
        }
    }

    // ---- the checks the scenarios share ----

    /** Each pair's GETSS shows its distance's strength within {@link #PLACED_WITHIN_MS} of the later INIT of the two. */
    private boolean placed(String check, RegisteredRobots robots, List<Pair> pairs) throws IOException, InterruptedException {
        List<String> figures = new ArrayList<>();
        boolean all = true;
        for (Pair pair : pairs) {
            String later = robots.init(pair.from()) > robots.init(pair.to()) ? pair.from() : pair.to();
            long shown = robots.awaitShown(pair, robots.init(later) + TimeUnit.MILLISECONDS.toNanos(PLACED_WITHIN_MS));
            all &= shown >= 0;
            figures.add(pair + (shown < 0 ? " never shown (" + robots.getss(pair) + ")"
                    : " shown " + robots.since(later, shown) + " after " + later + "'s INIT"));
        }
        return verdicts.say(check, all, String.join("; ", figures));
    }

    /** The pairs' strengths held for {@code millis}, and none of the robots kicked since the WSS started. */
    private void kept(String check, WssProcess wss, RegisteredRobots robots, List<String> names, List<Pair> pairs, long millis)
            throws InterruptedException {
        Held held = robots.holds(pairs, millis);
        Map<String, Long> kicks = robots.kicks(names);
        verdicts.say(check, held.well() && kicks.isEmpty(), held + "; kicked: " + (kicks.isEmpty() ? "none" : kicks) + "; "
                + wss.lastLineContaining("positions from"));
    }

    /** The source never counted as silent: no "lost the simulator" since the WSS started. */
    private void noSilence(String number, WssProcess wss) {
        long lost = wss.linesContaining("lost the simulator");
        long took = wss.lineTime("takes positions from", 0);
        long first = wss.lineTime("lost the simulator", 0);
        verdicts.say(number + " never silent", lost == 0, lost == 0 ? "no \"lost the simulator\""
                : lost + " times \"lost the simulator\", the first " + RegisteredRobots.seconds(first - took)
                        + " after \"takes positions\"; the last: " + wss.lastLineContaining("lost the simulator"));
    }

    /** Each robot asks GETSS of the next, the last of the first. */
    private static List<Pair> ring(List<String> names) {
        List<Pair> ring = new ArrayList<>();
        for (int i = 0; i < names.size(); i++) {
            int next = (i + 1) % names.size();
            ring.add(new Pair(names.get(i), names.get(next), 10.0 * Math.abs(next - i)));
        }
        return ring;
    }

    // ---- the processes ----

    private WssProcess wss(String topic, String... more) throws IOException, InterruptedException {
        List<String> settings = new ArrayList<>(List.of("wss.model=DistanceOnlyPropagationModel", "distance.n=3",
                "positions.interval=" + POLL_MS, "positions=rosbridge", "rosbridge.url=" + url, "rosbridge.topic=" + topic,
                "rosbridge.grace=" + GRACE_MS));
        settings.addAll(List.of(more));
        System.out.println("  WSS: " + String.join(" ", settings.subList(3, settings.size())));
        return WssProcess.start(settings.toArray(String[]::new));
    }

    private PublisherProcess publish(String arguments) throws IOException {
        System.out.println("  publisher: " + arguments);
        return PublisherProcess.start(publisher, arguments);
    }

    /** Kills the rosbridge process (its pid file) with SIGKILL and waits for its end: when it was killed. */
    private long killRosbridge() throws Exception {
        long pid = Long.parseLong(Files.readString(rosbridgeWork.resolve("pids/rosbridge.pid")).strip());
        ProcessHandle rosbridge = ProcessHandle.of(pid).orElseThrow(() -> new IOException("no rosbridge process " + pid));
        long killed = System.nanoTime();
        if (!rosbridge.destroyForcibly()) {
            throw new IOException("could not kill rosbridge (pid " + pid + ")");
        }
        rosbridge.onExit().get(10, TimeUnit.SECONDS);
        System.out.println("  killed rosbridge (pid " + pid + ") with SIGKILL");
        return killed;
    }

    /** Runs the work folder's start.sh (the pieces still running skipped), its output said; when it ended. */
    private long startRosbridge() throws Exception {
        ProcessBuilder builder = new ProcessBuilder("bash", rosbridgeWork.resolve("start.sh").toString()).redirectErrorStream(true);
        builder.environment().put("RB_WORK", rosbridgeWork.toString());
        Process start = builder.start();
        Thread said = OutputLines.follow(start.getInputStream(), line -> System.out.println("  [start.sh] " + line), "start.sh");
        if (!start.waitFor(120, TimeUnit.SECONDS)) {
            start.destroyForcibly();
            throw new IOException("start.sh did not end within 120 s");
        }
        said.join(2_000);
        if (start.exitValue() != 0) {
            throw new IOException("start.sh ended with " + start.exitValue());
        }
        return System.nanoTime();
    }

    /** When the WSS's first line from line {@code from} on containing the text was read, waiting until the deadline; -1: none. */
    private static long awaitLine(WssProcess wss, String text, int from, long deadline) throws InterruptedException {
        for (long at = wss.lineTime(text, from); System.nanoTime() < deadline; at = wss.lineTime(text, from)) {
            if (at >= 0) {
                return at;
            }
            Thread.sleep(20);
        }
        return wss.lineTime(text, from);
    }

    private static void sleepUntil(long nanos) throws InterruptedException {
        long left = nanos - System.nanoTime();
        if (left > 0) {
            TimeUnit.NANOSECONDS.sleep(left);
        }
    }
}
